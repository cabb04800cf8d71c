"""check_normals.py EVAL_OUTPUT unchanged | linear A DISTANCE
texcc-eval's output for a graph whose material 0 has out0 = the hit's Normal and out1 = the
bump node's normal (linear-graph.json, constant-graph.json), and whose material 1 (if any) has
out0 = the hit's GeomNormal:
  unchanged          out1 equals out0 (a height that does not change along the surface)
  linear A DISTANCE  out1 is the analytic bump of the height A * WorldPos.x as Cycles' Bump
                     forms it: its finite differences are taken across the geometric normal Ng,
                     so they see the gradient g = (A, 0, 0) projected onto that plane, gp; the
                     normal N tilts by DISTANCE times w, gp moved along Ng into the plane across
                     N (w = gp - (gp.N / N.Ng) Ng), normalized: N - DISTANCE w. Where Ng = N
                     that is the gradient projected onto the surface."""
import math
import sys


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


rows, geom = {}, {}
for line in open(sys.argv[1]):
    i, m, k, *v = line.split()
    if m == "0":
        rows.setdefault(int(i), {})[int(k)] = [float(x) for x in v[:3]]
    elif m == "1" and k == "0":
        geom[int(i)] = [float(x) for x in v[:3]]
mode = sys.argv[2]
worst = 0.0
for i, out in sorted(rows.items()):
    n, b = out[0], out[1]
    if mode == "unchanged":
        want = n
    else:
        a, d = float(sys.argv[3]), float(sys.argv[4])
        ng = geom[i]
        g = [a, 0.0, 0.0]
        gp = [g[j] - dot(g, ng) * ng[j] for j in range(3)]
        w = [gp[j] - dot(gp, n) / dot(n, ng) * ng[j] for j in range(3)]
        t = [n[j] - d * w[j] for j in range(3)]
        length = math.sqrt(dot(t, t))
        want = [x / length for x in t]
    worst = max(worst, max(abs(x - y) for x, y in zip(b, want)))
print("hits %d, worst component error %.3g" % (len(rows), worst))
assert rows and worst < 2e-4, "bumped normal off by %g" % worst
print("PASS")
