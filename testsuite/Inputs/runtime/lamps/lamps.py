"""Point, spot and area lamps lighting a Lambertian floor, against the closed form
(testsuite/runtime/light-lamps.test).

  lamps.py make OUTDIR         writes floor.obj, graph.json and one scene per lamp (SCENES):
                               a floor of albedo RHO at y = 0 seen from straight above, one lamp
  lamps.py errors OUTDIR       writes bad-NAME.json: scenes with one invalid lamp field each
                               (BAD; light-lamp-errors.test checks the error lines)
  lamps.py check OUTDIR NAME   reads OUTDIR/NAME.exr and NAME-var.exr (texrender --variance)
                               and compares each 4x4-pixel block's mean with the expectation

The floor is a plane, so it receives only the lamp's direct light: its radiance is RHO / pi
times the irradiance, integrated here over the lamp's surface in Cycles' units (a point or
spot lamp of power P: intensity P / (4 pi) at radius 0, else a disk of radius r facing the lit
point with radiance P / (4 pi^2 r^2); a spot's smoothstep edge; an area lamp's radiance
P / (pi A) on the side it lights). Camera rays that cross a lamp with "visibleToCamera" add its
radiance (a point lamp of radius > 0 is a disk facing the camera; a spot seen from outside its
cone and an area lamp seen from its back add nothing); without it (Blender's default) the
camera does not see the lamp ("point-hidden"). "sphere" (softFalloff false, Cycles' sphere
lamp) lights the floor exactly as a point would (it is wholly above every floor point's
horizon; the soft-falloff disk of the same radius gives up to 9% less under it) and is seen
by the camera as its silhouette. "point-shadow" and "point-noshadow" put a black
square between a point lamp and the floor: its shadow is exactly 0 with castShadow (the
default) and not there without it. A block passes within 1.5% (or 1e-3 of the brightest
block) and 4 standard errors of its expectation; blocks expected dark must be exactly 0.
Inverse-square falloff, the cone's edge and the lamps' units all have to be right.
"""
import math
import os
import sys

import numpy as np

from texcc_tools.testing.sphere_scene import main, read_image, write_json

RHO = 0.5
CAMERA_H, FOV, SIZE, SPP = 5.0, 60.0, 32, 64
SCENES = {
    "point": {"type": "point", "position": [0.3, 1.0, 0.0], "power": [100, 80, 60]},
    "point-disk": {"type": "point", "position": [0.0, 1.0, 0.0], "power": [100, 100, 100],
                   "radius": 0.25, "visibleToCamera": True},
    "point-hidden": {"type": "point", "position": [0.0, 1.0, 0.0], "power": [100, 100, 100],
                     "radius": 0.25},
    "sphere": {"type": "point", "position": [0.0, 1.0, 0.0], "power": [100, 100, 100],
               "radius": 0.3, "softFalloff": False, "visibleToCamera": True},
    "point-shadow": {"type": "point", "position": [0.3, 1.0, 0.0], "power": [100, 100, 100]},
    "point-noshadow": {"type": "point", "position": [0.3, 1.0, 0.0], "power": [100, 100, 100],
                       "castShadow": False},
    "spot": {"type": "spot", "position": [0.0, 1.5, 0.0], "direction": [0.2, -1.0, 0.0],
             "power": [200, 200, 200], "radius": 0.1, "spotSize": 50.0, "spotBlend": 0.3},
    "spot-hard": {"type": "spot", "position": [0.0, 1.0, 0.0], "direction": [0, -1, 0],
                  "power": [150, 150, 150], "spotSize": 60.0, "spotBlend": 0.0},
    "area-rect": {"type": "area", "position": [0.0, 1.0, 0.0], "direction": [0, -1, 0],
                  "axisU": [1, 0, 1], "shape": "rectangle", "size": [1.5, 0.5],
                  "power": [60, 60, 60]},
    "area-ellipse": {"type": "area", "position": [0.5, 0.8, 0.0], "direction": [-0.3, -1, 0],
                     "shape": "ellipse", "size": [1.0, 0.6], "axisU": [0, 0, 1],
                     "power": [40, 50, 60]},
}
# Scenes with a black square (side 2 OCC_HALF, facing up and down) at height OCC_Y between the
# lamp and the floor: with castShadow its shadow is black, without it the floor is lit as if
# it were not there; the square itself is black (albedo 0) wherever the camera sees it.
OCCLUDED = ("point-shadow", "point-noshadow")
OCC_X, OCC_Y, OCC_HALF = 1.0, 0.5, 0.2

# Invalid lamps: each case changes one field of a valid lamp.
BAD = {
    "point-no-power": ("point", {"power": None}),
    "point-negative-power": ("point", {"power": [1, -2, 1]}),
    "point-negative-radius": ("point", {"radius": -0.1}),
    "point-direction": ("point", {"direction": [0, -1, 0]}),
    "point-shadow-string": ("point", {"castShadow": "no"}),
    "spot-no-direction": ("spot-hard", {"direction": None}),
    "spot-zero-direction": ("spot-hard", {"direction": [0, 0, 0]}),
    "spot-size": ("spot-hard", {"spotSize": 200}),
    "spot-blend": ("spot-hard", {"spotBlend": 1.5}),
    "area-shape": ("area-rect", {"shape": "triangle"}),
    "area-size": ("area-rect", {"size": [1, 0]}),
    "area-size-array": ("area-rect", {"size": [1, 2, 3]}),
    "area-axis-parallel": ("area-rect", {"axisU": [0, 2, 0]}),
    "area-radius": ("area-rect", {"radius": 0.5}),
    "lamp-type": ("point", {"type": "lamp"}),
    "point-overflow": ("point-disk", {"radius": 1e-30}),
}


def errors(out):
    make(out)  # floor.obj and graph.json, for the cases found after the scene is read
    for name, (base, change) in BAD.items():
        lamp = dict(SCENES[base])
        for k, v in change.items():
            if v is None:
                lamp.pop(k)
            else:
                lamp[k] = v
        write_json(os.path.join(out, "bad-%s.json" % name), {
            "texrender": 1, "lights": [{"type": "sky", "radiance": [1, 1, 1]}, lamp],
            "meshes": [{"obj": "floor.obj", "material": "white"}]})


def make(out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "floor.obj"), "w") as f:
        f.write("v -20 0 -20\nv 20 0 -20\nv 20 0 20\nv -20 0 20\nvn 0 1 0\n"
                "f 1//1 3//1 2//1\nf 1//1 4//1 3//1\n")
    x0, x1, y, h = OCC_X - OCC_HALF, OCC_X + OCC_HALF, OCC_Y, OCC_HALF
    with open(os.path.join(out, "occluder.obj"), "w") as f:
        f.write("v %g %g %g\nv %g %g %g\nv %g %g %g\nv %g %g %g\n"
                "f 1 3 2\nf 1 4 3\n" % (x0, y, -h, x1, y, -h, x1, y, h, x0, y, h))
    write_json(os.path.join(out, "graph.json"),
               {"texcc": 1, "sources": [], "nodes": [],
                "materials": {"white": {"bsdf": "diffuse", "color": [RHO, RHO, RHO]},
                              "black": {"bsdf": "diffuse", "color": [0, 0, 0]}}})
    for name, lamp in SCENES.items():
        meshes = [{"obj": "floor.obj", "material": "white"}]
        if name in OCCLUDED:
            meshes.append({"obj": "occluder.obj", "material": "black"})
        write_json(os.path.join(out, name + ".json"), {
            "texrender": 1,
            "camera": {"position": [0, CAMERA_H, 0], "target": [0, 0, 0], "up": [0, 0, -1],
                       "fov": FOV},
            "film": {"width": SIZE, "height": SIZE}, "render": {"spp": SPP},
            "lights": [lamp], "meshes": meshes})


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def smoothstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3 - 2 * x)


def spot_factor(lamp, w):
    """w: unit vectors from the lamp towards the lit points (..., 3)."""
    if lamp["type"] != "spot":
        return 1.0
    cos_half = math.cos(math.radians(lamp["spotSize"]) / 2)
    cos = w @ unit(lamp["direction"])
    blend = lamp["spotBlend"]
    if blend == 0:
        return (cos > cos_half).astype(float)
    return smoothstep((cos - cos_half) / ((1 - cos_half) * blend))


def frame(n):
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    t = unit(np.cross(n, a))
    return t, np.cross(n, t)


def irradiance(lamp, x):
    """Irradiance at floor points x (N, 3), normal +y, per channel (N, 3)."""
    power = np.array(lamp["power"], dtype=float)
    c = np.array(lamp["position"], dtype=float)
    if lamp["type"] in ("point", "spot") and (lamp.get("radius", 0) == 0 or
                                              lamp.get("softFalloff", True) is False):
        # a point, or a sphere wholly above every floor point's horizon (for which a uniform
        # sphere of radiance P / (4 pi^2 r^2) gives exactly a point's irradiance)
        v = c - x
        d2 = (v * v).sum(-1)
        w = v / np.sqrt(d2)[:, None]
        e = np.maximum(w[:, 1], 0) / d2 * spot_factor(lamp, -w)
        return e[:, None] * power / (4 * math.pi)
    if lamp["type"] == "area":
        n = unit(lamp["direction"])
        u = np.array(lamp.get("axisU", [1, 0, 0]), dtype=float)
        u = unit(u - (u @ n) * n)
        v = np.cross(n, u)
        w_, h_ = (lamp["size"], lamp["size"]) if np.isscalar(lamp["size"]) else lamp["size"]
        k = 48
        s = (np.arange(k) + 0.5) / k * 2 - 1
        a, b = np.meshgrid(s, s)
        a, b = a.ravel(), b.ravel()
        if lamp["shape"] == "ellipse":
            keep = a * a + b * b <= 1
            a, b = a[keep], b[keep]
            area = math.pi / 4 * w_ * h_
        else:
            area = w_ * h_
        q = c + np.outer(a * w_ / 2, u) + np.outer(b * h_ / 2, v)  # (M, 3)
        da = area / len(q)
        radiance = power / (math.pi * area)
        normals = np.broadcast_to(n, q.shape)
        fac = np.ones(len(q))
        return _integrate(x, q, normals, fac, da) [:, None] * radiance
    # a disk of radius r facing each point (all points at once: frames per point)
    r = lamp["radius"]
    nr, na = 12, 24
    rr = r * np.sqrt((np.arange(nr) + 0.5) / nr)
    ph = (np.arange(na) + 0.5) / na * 2 * math.pi
    R, P = np.meshgrid(rr, ph)
    du, dv = (R * np.cos(P)).ravel(), (R * np.sin(P)).ravel()
    da = math.pi * r * r / (nr * na)
    radiance = power / (4 * math.pi ** 2 * r * r)
    n = unit_rows(x - c)  # (N, 3)
    a = np.where(np.abs(n[:, :1]) < 0.9, np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]]))
    t = unit_rows(np.cross(n, a))
    b = np.cross(n, t)
    q = c + du[None, :, None] * t[:, None, :] + dv[None, :, None] * b[:, None, :]  # (N, M, 3)
    v = q - x[:, None, :]
    d2 = (v * v).sum(-1)
    w = v / np.sqrt(d2)[..., None]  # from the lit point to the lamp point
    cos_x = np.maximum(w[..., 1], 0)
    cos_q = np.maximum(-(w * n[:, None, :]).sum(-1), 0)  # the disk faces the point
    e = (cos_x * cos_q / d2 * spot_factor(lamp, -w) * da).sum(-1)
    return e[:, None] * radiance


def unit_rows(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _integrate(x, q, nq, fac, da):
    """sum over lamp points q (normals nq, factors fac) of cos_x cos_q / d^2 dA, for each x."""
    v = q[None, :, :] - x[:, None, :]  # (N, M, 3) from x to q
    d2 = (v * v).sum(-1)
    w = v / np.sqrt(d2)[..., None]
    cos_x = np.maximum(w[..., 1], 0)
    cos_q = np.maximum(-(w * nq[None]).sum(-1), 0)
    return (cos_x * cos_q / d2 * fac[None] * da).sum(-1)


def camera_points(n_sub):
    half = math.tan(math.radians(FOV) / 2) * CAMERA_H
    s = (np.arange(SIZE * n_sub) + 0.5) / (SIZE * n_sub) * 2 - 1
    X, Z = np.meshgrid(s * half, s * half)  # row = image y (texrender: -up = +z), col = x
    return np.stack([X, np.zeros_like(X), Z], -1)


def in_occluder(p):
    """Whether points p (..., 3) at height OCC_Y lie on the occluder."""
    return (np.abs(p[..., 0] - OCC_X) <= OCC_HALF) & (np.abs(p[..., 2]) <= OCC_HALF)


def occlusion(name, lamp, flat):
    """1 where a floor point sees the lamp (radius 0) past the occluder, and the camera sees
    the floor point; 0 where the camera sees the black occluder or, with castShadow, the
    occluder hides the lamp."""
    cam = np.array([0, CAMERA_H, 0.0])
    f = (CAMERA_H - OCC_Y) / CAMERA_H
    seen = ~in_occluder(cam + f * (flat - cam))
    if not lamp.get("castShadow", True):
        return seen.astype(float)
    c = np.array(lamp["position"], dtype=float)
    g = OCC_Y / c[1]
    lit = ~in_occluder(flat + g * (c - flat))
    return (seen & lit).astype(float)


def expected(lamp, name=None):
    """Per pixel: the mean over n x n points (8 x 8 for a point, whose field is cheap and may
    have a hard edge; the camera's view of a disk lamp's edge also 8 x 8)."""
    small = lamp["type"] != "area" and lamp.get("radius", 0) == 0
    n_sub = 8 if small else 2
    flat = camera_points(n_sub).reshape(-1, 3)
    rad = RHO / math.pi * irradiance(lamp, flat)
    if name in OCCLUDED:
        rad *= occlusion(name, lamp, flat)[:, None]
    rad = rad.reshape(SIZE, n_sub, SIZE, n_sub, 3).mean(axis=(1, 3))
    if lamp.get("visibleToCamera") and lamp.get("radius", 0) > 0:
        # the disk facing the camera, crossed by the camera rays at its centre's height
        n_sub = 8
        flat = camera_points(n_sub).reshape(-1, 3)
        c = np.array(lamp["position"])
        cam = np.array([0, CAMERA_H, 0.0])
        d = unit_rows(flat - cam)
        if lamp.get("softFalloff", True) is False:  # a sphere: rays passing within r of c
            oc = c - cam
            closest = oc - (d @ oc)[:, None] * d
            inside = ((closest * closest).sum(-1) <= lamp["radius"] ** 2).astype(float)
        else:
            n = unit(cam - c)
            t = ((c - cam) @ n) / (d @ n)
            hit = cam + t[:, None] * d - c
            inside = ((hit * hit).sum(-1) <= lamp["radius"] ** 2).astype(float)
        cover = inside.reshape(SIZE, n_sub, SIZE, n_sub).mean(axis=(1, 3))
        rad += cover[..., None] * (np.array(lamp["power"]) /
                                   (4 * math.pi ** 2 * lamp["radius"] ** 2))
    return rad


def blocks(img, k=4):
    return img.reshape(SIZE // k, k, SIZE // k, k, 3).sum(axis=(1, 3))


def check(out, name):
    lamp = SCENES[name]
    img = read_image(os.path.join(out, name + ".exr"))[:, :, :3]
    var = read_image(os.path.join(out, name + "-var.exr"))[:, :, :3]
    exp = expected(lamp, name)
    n = 16
    got, want = blocks(img) / n, blocks(exp) / n
    se = np.sqrt(blocks(var)) / n
    peak = want.max()
    dark = want < 1e-6 * peak
    bad_dark = int((dark & (got != 0)).sum())
    lit = ~dark
    err = np.abs(got - want)
    ok_lit = (err <= np.maximum(0.015 * want, 1e-3 * peak)) | (err <= 4 * se)
    ok_lit &= err <= np.maximum(0.03 * want, 2e-3 * peak)  # 4 sigma, but never far off
    bad_lit = int((lit & ~ok_lit).sum())
    worst = float((err / np.maximum(want, 1e-3 * peak))[lit].max())
    print("%s: %d lit and %d dark block values; worst lit relative error %.4f; %d lit off, "
          "%d dark not 0; image mean %.5f expected %.5f" % (
              name, int(lit.sum()), int(dark.sum()), worst, bad_lit, bad_dark,
              float(img.mean()), float(exp.mean())))
    ok = bad_lit == 0 and bad_dark == 0
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if sys.argv[1] == "check":
        sys.exit(check(sys.argv[2], sys.argv[3]))
    main({"make": make, "errors": errors})
