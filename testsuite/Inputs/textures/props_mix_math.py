"""Defining properties of textures/mix.cl and textures/math.cl, through texcc's host target.
Free inputs come from attributes: a float from AO, float3s from ObjectPos and Normal."""
import math

from texprops import Oracle, check, finish, lcg_points, main_args

AO = {"attr": "AO"}
A3 = {"attr": "ObjectPos"}
B3 = {"attr": "Normal"}
nodes = {"mixv": ("mixValue", {"a": 2.0, "b": 6.0, "t": AO}),
         "mixc": ("mixColor", {"a": A3, "b": B3, "t": AO}),
         "range": ("mapRange", {"x": AO, "fromMin": 2.0, "fromMax": 4.0, "toMin": 10.0, "toMax": 0.0, "clampResult": 0}),
         "rangec": ("mapRange", {"x": AO, "fromMin": 2.0, "fromMax": 4.0, "toMin": 10.0, "toMax": 0.0, "clampResult": 1}),
         "range0": ("mapRange", {"x": AO, "fromMin": 1.0, "fromMax": 1.0, "toMin": 5.0, "toMax": 7.0, "clampResult": 0})}
for mode in range(9):
    nodes["blend%d" % mode] = ("blendColor", {"a": A3, "b": B3, "t": 1.0, "mode": mode})
nodes["blendhalf"] = ("blendColor", {"a": A3, "b": B3, "t": 0.5, "mode": 1})
for op in range(17):
    nodes["op%d" % op] = ("mathValue", {"a": AO, "b": 1.5, "op": op})
    nodes["opneg%d" % op] = ("mathValue", {"a": AO, "b": -2.0, "op": op})
    nodes["opc%d" % op] = ("mathColor", {"a": A3, "b": B3, "op": op})
o = Oracle(main_args(), "mix_math", ["mix.cl", "math.cl"], nodes)


def close(a, b, tol=1e-5):
    return abs(a - b) <= tol * max(1.0, abs(b))


# mixValue: the end points, linear in between, t clamped to [0, 1].
for t, want in ((0.0, 2.0), (1.0, 6.0), (0.25, 3.0), (-1.0, 2.0), (3.0, 6.0)):
    check(close(o.scalar("mixv", ao=t), want), "mixValue(2, 6, %g) != %g" % (t, want))
pts = lcg_points(40, 0.0, 1.0)
nrm = lcg_points(40, 0.0, 1.0, seed=5)
for a, b in zip(pts, nrm):
    got = o.eval("mixc", pos=a, normal=b, ao=0.3)[:3]
    check(all(close(g, x + (y - x) * 0.3) for g, x, y in zip(got, a, b)), "mixColor at t = 0.3")

# blendColor at t = 1 is the blend mode itself, per channel; at t = 0.5 halfway to it.
modes = [lambda x, y: y, lambda x, y: x * y, lambda x, y: x + y,
         lambda x, y: 1 - (1 - x) * (1 - y),
         lambda x, y: 2 * x * y if x < 0.5 else 1 - 2 * (1 - x) * (1 - y),
         lambda x, y: abs(x - y), min, max, lambda x, y: y]
for a, b in zip(pts, nrm):
    for mode, f in enumerate(modes):
        got = o.eval("blend%d" % mode, pos=a, normal=b)[:3]
        check(all(close(g, f(x, y)) for g, x, y in zip(got, a, b)), "blendColor mode %d at %s %s" % (mode, a, b))
    got = o.eval("blendhalf", pos=a, normal=b)[:3]
    check(all(close(g, x + (x * y - x) * 0.5) for g, x, y in zip(got, a, b)), "blendColor multiply t=0.5")
# Screen and multiply stay in [0, 1] for inputs in [0, 1].
for a, b in zip(pts, nrm):
    for mode in (1, 3, 4, 5, 6, 7):
        check(all(0.0 <= g <= 1.0 + 1e-6 for g in o.eval("blend%d" % mode, pos=a, normal=b)[:3]),
              "blendColor mode %d leaves [0, 1]" % mode)

# mathValue: every op code against its definition, on both sides of 0, and the fallback.
def ref(a, b, op):
    return [a + b, a - b, a * b, 0.0 if b == 0 else a / b, 0.0 if a <= 0 else a ** b,
            min(a, b), max(a, b), float(a < b), float(a > b),
            0.0 if b == 0 else a - b * math.floor(a / b), abs(a), 0.0 if a <= 0 else math.sqrt(a),
            math.sin(a), math.cos(a), float(a >= b), min(max(a, 0.0), 1.0), a][op]


for a in (-2.5, -1.0, 0.0, 0.3, 1.5, 2.0, 7.25):
    for op in range(17):
        for node, b in (("op%d" % op, 1.5), ("opneg%d" % op, -2.0)):
            got = o.scalar(node, ao=a)
            want = ref(a, b, op)
            check(close(got, want, 1e-5), "mathValue(%g, %g, op %d) = %g, expected %g" % (a, b, op, got, want))
# mathColor is mathValue per channel.
for a, b in zip(pts[:15], nrm[:15]):
    for op in range(17):
        got = o.eval("opc%d" % op, pos=a, normal=b)[:3]
        check(all(close(g, ref(x, y, op), 1e-5) for g, x, y in zip(got, a, b)), "mathColor op %d" % op)
# Modulo takes the sign of b and is periodic in a with period b.
for a in (-3.7, -0.2, 0.9, 5.1):
    r = o.scalar("opneg9", ao=a)
    check(-2.0 < r <= 0.0, "mathValue modulo by -2 of %g = %g not in (-2, 0]" % (a, r))

# mapRange: end points, linearity, reversed target, clamping, an empty source interval.
for x, want in ((2.0, 10.0), (4.0, 0.0), (3.0, 5.0), (5.0, -5.0), (1.0, 15.0)):
    check(close(o.scalar("range", ao=x), want), "mapRange(%g) != %g" % (x, want))
for x, want in ((5.0, 0.0), (1.0, 10.0), (2.5, 7.5)):
    check(close(o.scalar("rangec", ao=x), want), "clamped mapRange(%g) != %g" % (x, want))
check(close(o.scalar("range0", ao=3.0), 5.0), "mapRange with fromMin == fromMax is not toMin")
finish()
