"""The white furnace for the Principled subset (testsuite/runtime/principled-furnace.test).

  furnace.py make OUTDIR            writes sphere.obj, graph.json (one material per setting)
                                    and one scene per material: a unit sphere filling the
                                    view under a uniform sky of radiance 1
  furnace.py check OUTDIR           reads OUTDIR/<material>.exr and prints, per material,
                                    the mean radiance of the central 6x6 pixels (all on the
                                    sphere) and whether it meets the material's expectation

Under a uniform sky of radiance 1 a convex object's pixel shows its directional albedo at
the view direction. So every material must be <= 1 (energy conservation), a white one ~1 at
every metallic and roughness (a white metal's Fresnel is 1 and the multiple-scattering
compensation gives back what single-scattering GGX loses; a white dielectric's base gets what
its specular layer does not reflect: within 1.5%, 1% for a smooth metal), and a
principled dielectric with specular 0 is a Lambertian base: exactly its base color.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "scripts"))

# name: (inputs, expectation) with expectation ("le", 1) | ("near", value, tolerance)
MATERIALS = {}
for m in (0.0, 0.5, 1.0):
    for r in (0.0, 0.3, 0.6, 1.0):
        name = "m%g_r%g" % (m, r)
        # white keeps its energy at every roughness: the metal by the multiple-scattering
        # compensation (single-scattering GGX alone returns 0.31 at roughness 1), the
        # dielectric by giving the base exactly what the specular layer does not reflect
        # (1 - F(cos wo) instead returned 0.971 at roughness 1)
        MATERIALS[name] = ({"baseColor": [1, 1, 1], "metallic": m, "roughness": r},
                           ("near", 1.0, 0.015))
MATERIALS["spec1_r0.2"] = ({"baseColor": [1, 1, 1], "metallic": 0.0, "roughness": 0.2,
                            "specular": 1.0}, ("near", 1.0, 0.015))
MATERIALS["black_spec1"] = ({"baseColor": [0, 0, 0], "specular": 1.0, "roughness": 0.3},
                            ("le", 1.0))
MATERIALS["metal_smooth"] = ({"baseColor": [1, 1, 1], "metallic": 1.0, "roughness": 0.05},
                             ("near", 1.0, 0.01))
MATERIALS["lambert"] = ({"baseColor": [0.5, 0.25, 0.75], "specular": 0.0, "roughness": 0.5},
                        ("near", None, 0.01))


def sphere_obj(rows=24, cols=48):
    lines = []
    for i in range(rows + 1):
        t = math.pi * i / rows
        for j in range(cols + 1):
            p = 2 * math.pi * j / cols
            x, y, z = math.sin(t) * math.cos(p), math.cos(t), math.sin(t) * math.sin(p)
            lines.append("v %.6f %.6f %.6f" % (x, y, z))
            lines.append("vn %.6f %.6f %.6f" % (x, y, z))
    w = cols + 1
    for i in range(rows):
        for j in range(cols):
            a, b, c, d = i * w + j + 1, i * w + j + 2, (i + 1) * w + j + 2, (i + 1) * w + j + 1
            # counter-clockwise seen from outside
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, c, c, b, b))
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, d, d, c, c))
    return "\n".join(lines) + "\n"


def make(out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "sphere.obj"), "w") as f:
        f.write(sphere_obj())
    graph = {"texcc": 1, "sources": [], "nodes": [],
             "materials": {n: dict({"bsdf": "principled"}, **i)
                           for n, (i, _) in MATERIALS.items()}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f, indent=1)
    for n in MATERIALS:
        scene = {"texrender": 1,
                 "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov": 30},
                 "lights": [{"type": "sky", "radiance": [1, 1, 1]}],
                 "meshes": [{"obj": "sphere.obj", "material": n}]}
        with open(os.path.join(out, n + ".json"), "w") as f:
            json.dump(scene, f)


def check(out):
    from texexr import read_exr
    ok = True
    for n, (inputs, exp) in MATERIALS.items():
        with open(os.path.join(out, n + ".exr"), "rb") as f:
            img = read_exr(f.read())
        h, w = img.shape[:2]
        c = img[h // 2 - 3:h // 2 + 3, w // 2 - 3:w // 2 + 3, :3].reshape(-1, 3).mean(axis=0)
        good = bool((c <= 1.005).all())  # every material: energy <= 1 (+ noise)
        if exp[0] == "le":
            want = "<= 1"
        else:
            ref = inputs["baseColor"] if exp[1] is None else [exp[1]] * 3
            good &= all(abs(a - b) <= exp[2] * max(b, 1e-6) for a, b in zip(c, ref))
            want = "within %g%% of %s" % (exp[2] * 100, ref)
        ok &= good
        print("%-12s %.4f %.4f %.4f  %s %s" % (n, c[0], c[1], c[2], want,
                                               "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if sys.argv[1] == "make":
        make(sys.argv[2])
    else:
        sys.exit(check(sys.argv[2]))
