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
compensation gives back what single-scattering GGX loses; a white dielectric's base gets 1 - its
specular layer's estimated albedo, as in Cycles: within 1.5%, 1% for a smooth metal), and a
principled dielectric with specular 0 is a Lambertian base: exactly its base color.
"""
import os

from texcc_tools.testing.sphere_scene import furnace_scene, main, make_folder, read_image, write_json

# name: (inputs, expectation) with expectation ("le", 1) | ("near", value, tolerance)
MATERIALS = {}
for m in (0.0, 0.5, 1.0):
    for r in (0.0, 0.3, 0.6, 1.0):
        name = "m%g_r%g" % (m, r)
        # white keeps its energy at every roughness: the metal by the multiple-scattering
        # compensation (single-scattering GGX alone returns 0.31 at roughness 1), the
        # dielectric by giving the base 1 - the specular layer's estimated albedo (Cycles'
        # layering; 1 - F(cos wo) instead returned 0.971 at roughness 1)
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


def make(out):
    make_folder(out, 24, 48, {"texcc": 1, "sources": [], "nodes": [],
                              "materials": {n: dict({"bsdf": "principled"}, **i)
                                            for n, (i, _) in MATERIALS.items()}})
    for n in MATERIALS:
        write_json(os.path.join(out, n + ".json"), furnace_scene(n, [0, 0, 4], 30))


def check(out):
    ok = True
    for n, (inputs, exp) in MATERIALS.items():
        img = read_image(os.path.join(out, n + ".exr"))
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
    main({"make": make, "check": check})
