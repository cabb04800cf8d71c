"""Cycles' bump shadowing of a Principled BSDF's diffuse base
(testsuite/bump/bump-shadowing-principled.test).

  shadowing_principled.py make OUTDIR    plane.obj (y = 0, normal +y) and tilted.obj (the same
                                         plane turned 45 degrees about z towards -x), graph.json,
                                         and three scenes under shadowing.py's sun (70 degrees
                                         off +y towards -x), seen from above:
      bumped.json   plane.obj, principled base 0.5 whose normal is shadowing.py's bump (tilted
                    45 degrees towards -x): diffuse base x G1 + specular
      tilted.json   tilted.obj, the same principled unbumped: its normal is the bumped one, so
                    the same diffuse base (unshadowed) + the same specular
      black.json    tilted.obj, principled base 0: the specular alone
  shadowing_principled.py check OUTDIR   central 8x8 pixels: (bumped - black) / (tilted - black)
                                         is the shadowing of the diffuse base alone, Cycles'
                                         G1 = 0.8355 (shadowing.py), within 1%; unshadowed: 1
"""
import json
import math
import os
import sys

import shadowing

G1 = shadowing.g1(math.cos(shadowing.SUN_OFF), math.tan(math.radians(45)) ** 2 / 8)


def make(out):
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    shadowing.write_plane(out)
    c = math.sqrt(0.5)
    with open(os.path.join(out, "tilted.obj"), "w") as f:
        # (x, 0, z) turned 45 degrees about z: (c x, c x, z), normal (-c, c, 0)
        f.write("v %r %r -2\nv %r %r -2\nv %r %r 2\nv %r %r 2\nvn %r %r 0\n"
                "f 1//1 3//1 2//1\nf 1//1 4//1 3//1\n"
                % (-2 * c, -2 * c, 2 * c, 2 * c, 2 * c, 2 * c, -2 * c, -2 * c, -c, c))
    with open(os.path.join(here, "linear-graph.json")) as f:
        graph = json.load(f)
    graph["sources"] = [os.path.join(here, s) for s in graph["sources"]]
    graph["nodes"] = [n for n in graph["nodes"] if n["id"] in ("h", "b")]
    # Specular 0 (IOR level 0: no specular layer, as in Cycles): the bumped principled's GGX
    # lobes take a normal lifted so that its mirror reflection stays above the surface
    # (rt_valid_reflection_normal), which the tilted plane's do not need, so with a specular
    # layer the two differ by more than the diffuse base's shadowing.
    graph["materials"] = {
        "bumped": {"bsdf": "principled", "baseColor": [0.5, 0.5, 0.5], "specular": 0.0,
                   "normal": {"node": "b"}},
        "tilted": {"bsdf": "principled", "baseColor": [0.5, 0.5, 0.5], "specular": 0.0},
        "black": {"bsdf": "principled", "baseColor": [0.0, 0.0, 0.0], "specular": 0.0}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=1)
    radiance = 1.0 / (2.0 * (1.0 - math.cos(math.radians(shadowing.RADIUS))))
    for name, obj in (("bumped", "plane.obj"), ("tilted", "tilted.obj"), ("black", "tilted.obj")):
        scene = {"texrender": 1,
                 "camera": {"position": [0, 3, 0], "target": [0, 0, 0], "up": [0, 0, -1],
                            "fov": 30},
                 "render": {"maxDepth": 2},
                 "lights": [{"type": "sun", "radiance": [radiance] * 3,
                             "angularRadius": shadowing.RADIUS,
                             "direction": [-math.sin(shadowing.SUN_OFF),
                                           math.cos(shadowing.SUN_OFF), 0.0]}],
                 "meshes": [{"obj": obj, "material": name}]}
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
    return 0


def check(out):
    got = {name: shadowing.centre_mean(os.path.join(out, name + ".exr"), 4)
           for name in ("bumped", "tilted", "black")}
    shadow = (got["bumped"] - got["black"]) / (got["tilted"] - got["black"])
    good = abs(shadow / G1 - 1) <= 0.01
    print("bumped %.4f tilted %.4f black (specular) %.4f" % (got["bumped"], got["tilted"],
                                                             got["black"]))
    print("diffuse base shadowed by %.4f expected %.4f (%+.2f%%) %s"
          % (shadow, G1, 100 * (shadow / G1 - 1), "ok" if good else "FAIL"))
    print("PASS" if good else "FAIL")
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(make(sys.argv[2]) if sys.argv[1] == "make" else check(sys.argv[2]))
