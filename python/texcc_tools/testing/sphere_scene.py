"""What the sphere tests' input scripts share (testsuite/Inputs/): runtime/sun-sky/sunsky.py,
runtime/principled/furnace.py, runtime/env/env.py, runtime/lamps/lamps.py and
blender-export/glossy_furnace.py write a unit sphere, a graph
and scenes into a folder (`make OUTDIR`), then read texrender's images back (`check OUTDIR`)."""
import json
import math
import os
import sys

from texcc_tools import exr


def sphere_obj(rows, cols):
    """A unit sphere at the origin, rows x cols quads, normals = positions, as OBJ text."""
    lines = []
    for i in range(rows + 1):
        t = math.pi * i / rows
        for j in range(cols + 1):
            p = 2 * math.pi * j / cols
            x, y, z = math.sin(t) * math.cos(p), math.cos(t), math.sin(t) * math.sin(p)
            lines.append("v %.6f %.6f %.6f" % (x, y, z))
            lines.append("vn %.6f %.6f %.6f" % (x, y, z))
    w = cols + 1
    for i in range(rows):
        for j in range(cols):
            a, b, c, d = i * w + j + 1, i * w + j + 2, (i + 1) * w + j + 2, (i + 1) * w + j + 1
            # counter-clockwise seen from outside
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, c, c, b, b))
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, d, d, c, c))
    return "\n".join(lines) + "\n"


def write_json(path, value, indent=None):
    with open(path, "w") as f:
        json.dump(value, f, indent=indent)


def make_folder(out, rows, cols, graph):
    """OUTDIR with sphere.obj (sphere_obj(rows, cols)) and graph.json."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "sphere.obj"), "w") as f:
        f.write(sphere_obj(rows, cols))
    write_json(os.path.join(out, "graph.json"), graph, indent=1)


def furnace_scene(material, position, fov):
    """The sphere of `material` under a uniform sky of radiance 1, seen from `position`."""
    return {"texrender": 1,
            "camera": {"position": position, "target": [0, 0, 0], "fov": fov},
            "lights": [{"type": "sky", "radiance": [1, 1, 1]}],
            "meshes": [{"obj": "sphere.obj", "material": material}]}


def read_image(path):
    """An EXR texrender wrote (texcc_tools.exr)."""
    return exr.read_file(path)


def main(commands):
    """`SCRIPT COMMAND OUTDIR`: runs commands[COMMAND](OUTDIR); its return value is the exit
    status."""
    sys.exit(commands[sys.argv[1]](sys.argv[2]))
