"""Defining properties of textures/checker.cl and textures/brick.cl, through texcc's host
target: values, periods, the flip between neighbouring cells, the mortar's share of the area."""
import math

from texprops import Oracle, check, finish, lcg_points, main_args

P = {"attr": "ObjectPos"}
UV = {"attr": "TexCoord0"}
BW, BH, MORTAR = 0.25, 0.1, 0.02
CA, CB, CM = [0.5, 0.2, 0.1], [0.7, 0.4, 0.2], [0.9, 0.9, 0.8]
o = Oracle(main_args(), "pattern", ["checker.cl", "brick.cl"], {
    "cm3": ("checkerMask3", {"p": P, "scale": 4.0}),
    "cm2": ("checkerMask2", {"uv": UV, "scale": 3.0}),
    "c3": ("checker3", {"p": P, "scale": 4.0, "colorA": [1.0, 0.5, 0.0], "colorB": [0.0, 0.25, 1.0]}),
    "mask": ("brickMask", {"uv": UV, "brickSize": [BW, BH], "mortar": MORTAR, "offset": 0.5}),
    "mask0": ("brickMask", {"uv": UV, "brickSize": [BW, BH], "mortar": MORTAR, "offset": 0.0}),
    "id": ("brickId", {"uv": UV, "brickSize": [BW, BH], "offset": 0.5}),
    "color": ("brickColor", {"uv": UV, "brickSize": [BW, BH], "mortar": MORTAR, "offset": 0.5,
                             "colorA": CA, "colorB": CB, "mortarColor": CM}),
})


def interior(x, scale):
    """True if x * scale is not within 1e-3 of a cell border."""
    f = x * scale - math.floor(x * scale)
    return 1e-3 < f < 1 - 1e-3


# Checkerboard: values in {0, 1}; known value at the origin cell (parity 0 is even: 1);
# period 2/scale along every axis; neighbouring cells flip.
check(o.scalar("cm3", pos=(0.1, 0.1, 0.1)) == 1.0, "checkerMask3 of the origin's cell is not 1")
check(o.scalar("cm3", pos=(0.3, 0.1, 0.1)) == 0.0, "checkerMask3 of the cell next to the origin's is not 0")
for x, y, z in lcg_points(200, -5.0, 5.0):
    if not all(interior(c, 4.0) for c in (x, y, z)):
        continue
    v = o.scalar("cm3", pos=(x, y, z))
    check(v in (0.0, 1.0), "checkerMask3 = %g, not 0 or 1" % v)
    for axis in range(3):
        q = [x, y, z]
        q[axis] += 0.5
        check(o.scalar("cm3", pos=tuple(q)) == v, "checkerMask3 not periodic with 2/scale along axis %d" % axis)
        q[axis] -= 0.25
        check(o.scalar("cm3", pos=tuple(q)) == 1.0 - v, "checkerMask3 does not flip between neighbours")
    want = [1.0, 0.5, 0.0] if v == 1.0 else [0.0, 0.25, 1.0]
    check(list(o.eval("c3", pos=(x, y, z))[:3]) == want, "checker3 colour does not follow its mask")
for u, v in lcg_points(200, -3.0, 3.0, dims=2):
    if not (interior(u, 3.0) and interior(v, 3.0)):
        continue
    m = o.scalar("cm2", uv=(u, v))
    want = 1.0 if (math.floor(u * 3.0) + math.floor(v * 3.0)) % 2 == 0 else 0.0
    check(m == want, "checkerMask2(%g, %g) = %g, expected %g" % (u, v, m, want))

# Bricks: mask in {0, 1}; periodic with (BW, 2 BH) at offset 0.5 and (BW, BH) at offset 0;
# brick id constant inside a brick, in [0, 1); colour = mortar colour in the joints and within
# [colorA, colorB] on the bricks; the mortar's share of a period matches its geometry.
pts = lcg_points(300, -2.0, 2.0, dims=2, seed=3)
for u, v in pts:
    m = o.scalar("mask", uv=(u, v))
    check(m in (0.0, 1.0), "brickMask = %g, not 0 or 1" % m)
    near_border = min(abs(u / BW * 2 - round(u / BW * 2)), abs(v / BH - round(v / BH))) < 1e-3
    if near_border:
        continue
    check(o.scalar("mask", uv=(u + BW, v)) == m, "brickMask not periodic in u with the brick width")
    check(o.scalar("mask", uv=(u, v + 2 * BH)) == m, "brickMask not periodic in v with two rows")
    check(o.scalar("mask0", uv=(u, v + BH)) == o.scalar("mask0", uv=(u, v)), "offset 0: not periodic in v with one row")
    c = o.eval("color", uv=(u, v))[:3]
    if m == 0.0:
        check(all(abs(a - b) < 1e-6 for a, b in zip(c, CM)), "brickColor in the mortar is not mortarColor")
    else:
        check(all(min(a, b) - 1e-6 <= x <= max(a, b) + 1e-6 for x, a, b in zip(c, CA, CB)),
              "brickColor outside [colorA, colorB]")
# Brick id: constant over one brick (row 0, first brick: u in (0, BW), v in (0, BH)).
row0 = {o.scalar("id", uv=(BW * a, BH * b)) for a in (0.01, 0.5, 0.99) for b in (0.02, 0.5, 0.98)}
check(len(row0) == 1 and 0.0 <= min(row0) < 1.0, "brickId not constant (and in [0, 1)) over a brick: %s" % row0)
# Odd rows are shifted by half a brick: the brick of row 1 spans u in (-BW/2, BW/2) + k BW.
row1 = {o.scalar("id", uv=(BW * (a - 0.5), BH * (1 + b))) for a in (0.01, 0.02, 0.5, 0.98, 0.99) for b in (0.2, 0.8)}
check(len(row1) == 1, "row 1 is not shifted by half a brick (brickId varies over the shifted brick)")
# Mortar share: on a fine grid over one period, 1 - (1 - MORTAR/BW)(1 - MORTAR/BH).
n = 120
zeros = sum(o.scalar("mask", uv=(BW * (i + 0.5) / n, 2 * BH * (j + 0.5) / n)) == 0.0
            for i in range(n) for j in range(n))
want = 1 - (1 - MORTAR / BW) * (1 - MORTAR / BH)
check(abs(zeros / float(n * n) - want) < 0.02, "mortar share %g, expected %g" % (zeros / float(n * n), want))
finish()
