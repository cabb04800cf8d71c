"""A Lambertian sphere under a sky and a large sun, against its closed form
(testsuite/runtime/sun-sky-sphere.test).

  sunsky.py make OUTDIR     writes sphere.obj, graph.json and scene.json: a unit sphere of
                            albedo RHO filling most of the view, a uniform sky of radiance SKY
                            and a sun of radiance SUN and half-angle ALPHA (large, so that BSDF
                            samples reach it often and its MIS weights matter)
  sunsky.py check OUTDIR    reads OUTDIR/img.exr and OUTDIR/var.exr (texrender --variance) and
                            compares the pixels wholly on the sphere with the closed form,
                            separately where the sun is wholly above the horizon, where it is
                            partly above and where it is wholly below

A convex object occludes nothing of its own upper hemisphere, so a point of normal n sees the
whole sky and the part of the sun's disc above its horizon: radiance RHO * SKY + RHO / pi *
SUN * g(theta), g(theta) the integral of max(cos, 0) over the disc at angle theta from n
(pi sin^2 ALPHA cos theta when the disc is wholly above; numerically otherwise). Each region's
mean must be within 0.6% and 4 standard errors (from the per-pixel variance) of the
expectation, which the light choice and the MIS weights of next-event estimation and BSDF
sampling for the sun and the sky must get exactly right to meet.
"""
import math
import os

import numpy as np

from texcc_tools.testing.sphere_scene import main, make_folder, read_image, write_json

RHO, SKY, SUN, ALPHA = 0.5, 1.0, 8.0, 20.0
SUN_DIR = np.array([0.0, 1.0, 0.0])  # towards the sun: the top half lit, the bottom dark
CAMERA, FOV, SIZE = np.array([0.0, 0.0, 4.0]), 36.0, 48


def make(out):
    make_folder(out, 64, 128, {"texcc": 1, "sources": [], "nodes": [],
                               "materials": {"white": {"bsdf": "diffuse",
                                                       "color": [RHO, RHO, RHO]}}})
    scene = {"texrender": 1,
             "camera": {"position": CAMERA.tolist(), "target": [0, 0, 0], "up": [0, 1, 0],
                        "fov": FOV},
             "film": {"width": SIZE, "height": SIZE},
             "lights": [{"type": "sky", "radiance": [SKY] * 3},
                        {"type": "sun", "direction": SUN_DIR.tolist(),
                         "radiance": [SUN] * 3, "angularRadius": ALPHA}],
             "meshes": [{"obj": "sphere.obj", "material": "white"}]}
    write_json(os.path.join(out, "scene.json"), scene)


def disc_integral():
    """g(theta) on a table of theta in [0, pi]: the integral of max(cos, 0) over the disc."""
    a = math.radians(ALPHA)
    # the disc in its own frame: polar angle t in [0, a], azimuth p
    t = (np.arange(200) + 0.5) / 200 * a
    p = (np.arange(400) + 0.5) / 400 * 2 * math.pi
    T, P = np.meshgrid(t, p, indexing="ij")
    dw = np.sin(T) * (a / 200) * (2 * math.pi / 400)
    thetas = np.linspace(0.0, math.pi, 361)
    g = []
    for th in thetas:
        # the normal at angle th from the disc's axis (in the x-z plane of the disc frame)
        cos = np.cos(T) * math.cos(th) + np.sin(T) * np.cos(P) * math.sin(th)
        g.append(float((np.maximum(cos, 0.0) * dw).sum()))
    return thetas, np.array(g)


def expected(size):
    """Per pixel: the expected radiance (8x8 points per pixel), whether every point hits the
    sphere, and the angle of the pixel centre's normal to the sun."""
    thetas, g = disc_integral()
    half = math.tan(math.radians(FOV) / 2)
    n_sub = 8
    s = (np.arange(size * n_sub) + 0.5) / (size * n_sub)
    sx = 2 * s - 1
    sy = 1 - 2 * s
    X, Y = np.meshgrid(sx, sy)  # row = y (top first), column = x
    d = np.stack([X * half, Y * half, -np.ones_like(X)], axis=-1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    o = CAMERA
    b = (d @ o)
    c = o @ o - 1.0
    disc = b * b - c
    hit = disc > 0
    tq = -b - np.sqrt(np.maximum(disc, 0))
    p = o + d * tq[..., None]
    cos_t = np.clip(p @ SUN_DIR, -1, 1)
    rad = RHO * SKY + RHO / math.pi * SUN * np.interp(np.arccos(cos_t), thetas, g)
    rad = np.where(hit, rad, 0.0)
    rad = rad.reshape(size, n_sub, size, n_sub).mean(axis=(1, 3))
    full = hit.reshape(size, n_sub, size, n_sub).all(axis=(1, 3))
    theta = np.degrees(np.arccos(cos_t)).reshape(size, n_sub, size, n_sub)
    return rad, full, theta.min(axis=(1, 3)), theta.max(axis=(1, 3))


def check(out):
    img = read_image(os.path.join(out, "img.exr"))[:, :, :3].mean(axis=-1)
    var = read_image(os.path.join(out, "var.exr"))[:, :, :3].mean(axis=-1)
    exp, full, tmin, tmax = expected(img.shape[0])
    regions = {"sun above": full & (tmax < 90 - ALPHA),
               "sun partly": full & (tmin > 90 - ALPHA) & (tmax < 90 + ALPHA),
               "sun below": full & (tmin > 90 + ALPHA)}
    ok = True
    for name, m in regions.items():
        n = int(m.sum())
        if n < 20:
            print("%-10s only %d pixels FAIL" % (name, n))
            ok = False
            continue
        got, want = float(img[m].mean()), float(exp[m].mean())
        se = math.sqrt(float(var[m].sum())) / n
        rel = abs(got - want) / want
        good = rel <= 0.006 and abs(got - want) <= 4 * se
        ok &= good
        print("%-10s %4d px  mean %.5f  expected %.5f  rel %.4f  z %.2f  %s" % (
            name, n, got, want, rel, (got - want) / se, "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    main({"make": make, "check": check})
