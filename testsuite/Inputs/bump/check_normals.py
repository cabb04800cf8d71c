"""check_normals.py EVAL_OUTPUT unchanged | linear A DISTANCE
texcc-eval's output for a graph whose material 0 has out0 = the hit's Normal and out1 = the
bump node's normal (linear-graph.json, constant-graph.json):
  unchanged          out1 equals out0 (a height that does not change along the surface)
  linear A DISTANCE  out1 is the analytic bump of the height A * WorldPos.x: the normal tilted
                     by DISTANCE times the height's gradient (A, 0, 0) projected onto the
                     surface, normalized (Cycles' Bump)"""
import math
import sys

rows = {}
for line in open(sys.argv[1]):
    i, m, k, *v = line.split()
    if m == "0":
        rows.setdefault(int(i), {})[int(k)] = [float(x) for x in v[:3]]
mode = sys.argv[2]
worst = 0.0
for i, out in sorted(rows.items()):
    n, b = out[0], out[1]
    if mode == "unchanged":
        want = n
    else:
        a, d = float(sys.argv[3]), float(sys.argv[4])
        g = [a, 0.0, 0.0]
        gn = sum(x * y for x, y in zip(g, n))
        t = [n[j] - d * (g[j] - gn * n[j]) for j in range(3)]
        length = math.sqrt(sum(x * x for x in t))
        want = [x / length for x in t]
    worst = max(worst, max(abs(x - y) for x, y in zip(b, want)))
print("hits %d, worst component error %.3g" % (len(rows), worst))
assert rows and worst < 2e-4, "bumped normal off by %g" % worst
print("PASS")
