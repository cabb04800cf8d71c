"""The scene of trace-wide-bvh.test: the Cornell box's walls and light around a bumpy sphere of
32768 triangles and 2000 scattered small ones (a BVH several levels deep).
usage: make_scene.py OUT_DIR CORNELL_DIR (writes OUT_DIR/dense.obj and OUT_DIR/scene.json)"""
import json, math, os, random, sys

out = sys.argv[1]
box = sys.argv[2]
rng = random.Random(7)
lines = []
# A bumpy sphere: 128 x 128 quads (32768 triangles), radius varying with position.
cx, cy, cz, r = 0.0, -0.45, 0.1, 0.4
nu, nv = 128, 128
for j in range(nv + 1):
    th = math.pi * j / nv
    for i in range(nu):
        ph = 2 * math.pi * i / nu
        rr = r * (1 + 0.08 * math.sin(7 * ph) * math.sin(5 * th) + 0.02 * rng.random())
        lines.append("v %f %f %f" % (cx + rr * math.sin(th) * math.cos(ph), cy + rr * math.cos(th),
                                     cz + rr * math.sin(th) * math.sin(ph)))
for j in range(nv):
    for i in range(nu):
        a = j * nu + i + 1
        b = j * nu + (i + 1) % nu + 1
        c, d = a + nu, b + nu
        lines.append("f %d %d %d" % (a, c, b))
        lines.append("f %d %d %d" % (b, c, d))
# 2000 small triangles scattered in the upper half of the box.
base = (nv + 1) * nu
for k in range(2000):
    p = [rng.uniform(-0.9, 0.9), rng.uniform(0.0, 0.9), rng.uniform(-0.9, 0.9)]
    for _ in range(3):
        lines.append("v %f %f %f" % tuple(x + rng.uniform(-0.04, 0.04) for x in p))
    lines.append("f %d %d %d" % (base + 3 * k + 1, base + 3 * k + 2, base + 3 * k + 3))
with open(os.path.join(out, "dense.obj"), "w") as f:
    f.write("\n".join(lines) + "\n")
# The Cornell box's walls and light (no boxes) around them.
scene = {"texrender": 1,
         "camera": {"position": [0, 0, 3.9], "target": [0, 0, 2.9], "up": [0, 1, 0],
                    "fov": 39.3077, "fovAxis": "smaller"},
         "film": {"width": 32, "height": 32},
         "render": {"spp": 16, "maxDepth": 4, "seed": 1},
         "lights": [],
         "meshes": [{"obj": os.path.join(box, n + ".obj"), "material": "white"}
                    for n in ("floor", "ceiling", "back", "green-wall", "red-wall")]}
scene["meshes"].append({"obj": os.path.join(box, "light.obj"), "material": "white",
                        "emission": [18.387, 13.9873, 6.75357]})
scene["meshes"].append({"obj": "dense.obj", "material": "tex"})
with open(os.path.join(out, "scene.json"), "w") as f:
    json.dump(scene, f, indent=1)
