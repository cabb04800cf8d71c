"""Bump's step follows the camera's pixel footprint (testsuite/bump/bump-footprint.test).

  footprint.py make OUTDIR           plane.obj (y = 0, normal +y, UV = (x + 2, z + 2) / 4),
                                     graph.json, scene.json: the plane seen from 3 above with
                                     a 30-degree fov, its Emission colour = tan of the tilt
                                     of a bump of footprint.cl's aboutHit (no lights)
  footprint.py check OUTDIR W...     OUTDIR/W.exr for each image width W: the step measured
                                     in the central 8x8 pixels against 0.1 x pixel angle x
                                     distance, pixel angle = 2 tan(15 deg) / W

The height k |P - Q|^2 (Q the unmoved hit) is 0 at the hit and k e^2 at both moved positions
(P + e t, P + e b), so Cycles' Bump tilts the normal by tan = sqrt(2) Distance k e: the image
is the step e. A fixed angular step (texcc before: 2.8e-4 rad) gives the same e at every W.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "scripts"))

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
                       {"id": "t", "fn": "tiltTan", "args": {"nb": {"node": "b"}}}],
             "materials": {"probe": {"bsdf": "emission", "color": {"node": "t"},
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
    return 0


def check(out, widths):
    import numpy as np
    from texexr import read_exr
    ok, steps = True, []
    for w in widths:
        with open(os.path.join(out, "%d.exr" % w), "rb") as f:
            img = read_exr(f.read())
        img = np.asarray(img[0] if isinstance(img, tuple) else img)[..., 0]
        h = img.shape[0]
        angle = 2 * math.tan(math.radians(FOV / 2)) / w
        ratios = []
        for j in range(h // 2 - 4, h // 2 + 4):
            for i in range(w // 2 - 4, w // 2 + 4):
                x, y = (i + 0.5 - w / 2) * angle, (j + 0.5 - h / 2) * angle
                dist = HEIGHT * math.sqrt(1 + x * x + y * y)
                step = img[j, i] / (math.sqrt(2) * DISTANCE * K)
                ratios.append(step / (0.1 * angle * dist))
        worst = max(abs(r - 1) for r in ratios)
        good = worst <= 0.01
        ok &= good
        steps.append(float(np.mean(img[h // 2 - 4:h // 2 + 4, w // 2 - 4:w // 2 + 4])))
        print("width %d: step / (0.1 x pixel angle x distance) %.4f..%.4f %s"
              % (w, min(ratios), max(ratios), "ok" if good else "FAIL"))
    for a, b, wa, wb in zip(steps, steps[1:], widths, widths[1:]):
        good = abs((a / b) / (wb / wa) - 1) <= 0.01
        ok &= good
        print("step ratio %d/%d: %.4f, widths %d/%d: %.4f %s"
              % (wa, wb, a / b, wb, wa, wb / wa, "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if sys.argv[1] == "make":
        sys.exit(make(sys.argv[2]))
    sys.exit(check(sys.argv[2], [int(w) for w in sys.argv[3:]]))
