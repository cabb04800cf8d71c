"""A glossy lobe's normal is lifted as Cycles' Glossy BSDF lifts it
(testsuite/bump/bump-valid-reflection.test).

  valid_reflection.py make OUTDIR    plane.obj (y = 0, normal +y), graph.json, away.json and
                                     lifted.json: the plane seen from (0, 1, 3) with a 1-degree
                                     fov under a uniform white sky (direct light only), a white
                                     glossy (roughness 0.3) whose normal input is N = (0, 1,
                                     -0.8) normalized (away.json: tilted from the viewer, the
                                     mirror reflection of the view about it points into the
                                     plane), or N' (lifted.json), N turned towards the plane's
                                     normal just enough that the reflection is 0.01 above the
                                     plane, as Cycles' ensure_valid_specular_reflection does
                                     diffuse.json: a white-0.5 diffuse with the normal N, lit
                                     only by a sun 45 degrees up towards -z (irradiance pi)
  valid_reflection.py check OUTDIR   the central 4x4 pixels of away.exr against lifted.exr, and
                                     of diffuse.exr against 0.5 cos(N, sun) x G1 (Cycles' bump
                                     shadowing, shadowing.py)

Without the lift the lobe faces away from the viewer and renders black; with it, both images
show the same lobe. A diffuse lobe, as Cycles' diffuse closure, asks only that the light is
above N: it shades although N faces away from the viewer (texrender before: black).
"""
import json
import math
import os
import sys

from shadowing import centre_mean, g1, write_plane

CAMERA = (0.0, 1.0, 3.0)
AWAY = (0.0, 1.0, -0.8)
SUN = (0.0, 1.0, -1.0)
RADIUS = 0.27  # degrees


def diffuse_expected():
    n, sun, ng = norm(AWAY), norm(SUN), [0.0, 1.0, 0.0]
    cos_d = dot(n, ng)
    return 0.5 * dot(n, sun) * g1(dot(ng, sun), min(1.0, 0.125 * (1 / cos_d ** 2 - 1)))


def norm(v):
    length = math.sqrt(sum(x * x for x in v))
    return [x / length for x in v]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def lifted(ng, wo, n):
    """n turned towards ng, in their plane, so that wo's mirror reflection has height
    t = min(0.9 wo.ng, 0.01) over the plane: the new normal sqrt(1 - z^2) x + z ng (x the unit
    part of n across ng) with 2 (n'.wo) z - wo.ng = t, solved for z."""
    iz = dot(wo, ng)
    t = min(0.9 * iz, 0.01)
    x = norm([n[j] - dot(n, ng) * ng[j] for j in range(3)])
    ix = dot(wo, x)
    best = None
    for k in range(200001):  # z on a fine grid: the lowest height not below t
        z = k / 200000.0
        nn = [math.sqrt(1 - z * z) * x[j] + z * ng[j] for j in range(3)]
        height = 2 * dot(nn, wo) * z - iz
        if height >= t and (best is None or height < best[0]):
            best = (height, nn)
    return best[1]


def make(out):
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    write_plane(out)
    wo = norm(CAMERA)
    n = norm(AWAY)
    assert dot([2 * dot(n, wo) * n[j] - wo[j] for j in range(3)], [0, 1, 0]) < 0
    nl = lifted([0.0, 1.0, 0.0], wo, n)
    graph = {"texcc": 1, "sources": [os.path.join(here, "valid_reflection.cl")],
             "nodes": [{"id": "away", "fn": "givenNormal",
                        "args": {"x": n[0], "y": n[1], "z": n[2]}},
                       {"id": "lifted", "fn": "givenNormal",
                        "args": {"x": nl[0], "y": nl[1], "z": nl[2]}}],
             "materials": {m: {"bsdf": "glossy", "color": [1, 1, 1], "roughness": 0.3,
                               "normal": {"node": m}} for m in ("away", "lifted")}}
    graph["materials"]["diffuse"] = {"bsdf": "diffuse", "color": [0.5, 0.5, 0.5],
                                     "normal": {"node": "away"}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=1)
    for m in ("away", "lifted"):
        scene = {"texrender": 1,
                 "camera": {"position": list(CAMERA), "target": [0, 0, 0], "up": [0, 1, 0],
                            "fov": 1.0},
                 "render": {"maxDepth": 2},
                 "lights": [{"type": "sky", "radiance": [1.0, 1.0, 1.0]}],
                 "meshes": [{"obj": "plane.obj", "material": m}]}
        with open(os.path.join(out, m + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
    radiance = 1.0 / (2.0 * (1.0 - math.cos(math.radians(RADIUS))))
    scene["lights"] = [{"type": "sun", "radiance": [radiance] * 3, "angularRadius": RADIUS,
                        "direction": norm(SUN)}]
    scene["meshes"][0]["material"] = "diffuse"
    with open(os.path.join(out, "diffuse.json"), "w") as f:
        json.dump(scene, f, indent=1)
    print("N %s, lifted %s" % (["%.4f" % x for x in n], ["%.4f" % x for x in nl]))
    return 0


def check(out):
    means = {m: centre_mean(os.path.join(out, m + ".exr"), 2) for m in ("away", "lifted", "diffuse")}
    ratio = means["away"] / means["lifted"] if means["lifted"] > 0 else float("nan")
    good = means["lifted"] > 0.05 and abs(ratio - 1) <= 0.01
    print("away %.4f, lifted %.4f, ratio %.4f %s" % (means["away"], means["lifted"], ratio,
                                                    "ok" if good else "FAIL"))
    want = diffuse_expected()
    good_d = abs(means["diffuse"] / want - 1) <= 0.01
    print("diffuse %.4f expected %.4f %s" % (means["diffuse"], want, "ok" if good_d else "FAIL"))
    print("PASS" if good and good_d else "FAIL")
    return 0 if good and good_d else 1


if __name__ == "__main__":
    sys.exit(make(sys.argv[2]) if sys.argv[1] == "make" else check(sys.argv[2]))
