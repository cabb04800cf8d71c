"""Defining properties of textures/image.cl and textures/triplanar.cl, through texcc's host
target, on a small synthetic image fed to the evaluator (texel values known exactly)."""
import math

from texprops import Oracle, check, finish, lcg_points, main_args

UV = {"attr": "TexCoord0"}
P = {"attr": "ObjectPos"}
N = {"attr": "Normal"}
IMG = {"image": "img"}
o = Oracle(main_args(), "image", ["image.cl", "triplanar.cl"], {
    "tex": ("imageTexture", {"image": IMG, "uv": UV, "tiling": [1.0, 1.0], "offset": [0.0, 0.0]}),
    "tiled": ("imageTexture", {"image": IMG, "uv": UV, "tiling": [2.0, 3.0], "offset": [0.25, 0.0]}),
    "texuv": ("imageTextureUV", {"image": IMG, "tiling": [1.0, 1.0]}),
    "lum": ("imageLuminance", {"image": IMG, "uv": UV, "tiling": [1.0, 1.0], "offset": [0.0, 0.0]}),
    "tri": ("triplanar", {"image": IMG, "p": P, "n": N, "scale": 0.5, "sharpness": 4.0}),
    "tri1": ("triplanar", {"image": IMG, "p": P, "n": N, "scale": 0.5, "sharpness": 1.0}),
    "w4": ("triplanarWeights", {"n": N, "sharpness": 4.0}),
    "w1": ("triplanarWeights", {"n": N, "sharpness": 1.0}),
}, images={"img": "examples/image-multiply/images/dots.png"})

W, H = 4, 3
texels = [((x + 1) / 4.0, (y + 1) / 3.0, ((x * 7 + y * 5) % 6) / 5.0, 1.0) for y in range(H) for x in range(W)]
o.set_images([(W, H, texels)])


def texel(x, y):
    return texels[(y % H) * W + (x % W)]


def near(a, b, tol=1e-5):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


# Known values: at a texel centre the lookup is that texel; halfway between two texel centres,
# their average (bilinear); the image wraps (period 1 in u and v).
for y in range(H):
    for x in range(W):
        uv = ((x + 0.5) / W, (y + 0.5) / H)
        check(near(o.eval("tex", uv=uv), texel(x, y)), "imageTexture at texel (%d, %d)" % (x, y))
        check(near(o.eval("tex", uv=(uv[0] + 3.0, uv[1] - 2.0)), texel(x, y)), "imageTexture does not wrap")
        mid = ((x + 1.0) / W, (y + 0.5) / H)
        avg = tuple((a + b) / 2 for a, b in zip(texel(x, y), texel(x + 1, y)))
        check(near(o.eval("tex", uv=mid), avg), "imageTexture is not bilinear between texels (%d, %d)" % (x, y))
# Tiling and offset: tiled(uv) = tex(uv * tiling + offset); period 1/tiling.
for u, v in lcg_points(60, -2.0, 2.0, dims=2):
    a = o.eval("tiled", uv=(u, v))
    check(near(a, o.eval("tex", uv=(u * 2.0 + 0.25, v * 3.0)), 1e-4), "imageTexture tiling/offset")
    check(near(a, o.eval("tiled", uv=(u + 0.5, v + 1.0 / 3.0)), 1e-4), "imageTexture not periodic with 1/tiling")
    check(near(o.eval("texuv", uv=(u, v)), o.eval("tex", uv=(u, v))), "imageTextureUV != imageTexture at TexCoord0")
    c = o.eval("tex", uv=(u, v))
    check(abs(o.scalar("lum", uv=(u, v)) - (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2])) < 1e-5,
          "imageLuminance is not the Rec. 709 luminance")
    # Continuity: bilinear lookups move little over a small step.
    check(near(o.eval("tex", uv=(u + 1e-4, v)), c, 5e-3), "imageTexture jumps at uv (%g, %g)" % (u, v))

# Triplanar: weights non-negative and summing to 1; an axis-aligned normal picks exactly its
# projection (x: (p.y, p.z), y: (p.z, p.x), z: (p.x, p.y), times scale); a diagonal normal in
# the xy plane weighs x and y equally; continuous in the normal.
for n in lcg_points(60, -1.0, 1.0, seed=8):
    for node in ("w4", "w1"):
        w = o.eval(node, normal=n)[:3]
        check(all(c >= 0.0 for c in w) and abs(sum(w) - 1.0) < 1e-5, "%s weights %s" % (node, w))
    w1 = o.eval("w1", normal=n)[:3]
    s = sum(abs(c) for c in n)
    check(near(w1, [abs(c) / s for c in n]), "sharpness 1 weights are not |n| / sum |n|")
check(near(o.eval("w4", normal=(0.0, 0.0, 0.0))[:3], (1 / 3.0,) * 3), "a zero normal does not weigh the axes equally")
check(near(o.eval("w4", normal=(0.7, -0.7, 0.0))[:3], (0.5, 0.5, 0.0)), "diagonal normal weights")
for x, y, z in lcg_points(40, -3.0, 3.0, seed=9):
    for n, uv in (((1.0, 0.0, 0.0), (y, z)), ((0.0, -1.0, 0.0), (z, x)), ((0.0, 0.0, 2.0), (x, y))):
        got = o.eval("tri", pos=(x, y, z), normal=n)
        want = o.eval("tex", uv=(uv[0] * 0.5, uv[1] * 0.5))
        check(near(got, want, 1e-4), "triplanar with normal %s is not the %s projection" % (n, uv))
    a = o.eval("tri1", pos=(x, y, z), normal=(0.6, 0.64, 0.48))
    b = o.eval("tri1", pos=(x, y, z), normal=(0.6001, 0.64, 0.48))
    check(near(a, b, 1e-3), "triplanar jumps with the normal")
finish()
