"""Defining properties of textures/ramp.cl, evaluated through texcc's host target.
The ramp position t comes from the AO attribute, the one float attribute, so that one compiled
graph can be evaluated at any t."""

from texprops import Oracle, check, finish, main_args

T = {"attr": "AO"}
STOPS = [[0.0, 1.0, 0.0, 0.0], [0.5, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 1.0]]
VSTOPS = [[0.2, 1.0], [0.6, 3.0], [0.8, 2.0]]
nodes = {"lin": ("colorRamp", {"t": T, "stops": STOPS, "count": 3, "interpolation": 0}),
         "const": ("colorRamp", {"t": T, "stops": STOPS, "count": 3, "interpolation": 1}),
         "ease": ("colorRamp", {"t": T, "stops": STOPS, "count": 3, "interpolation": 2}),
         "two": ("colorRamp", {"t": T, "stops": STOPS, "count": 2, "interpolation": 0}),
         "one": ("colorRamp", {"t": T, "stops": STOPS, "count": 1, "interpolation": 0}),
         "vlin": ("valueRamp", {"t": T, "stops": VSTOPS, "count": 3, "interpolation": 0}),
         "vconst": ("valueRamp", {"t": T, "stops": VSTOPS, "count": 3, "interpolation": 1})}
o = Oracle(main_args(), "ramp", ["ramp.cl"], nodes)


def rgb(node, t):
    return o.eval(node, ao=t)[:3]


def near(a, b, tol=1e-5):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


# Known values: the stops themselves, linear midpoints, clamping outside the stops.
cases = [("lin", 0.0, (1, 0, 0)), ("lin", 0.5, (0, 1, 0)), ("lin", 1.0, (0, 0, 1)),
         ("lin", 0.25, (0.5, 0.5, 0)), ("lin", 0.75, (0, 0.5, 0.5)), ("lin", -3.0, (1, 0, 0)),
         ("lin", 7.0, (0, 0, 1)), ("const", 0.25, (1, 0, 0)), ("const", 0.49, (1, 0, 0)),
         ("const", 0.5, (0, 1, 0)), ("const", 0.99, (0, 1, 0)), ("const", 1.0, (0, 0, 1)),
         ("ease", 0.25, (0.5, 0.5, 0)), ("ease", 0.125, (1 - 0.15625, 0.15625, 0)),
         ("two", 0.75, (0, 1, 0)), ("one", 0.7, (1, 0, 0))]
for node, t, want in cases:
    got = rgb(node, t)
    check(near(got, want), "%s(t=%g) = %s, expected %s" % (node, t, got, want))
for t, want in ((0.0, 1.0), (0.4, 2.0), (0.7, 2.5), (0.9, 2.0)):
    check(abs(o.scalar("vlin", ao=t) - want) < 1e-5, "valueRamp linear(t=%g) != %g" % (t, want))
check(abs(o.scalar("vconst", ao=0.65) - 3.0) < 1e-6, "valueRamp constant(0.65) != 3")

# Continuity (linear and ease) at and between the stops; the constant ramp is a step.
for node in ("lin", "ease"):
    for k in range(0, 101):
        t = k / 100.0
        a, b = rgb(node, t - 1e-4), rgb(node, t + 1e-4)
        check(near(a, b, 1e-3), "%s jumps at t = %g" % (node, t))
a, b = rgb("const", 0.5 - 1e-4), rgb("const", 0.5 + 1e-4)
check(near(a, (1, 0, 0)) and near(b, (0, 1, 0)), "constant ramp is not a step at its stop")
# Range: a linear ramp never leaves the stops' convex hull (here each channel in [0, 1]).
check(all(0.0 <= c <= 1.0 for k in range(-10, 111) for c in rgb("lin", k / 100.0)),
      "linear ramp leaves the range of its stops")
finish()
