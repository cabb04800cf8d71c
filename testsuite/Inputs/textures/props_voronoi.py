"""Defining properties of textures/voronoi.cl, evaluated through texcc's host target."""
import math

from texprops import Oracle, check, finish, lcg_points, main_args

P = {"attr": "ObjectPos"}
nodes = {}
for jit, tag in ((1.0, ""), (0.0, "0")):
    for fn in ("voronoiF1", "voronoiF2", "voronoiEdge", "voronoiCellId", "voronoiCellColor"):
        nodes[fn + tag] = (fn, {"p": P, "scale": 1.0, "jitter": jit})
nodes["f1s"] = ("voronoiF1", {"p": P, "scale": 3.0, "jitter": 1.0})
o = Oracle(main_args(), "voronoi", ["voronoi.cl"], nodes)
pts = lcg_points(600, -30.0, 30.0)

# Order and ranges: 0 <= F1 <= F2, F1 <= sqrt(3), F2 <= sqrt(6), edge = F2 - F1.
for p in pts:
    f1, f2, e = o.scalar("voronoiF1", pos=p), o.scalar("voronoiF2", pos=p), o.scalar("voronoiEdge", pos=p)
    check(0.0 <= f1 <= f2, "not 0 <= F1 <= F2 at %s: %g %g" % (p, f1, f2))
    check(f1 <= math.sqrt(3) + 1e-5 and f2 <= math.sqrt(6) + 1e-5, "F1/F2 beyond their bounds at %s" % (p,))
    check(abs(e - (f2 - f1)) < 1e-5, "voronoiEdge != F2 - F1 at %s" % (p,))
    cid = o.scalar("voronoiCellId", pos=p)
    check(0.0 <= cid < 1.0, "voronoiCellId %g outside [0, 1)" % cid)
    col = o.eval("voronoiCellColor", pos=p)[:3]
    check(all(0.0 <= c < 1.0 for c in col), "voronoiCellColor outside [0, 1)^3")

# F1 is a distance field: 1-Lipschitz in scaled units, hence continuous across cell borders.
for (x, y, z), q in zip(pts[:300], lcg_points(300, -0.05, 0.05, seed=99)):
    a = (x, y, z)
    b = (x + q[0], y + q[1], z + q[2])
    d = math.sqrt(sum(c * c for c in q))
    check(abs(o.scalar("voronoiF1", pos=a) - o.scalar("voronoiF1", pos=b)) <= d + 1e-5,
          "F1 is not 1-Lipschitz between %s and %s" % (a, b))
    check(abs(o.scalar("f1s", pos=a) - o.scalar("f1s", pos=b)) <= 3.0 * d + 1e-5,
          "F1 at scale 3 is not 3-Lipschitz")
for x, y, z in pts[:100]:
    k = float(round(x))
    check(abs(o.scalar("voronoiF1", pos=(k - 1e-4, y, z)) - o.scalar("voronoiF1", pos=(k + 1e-4, y, z))) < 1e-3,
          "F1 jumps across the cell border x = %g" % k)

# Known values with jitter 0: the feature points are the cell centres, so F1 is the distance to
# the own cell's centre, F2 (for a point inside the central half of its cell) the distance to
# the nearest face neighbour's centre, the edge 0 on a cell face, and the cell id constant over
# the cube.
for x, y, z in pts[:300]:
    fr = [c - math.floor(c) - 0.5 for c in (x, y, z)]
    f1 = math.sqrt(sum(c * c for c in fr))
    check(abs(o.scalar("voronoiF10", pos=(x, y, z)) - f1) < 1e-4, "jitter 0: F1 at %s" % ((x, y, z),))
    i = max(range(3), key=lambda k: abs(fr[k]))
    f2 = math.sqrt(sum(c * c for c in fr) - fr[i] ** 2 + (1.0 - abs(fr[i])) ** 2)
    check(abs(o.scalar("voronoiF20", pos=(x, y, z)) - f2) < 1e-4, "jitter 0: F2 at %s" % ((x, y, z),))
for x, y, z in pts[:100]:
    k = float(math.floor(x))
    fy, fz = y - math.floor(y), z - math.floor(z)
    if 0.2 < fy < 0.8 and 0.2 < fz < 0.8:
        check(o.scalar("voronoiEdge0", pos=(k, y, z)) < 1e-3, "jitter 0: edge not 0 on the face x = %g" % k)
    base = (math.floor(x), math.floor(y), math.floor(z))
    ids = {o.scalar("voronoiCellId0", pos=(base[0] + a, base[1] + b, base[2] + c))
           for a, b, c in lcg_points(6, 0.05, 0.95, seed=int(abs(x) * 1000))}
    check(len(ids) == 1, "jitter 0: cell id varies inside the cube at %s" % (base,))
# Neighbouring cells differ (a 24-bit hash; equal ids would be a hash collision).
same = sum(o.scalar("voronoiCellId0", pos=(math.floor(x) + 0.5, y, z)) ==
           o.scalar("voronoiCellId0", pos=(math.floor(x) + 1.5, y, z)) for x, y, z in pts[:100])
check(same <= 1, "%d of 100 neighbouring cells share an id" % same)
finish()
