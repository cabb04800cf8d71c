"""obj_normals.py OBJ (export-flat-normals.test): reads an OBJ the exporter wrote: per triangle, the angle between each corner's normal and the
normal of the triangle's corners (cross product, winding order)."""
import math
import sys

v, vn, worst, n = [], [], 0.0, 0
for line in open(sys.argv[1]):
    f = line.split()
    if not f:
        continue
    if f[0] == "v":
        v.append([float(x) for x in f[1:4]])
    elif f[0] == "vn":
        vn.append([float(x) for x in f[1:4]])
    elif f[0] == "f":
        corners = [c.split("/") for c in f[1:4]]
        p = [v[int(c[0]) - 1] for c in corners]
        a = [p[1][i] - p[0][i] for i in range(3)]
        b = [p[2][i] - p[0][i] for i in range(3)]
        ng = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        length = math.sqrt(sum(x * x for x in ng))
        for c in corners:
            m = vn[int(c[-1]) - 1]
            cos = sum(ng[i] * m[i] for i in range(3)) / (length * math.sqrt(sum(x * x for x in m)))
            worst = max(worst, math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
        n += 1
print("%d triangles, largest angle between a corner normal and the triangle's normal %.4f degrees"
      % (n, worst))
