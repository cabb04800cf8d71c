"""Cycles' bump shadowing of a diffuse lobe (testsuite/bump/bump-shadowing.test).

  shadowing.py make OUTDIR     plane.obj (y = 0, normal +y), graph.json and scene.json: the
                               plane seen from above, lit only by a sun 70 degrees off its
                               normal towards -x; material "bumped": a white-0.5 diffuse whose
                               normal is a bump of the height 2 x (distance 0.5: tilted 45
                               degrees towards -x, so 25 degrees from the sun), "flat": the same
                               without the bump
  shadowing.py check OUTDIR    the central 8x8 pixels of OUTDIR/bumped.exr and flat.exr against
                               the analytic radiance

With the sun's irradiance E = pi, a diffuse of albedo 0.5 shows 0.5 cos(n, sun). The bumped
lobe is also shadowed as Cycles' bump map correction does it: times the GGX masking G1 at the
sun's angle to the smooth normal (cos 70), of alpha^2 = tan^2(45) / 8: G1 = 0.8355, so 0.3786
where an unshadowed bump gives 0.4532; flat: 0.5 cos 70 = 0.1710.
"""
import json
import math
import os
import sys


SUN_OFF = math.radians(70.0)
RADIUS = 0.27  # degrees


def g1(cos, a2):
    return 2 * cos / (cos + math.sqrt(a2 + (1 - a2) * cos * cos))


def write_plane(out):
    """OUTDIR/plane.obj: the square y = 0, x and z in [-2, 2], normal +y (the bump tests' plane)."""
    with open(os.path.join(out, "plane.obj"), "w") as f:
        f.write("v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\nvn 0 1 0\n"
                "f 1//1 3//1 2//1\nf 1//1 4//1 3//1\n")


def centre_mean(path, half):
    """The mean RGB of the (2 half)^2 pixels at the centre of the EXR at path."""
    import numpy as np
    from texcc_tools.exr import read_exr
    with open(path, "rb") as f:
        img = read_exr(f.read())
    img = np.asarray(img[0] if isinstance(img, tuple) else img)
    h, w = img.shape[:2]
    return float(img[h // 2 - half:h // 2 + half, w // 2 - half:w // 2 + half, :3].mean())


EXPECTED = {"bumped": 0.5 * math.cos(SUN_OFF - math.radians(45)) *
            g1(math.cos(SUN_OFF), math.tan(math.radians(45)) ** 2 / 8),
            "flat": 0.5 * math.cos(SUN_OFF)}


def make(out):
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    write_plane(out)
    with open(os.path.join(here, "linear-graph.json")) as f:
        graph = json.load(f)
    graph["sources"] = [os.path.join(here, s) for s in graph["sources"]]
    graph["nodes"] = [n for n in graph["nodes"] if n["id"] in ("h", "b")]
    graph["materials"] = {
        "bumped": {"bsdf": "diffuse", "color": [0.5, 0.5, 0.5], "normal": {"node": "b"}},
        "flat": {"bsdf": "diffuse", "color": [0.5, 0.5, 0.5]}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=1)
    # radiance R over a disc of half-angle r: irradiance R 2 pi (1 - cos r) = pi
    radiance = 1.0 / (2.0 * (1.0 - math.cos(math.radians(RADIUS))))
    for name in EXPECTED:
        scene = {"texrender": 1,
                 "camera": {"position": [0, 3, 0], "target": [0, 0, 0], "up": [0, 0, -1],
                            "fov": 30},
                 "render": {"maxDepth": 2},
                 "lights": [{"type": "sun", "radiance": [radiance] * 3, "angularRadius": RADIUS,
                             "direction": [-math.sin(SUN_OFF), math.cos(SUN_OFF), 0.0]}],
                 "meshes": [{"obj": "plane.obj", "material": name}]}
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)


def check(out):
    ok = True
    for name, want in EXPECTED.items():
        got = centre_mean(os.path.join(out, name + ".exr"), 4)
        good = abs(got / want - 1) <= 0.01
        ok &= good
        print("%-7s %.4f expected %.4f (%+.2f%%) %s" % (name, got, want, 100 * (got / want - 1),
                                                       "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(make(sys.argv[2]) if sys.argv[1] == "make" else check(sys.argv[2]))
