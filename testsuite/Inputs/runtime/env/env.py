"""The environment light (scene.json "environment", docs/scene.md) against closed forms and a
numerical reference (testsuite/runtime/env-*.test).

  env.py make OUTDIR         writes sphere.obj, graph.json, the maps and the scenes below
  env.py check OUTDIR CASE   reads OUTDIR/CASE.exr and OUTDIR/CASE-var.exr (texrender
                             --variance) and compares them with what CASE should give

Cases (a Lambertian sphere of albedo RHO at the origin, radius 1, camera on +z):
  const     a constant 8x4 map of value C, strength 1.5: the furnace. Every pixel on the sphere
            is RHO x C x 1.5 and every other pixel C x 1.5 (next-event estimation of the map and
            BSDF samples that escape, combined by MIS, must add up to the constant sky's value)
  onehot    a 32x16 map of a small base value with one hot texel, rotated by a matrix: the
            sphere's radiance RHO / pi x the irradiance of the bilinearly interpolated map,
            integrated numerically (the hot texel dominates it: next-event estimation's density
            and its MIS weights must be right, and the matrix must rotate the map the documented
            way: e = M d). Regions by expected value, each within 1% and 4 standard errors
  gradient  a smooth 64x32 map of three colours, rotated about the map's z, seen by the
            camera: every 8x8 block of background pixels against the lookup of Cycles'
            equirectangular coordinates (u = 0.5 - atan2(e.y, e.x) / 2pi, v = 1 - acos(e.z) / pi,
            v = 0 the image's bottom row, bilinear between texel centres, wrapping) of the
            pixels' directions, within 1%
  srgb      the gradient as an 8-bit sRGB PNG: interpolated encoded and decoded after (Cycles
            reads 8-bit images so), every block within 1%
  closest   the gradient with "interpolation": "closest", within 1%

  env.py errors OUTDIR       writes bad-*.json scenes (env-errors.test) and the maps they name
"""
import math
import os
import struct
import sys
import zlib

import numpy as np

from texcc_tools.exr import write_exr
from texcc_tools.testing.sphere_scene import main, make_folder, read_image, write_json

RHO = 0.5
C = np.array([0.6, 0.8, 1.0])
CAMERA, FOV, SIZE = np.array([0.0, 0.0, 4.0]), 36.0, 48
BASE, HOT, HOT_XY = 0.05, np.array([400.0, 300.0, 200.0]), (20, 5)  # HOT_XY: column, row from top
# e = M d: the onehot map turned 90 degrees about x (world +y looks at the map's +z... and so on)
M_ONEHOT = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
ANGLE = math.radians(30.0)
M_GRADIENT = np.array([[math.cos(ANGLE), -math.sin(ANGLE), 0.0],
                       [math.sin(ANGLE), math.cos(ANGLE), 0.0], [0.0, 0.0, 1.0]])


def gradient_map(w=64, h=32):
    """Smooth, positive, different in each channel and along both axes (row 0 at the top)."""
    y, x = np.meshgrid((np.arange(h) + 0.5) / h, (np.arange(w) + 0.5) / w, indexing="ij")
    r = 0.6 + 0.4 * np.sin(2 * math.pi * x) * np.cos(math.pi * y)
    g = 0.2 + 0.7 * y
    b = 0.3 + 0.5 * x * (1 - x) * 4 * (1 - y)
    return np.stack([r, g, b], axis=-1)


def write_png8(path, rgb):
    """An 8-bit RGB PNG of rgb (values in [0, 1], row 0 at the top)."""
    h, w, _ = rgb.shape
    data = np.clip(np.rint(rgb * 255), 0, 255).astype(np.uint8)
    raw = b"".join(b"\0" + data[y].tobytes() for y in range(h))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + \
            struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def srgb_decode(v):
    return np.where(v < 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def lookup(img, u, v, closest=False):
    """Cycles' Environment Texture lookup of img (row 0 at the top) at (u, v): v = 0 is the
    bottom row; Linear is bilinear between texel centres, wrapping in both axes."""
    h, w, _ = img.shape
    tex = img[::-1]  # row 0 the bottom
    if closest:
        x = np.floor(u * w).astype(int) % w
        y = np.floor(v * h).astype(int) % h
        return tex[y, x]
    fx, fy = u * w - 0.5, v * h - 0.5
    x0, y0 = np.floor(fx), np.floor(fy)
    tx, ty = (fx - x0)[..., None], (fy - y0)[..., None]
    x0, y0 = x0.astype(int), y0.astype(int)
    xa, xb, ya, yb = x0 % w, (x0 + 1) % w, y0 % h, (y0 + 1) % h
    return ((tex[ya, xa] * (1 - tx) + tex[ya, xb] * tx) * (1 - ty) +
            (tex[yb, xa] * (1 - tx) + tex[yb, xb] * tx) * ty)


def to_uv(e):
    u = 0.5 - np.arctan2(e[..., 1], e[..., 0]) / (2 * math.pi)
    v = 1.0 - np.arccos(np.clip(e[..., 2], -1, 1)) / math.pi
    return u, v


def from_uv(u, v):
    theta, phi = math.pi * (1 - v), math.pi * (1 - 2 * u)
    return np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)],
                    axis=-1)


def camera_rays(size, n_sub):
    """Unit directions of n_sub x n_sub points per pixel (row 0 at the top)."""
    half = math.tan(math.radians(FOV) / 2)
    s = (np.arange(size * n_sub) + 0.5) / (size * n_sub)
    X, Y = np.meshgrid(2 * s - 1, 1 - 2 * s)
    d = np.stack([X * half, Y * half, -np.ones_like(X)], axis=-1)
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def sphere_hits(d):
    b = d @ CAMERA
    disc = b * b - (CAMERA @ CAMERA - 1.0)
    hit = disc > 0
    t = -b - np.sqrt(np.maximum(disc, 0))
    return hit, CAMERA + d * t[..., None]


def scene(light, fov=FOV):
    return {"texrender": 1,
            "camera": {"position": CAMERA.tolist(), "target": [0, 0, 0], "up": [0, 1, 0],
                       "fov": fov},
            "film": {"width": SIZE, "height": SIZE},
            "lights": [dict(light, type="environment")],
            "meshes": [{"obj": "sphere.obj", "material": "white"}]}


def onehot_map():
    img = np.full((16, 32, 3), BASE)
    img[HOT_XY[1], HOT_XY[0]] = HOT
    return img


def make(out):
    make_folder(out, 64, 128, {"texcc": 1, "sources": [], "nodes": [],
                               "materials": {"white": {"bsdf": "diffuse",
                                                       "color": [RHO, RHO, RHO]}}})
    maps = {"map-const.exr": np.broadcast_to(C, (4, 8, 3)), "map-onehot.exr": onehot_map(),
            "map-gradient.exr": gradient_map()}
    for name, img in maps.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(write_exr(np.ascontiguousarray(img, np.float32)))
    write_png8(os.path.join(out, "map-gradient.png"), gradient_map())
    write_json(os.path.join(out, "const.json"), scene({"image": "map-const.exr", "strength": 1.5}))
    write_json(os.path.join(out, "onehot.json"),
               scene({"image": "map-onehot.exr", "matrix": M_ONEHOT.tolist()}))
    # The gradient cases look past a small sphere far away (the sky fills the view).
    for case, light in (("gradient", {"image": "map-gradient.exr", "strength": 2.0}),
                        ("srgb", {"image": "map-gradient.png"}),
                        ("closest", {"image": "map-gradient.exr", "interpolation": "closest"})):
        s = scene(dict(light, matrix=M_GRADIENT.tolist()), fov=100.0)
        s["meshes"][0]["transform"] = {"scale": [0.01, 0.01, 0.01], "translate": [0, 0, -50]}
        write_json(os.path.join(out, case + ".json"), s)


def errors(out):
    make(out)
    nan = gradient_map()
    nan[3, 7, 1] = float("nan")
    with open(os.path.join(out, "map-nan.exr"), "wb") as f:
        f.write(write_exr(np.ascontiguousarray(nan, np.float32)))
    with open(os.path.join(out, "not-an-image.png"), "w") as f:
        f.write("not a PNG\n")
    good = {"image": "map-const.exr"}
    bad = {"no-image": {},
           "missing-image": {"image": "does-not-exist.exr"},
           "not-image": {"image": "not-an-image.png"},
           "empty-image": {"image": ""},
           "unknown-key": dict(good, rotation=30),
           "negative-strength": dict(good, strength=-1),
           "colorspace": dict(good, colorSpace="ACEScg"),
           "interpolation": dict(good, interpolation="cubic"),
           "matrix-shape": dict(good, matrix=[[1, 0, 0], [0, 1, 0]]),
           "matrix-shear": dict(good, matrix=[[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]),
           "matrix-scale": dict(good, matrix=[[2, 0, 0], [0, 1, 0], [0, 0, 1]]),
           "nan-texel": {"image": "map-nan.exr"}}
    for name, light in bad.items():
        write_json(os.path.join(out, "bad-%s.json" % name), scene(light))
    two = scene(good)
    two["lights"].insert(0, {"type": "sky", "radiance": [1, 1, 1]})
    write_json(os.path.join(out, "bad-two-worlds.json"), two)
    # A scaled rotation is a rotation: accepted (normalized), as is a mirror.
    write_json(os.path.join(out, "good-scaled.json"),
               scene(dict(good, matrix=(3 * M_GRADIENT).tolist())))


def irradiance(normals, img, m):
    """The irradiance at each normal (world space) from the bilinear map img rotated by m,
    integrated over 16 x 16 points per texel (only where the map is above its base value:
    the base adds pi x BASE)."""
    h, w, _ = img.shape
    n = 16
    s_u = (np.arange(w * n) + 0.5) / (w * n)
    s_v = (np.arange(h * n) + 0.5) / (h * n)
    U, V = np.meshgrid(s_u, s_v)
    L = lookup(img, U, V) - BASE
    keep = L.max(axis=-1) > 1e-9
    U, V, L = U[keep], V[keep], L[keep]
    e = from_uv(U, V)
    d = e @ m  # world direction: M^T e (rows of e times m)
    dw = (2 * math.pi * math.pi / (w * n * h * n)) * np.sin(math.pi * V)
    cos = np.maximum(normals @ d.T, 0.0)
    return cos @ (L * dw[:, None]) + math.pi * BASE


def erode(mask):
    out = mask.copy()
    out[1:] &= mask[:-1]
    out[:-1] &= mask[1:]
    out[:, 1:] &= mask[:, :-1]
    out[:, :-1] &= mask[:, 1:]
    return out


def check_blocks(img, exp, mask, block=8, tol=0.01):
    """Blocks wholly inside mask: relative error of the mean per channel."""
    worst, bad, count = 0.0, 0, 0
    for by in range(0, img.shape[0], block):
        for bx in range(0, img.shape[1], block):
            if not mask[by:by + block, bx:bx + block].all():
                continue
            got = img[by:by + block, bx:bx + block].mean(axis=(0, 1))
            want = exp[by:by + block, bx:bx + block].mean(axis=(0, 1))
            rel = float(np.max(np.abs(got - want) / want))
            worst = max(worst, rel)
            bad += rel > tol
            count += 1
    print("%d blocks, %d outside %.1f%%, worst %.3f%%" % (count, bad, 100 * tol, 100 * worst))
    return count > 0 and bad == 0


def check(out, case):
    img = read_image(os.path.join(out, case + ".exr"))[:, :, :3]
    var = read_image(os.path.join(out, case + "-var.exr"))[:, :, :3]
    n_sub = 4
    d = camera_rays(SIZE, n_sub)
    hit, p = sphere_hits(d)

    def pix(x):
        return x.reshape(SIZE, n_sub, SIZE, n_sub, *x.shape[2:]).mean(axis=(1, 3))
    # Pixels wholly on the sphere or wholly off it, and so are their neighbours (the points
    # above are not every point of a pixel).
    full = erode(hit.reshape(SIZE, n_sub, SIZE, n_sub).all(axis=(1, 3)))
    none = erode(~hit.reshape(SIZE, n_sub, SIZE, n_sub).any(axis=(1, 3)))
    ok = True
    if case == "const":
        for name, mask, want in (("sphere", full, RHO * C * 1.5), ("sky", none, C * 1.5)):
            got = img[mask].mean(axis=0)
            se = np.sqrt(var[mask].sum(axis=0)) / mask.sum()
            rel = np.abs(got - want) / want
            good = bool((rel <= 0.005).all() and (np.abs(got - want) <= 4 * se + 1e-5 * want).all())
            ok &= good
            print("%-6s %4d px  mean %s  expected %s  worst rel %.4f  %s" % (
                name, mask.sum(), np.round(got, 5), np.round(want, 5), rel.max(),
                "ok" if good else "FAIL"))
    elif case == "onehot":
        normals = p.reshape(-1, 3)
        e = np.concatenate([irradiance(normals[k:k + 4096], onehot_map(), M_ONEHOT)
                            for k in range(0, len(normals), 4096)])
        exp = pix((RHO / math.pi * e).reshape(SIZE * n_sub, SIZE * n_sub, 3))
        lum = exp.mean(axis=-1)
        for name, sel in (("bright", lum > 1.0), ("mid", (lum > 0.2) & (lum <= 1.0)),
                          ("dark", lum <= 0.2)):
            m = full & sel
            if m.sum() < 20:
                print("%-6s only %d pixels FAIL" % (name, m.sum()))
                ok = False
                continue
            got, want = img[m].mean(axis=0), exp[m].mean(axis=0)
            se = np.sqrt(var[m].sum(axis=0)) / m.sum()
            rel = np.abs(got - want) / want
            good = bool((rel <= 0.01).all() and (np.abs(got - want) <= 4 * se).all())
            ok &= good
            print("%-6s %4d px  mean %s  expected %s  worst rel %.4f  z %s  %s" % (
                name, m.sum(), np.round(got, 4), np.round(want, 4), rel.max(),
                np.round((got - want) / se, 2), "ok" if good else "FAIL"))
    else:
        half = math.tan(math.radians(100.0) / 2)
        s = (np.arange(SIZE * n_sub) + 0.5) / (SIZE * n_sub)
        X, Y = np.meshgrid(2 * s - 1, 1 - 2 * s)
        dd = np.stack([X * half, Y * half, -np.ones_like(X)], axis=-1)
        dd /= np.linalg.norm(dd, axis=-1, keepdims=True)
        u, v = to_uv(dd @ M_GRADIENT.T)
        src = gradient_map()
        if case == "srgb":
            enc = np.clip(np.rint(src * 255), 0, 255) / 255.0
            val = srgb_decode(lookup(enc, u, v))
        else:
            val = lookup(src, u, v, closest=case == "closest") * (2.0 if case == "gradient" else 1)
        # the far sphere covers a pixel or two in the centre: leave the centre block out
        mask = np.ones((SIZE, SIZE), bool)
        mask[SIZE // 2 - 4:SIZE // 2 + 4, SIZE // 2 - 4:SIZE // 2 + 4] = False
        ok &= check_blocks(img, pix(val), mask)
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if sys.argv[1] == "check":
        sys.exit(check(sys.argv[2], sys.argv[3]))
    main({"make": make, "errors": errors})
