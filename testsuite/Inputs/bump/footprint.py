"""Bump's step follows the ray's footprint, and its offsets lie across the geometric normal
(testsuite/bump/bump-footprint.test, bump-frame.test).

  footprint.py make OUTDIR           plane.obj (y = 0, normal +y, UV = (x + 2, z + 2) / 4),
                                     graph.json, scene.json and frame.json: the plane seen from
                                     3 above with a 30-degree fov, its Emission colour the tan
                                     of the tilt of a bump of footprint.cl's aboutHit (scene),
                                     or tiltXZ of a bump of alongX (frame); no lights
  footprint.py check OUTDIR W...     OUTDIR/W.exr for each image width W: the step measured in
                                     every pixel against 0.1 x the footprint, pixel angle x
                                     distance x the off-centre factor, pixel angle =
                                     2 tan(15 deg) / W
  footprint.py frame OUTDIR W        OUTDIR/frame-W.exr: the tilt is along z only, by the
                                     amount Cycles' offset directions give

The height k |P - Q|^2 (Q the unmoved hit) is 0 at the hit and k e^2 at both moved positions
(P + e a, P + e b), so Cycles' Bump tilts the normal by tan = sqrt(2) Distance k e: the image
is the step e. Cycles' footprint of a camera ray is its distance times the mean length of the
unit direction's change over one pixel in x and y: at the film position (x, y) (tangents off
the view axis) pixel angle x 0.5 (sqrt(1 + y^2) + sqrt(1 + x^2)) / (1 + x^2 + y^2), 0.905 at
this view's corners (the centre's value everywhere: fails there by 10%). A fixed angular step
(texcc before 01dca36: 2.8e-4 rad) gives the same e at every W.

Cycles offsets along its orthonormal pair of the geometric normal n = +y: a = normalize((1, 1,
1) x n) = (-1, 0, 1) / sqrt(2), b = n x a = (1, 0, 1) / sqrt(2). The height k ((P - Q).x)^2 then
rises by k e^2 / 2 along both, and the bump tilts the normal along z only, by tan = Distance k
e / sqrt(2). Offsets along the plane's UV tangent (1, 0, 0) and n x (1, 0, 0) (texcc before)
tilt it along x only, by Distance k e.
"""
import json
import math
import os
import sys


HEIGHT, FOV, K, DISTANCE = 3.0, 30.0, 100.0, 1.0


def make(out):
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(out, "plane.obj"), "w") as f:
        f.write("v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                "vn 0 1 0\nf 1/1/1 3/3/1 2/2/1\nf 1/1/1 4/4/1 3/3/1\n")
    graph = {"texcc": 1, "sources": [os.path.join(here, "footprint.cl")],
             "nodes": [{"id": "h", "fn": "aboutHit", "args": {"k": K}},
                       {"id": "b", "fn": "bump",
                        "args": {"height": {"node": "h"}, "strength": 1.0,
                                 "distance": DISTANCE, "normal": {"attr": "Normal"}}},
                       {"id": "t", "fn": "tiltTan", "args": {"nb": {"node": "b"}}},
                       {"id": "hx", "fn": "alongX", "args": {"k": K}},
                       {"id": "bx", "fn": "bump",
                        "args": {"height": {"node": "hx"}, "strength": 1.0,
                                 "distance": DISTANCE, "normal": {"attr": "Normal"}}},
                       {"id": "tx", "fn": "tiltXZ", "args": {"nb": {"node": "bx"}}}],
             "materials": {"probe": {"bsdf": "emission", "color": {"node": "t"},
                                     "strength": 1.0},
                           "frame": {"bsdf": "emission", "color": {"node": "tx"},
                                     "strength": 1.0}}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=1)
    scene = {"texrender": 1,
             "camera": {"position": [0, HEIGHT, 0], "target": [0, 0, 0], "up": [0, 0, -1],
                        "fov": FOV},
             "render": {"maxDepth": 1},
             "lights": [],
             "meshes": [{"obj": "plane.obj", "material": "probe"}]}
    with open(os.path.join(out, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    scene["meshes"][0]["material"] = "frame"
    with open(os.path.join(out, "frame.json"), "w") as f:
        json.dump(scene, f, indent=1)
    return 0


def footprint(i, j, w, h):
    """The expected footprint at pixel (i, j) of a w x h image, and its step (0.1 of it)."""
    angle = 2 * math.tan(math.radians(FOV / 2)) / w
    x, y = (i + 0.5 - w / 2) * angle, (j + 0.5 - h / 2) * angle
    dist = HEIGHT * math.sqrt(1 + x * x + y * y)
    off = 0.5 * (math.sqrt(1 + y * y) + math.sqrt(1 + x * x)) / (1 + x * x + y * y)
    return 0.1 * angle * dist * off


def read(path):
    import numpy as np
    from texcc_tools.exr import read_exr
    with open(path, "rb") as f:
        img = read_exr(f.read())
    return np.asarray(img[0] if isinstance(img, tuple) else img)


def check(out, widths):
    import numpy as np
    ok, steps = True, []
    for w in widths:
        img = read(os.path.join(out, "%d.exr" % w))[..., 0]
        h = img.shape[0]
        ratios = [img[j, i] / (math.sqrt(2) * DISTANCE * K) / footprint(i, j, w, h)
                  for j in range(h) for i in range(w)]
        worst = max(abs(r - 1) for r in ratios)
        good = worst <= 0.01
        ok &= good
        corner = img[0, 0] / (math.sqrt(2) * DISTANCE * K) / footprint(w // 2, h // 2, w, h)
        steps.append(float(np.mean(img[h // 2 - 4:h // 2 + 4, w // 2 - 4:w // 2 + 4])))
        print("width %d: step / (0.1 x footprint) %.4f..%.4f, corner / centre %.4f %s"
              % (w, min(ratios), max(ratios), corner, "ok" if good else "FAIL"))
    for a, b, wa, wb in zip(steps, steps[1:], widths, widths[1:]):
        good = abs((a / b) / (wb / wa) - 1) <= 0.01
        ok &= good
        print("step ratio %d/%d: %.4f, widths %d/%d: %.4f %s"
              % (wa, wb, a / b, wb, wa, wb / wa, "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


def frame(out, w):
    img = read(os.path.join(out, "frame-%d.exr" % w))
    h = img.shape[0]
    across, ratios = 0.0, []
    for j in range(h):
        for i in range(w):
            tx, tz = img[j, i, 0], img[j, i, 1]
            across = max(across, tx / tz)
            ratios.append(tz / (DISTANCE * K * footprint(i, j, w, h) / math.sqrt(2)))
    good_x, good_z = across <= 0.01, max(abs(r - 1) for r in ratios) <= 0.01
    print("tilt along x / along z: at most %.4f %s" % (across, "ok" if good_x else "FAIL"))
    print("tilt along z / (Distance k e / sqrt 2): %.4f..%.4f %s"
          % (min(ratios), max(ratios), "ok" if good_z else "FAIL"))
    print("PASS" if good_x and good_z else "FAIL")
    return 0 if good_x and good_z else 1


if __name__ == "__main__":
    if sys.argv[1] == "make":
        sys.exit(make(sys.argv[2]))
    if sys.argv[1] == "frame":
        sys.exit(frame(sys.argv[2], int(sys.argv[3])))
    sys.exit(check(sys.argv[2], [int(w) for w in sys.argv[3:]]))
