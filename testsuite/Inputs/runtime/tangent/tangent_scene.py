"""The tangent tests' quad (testsuite/runtime/tangent-*.test).

    tangent_scene.py scene OUTDIR MATERIAL [--vtan rotated|none|BADLINE...] [--back] [--mirror]
        writes OUTDIR/quad.obj and OUTDIR/scene.json: the quad [-1, 1]^2 at z = 0 (normal +z)
        under a camera on +z (or -z with --back) that it fills, 16x16. --vtan rotated gives
        each corner its own vn and vtan: the tangent turned by 0, 30, 60 and 90 degrees about
        z, bitangent sign -1 (the UVs' own orientation is +1); none writes no vtan; any other
        value is a line written after the vtan (a malformed one). --mirror mirrors the UVs
        (u -> 1 - u: the orientation -1, dP/du along -x).
    tangent_scene.py check IMAGE.exr WHAT [--back] [--mirror] [--vtan rotated|none]
        compares the image of material WHAT (tangent, sign, nmap) with the values expected at
        each pixel's centre (the corners' tangents interpolated barycentrically, as Cycles
        interpolates them: not normalized): every pixel within 0.01 per channel.
"""
import json
import math
import os
import sys

import numpy as np

from texcc_tools.exr import read_exr

P = [(-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)]
ANGLES = [0.0, 30.0, 60.0, 90.0]
SIGN = -1.0
SIZE, DIST = 16, 4.0
# The camera's field of view: the film spans [-0.9, 0.9] on the quad (pixel centres inside).
FOV = 2.0 * math.degrees(math.atan(0.9 / DIST))
COLOR = np.array([0.75, 0.25, 0.9])


def uvs(mirror):
    uv = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    return [(1.0 - u, v) for u, v in uv] if mirror else uv


def tangents():
    return [(math.cos(math.radians(a)), math.sin(math.radians(a)), 0.0) for a in ANGLES]


def scene(out, material, vtan, back, mirror):
    os.makedirs(out, exist_ok=True)
    lines = ["# tangent_scene.py"]
    lines += ["v %g %g %g" % p for p in P]
    lines += ["vt %g %g" % t for t in uvs(mirror)]
    lines += ["vn 0 0 1"] * 4
    if vtan[0] != "none":
        lines += ["vtan %.9g %.9g %.9g %g" % (t + (SIGN,)) for t in tangents()]
    lines += vtan[1:] if vtan[0] == "rotated" else [l for l in vtan if l != "none"]
    lines += ["f 1/1/1 2/2/2 3/3/3", "f 1/1/1 3/3/3 4/4/4"]
    with open(os.path.join(out, "quad.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")
    z = -DIST if back else DIST
    doc = {"texrender": 1, "camera": {"position": [0, 0, z], "target": [0, 0, 0], "up": [0, 1, 0],
                                      "fov": FOV, "fovAxis": "x"},
           "film": {"width": SIZE, "height": SIZE},
           "render": {"spp": 64, "maxDepth": 1, "seed": 1}, "lights": [],
           "meshes": [{"obj": "quad.obj", "material": material}]}
    with open(os.path.join(out, "scene.json"), "w") as f:
        json.dump(doc, f)


def expected(what, back, mirror, vtan):
    """Per pixel (rows top first), the expected RGB at the pixel's centre."""
    out = np.zeros((SIZE, SIZE, 3))
    t = np.array(tangents())
    for row in range(SIZE):
        for col in range(SIZE):
            sx = ((col + 0.5) / SIZE * 2 - 1) * 0.9
            y = (1 - (row + 0.5) / SIZE * 2) * 0.9
            x = -sx if back else sx  # from -z the film's right is -x
            # Barycentrics in the triangle (1, 2, 3) or (1, 3, 4) of the quad.
            if x >= y:
                a, b, c, k = (1 - x) / 2, (x - y) / 2, (1 + y) / 2, (0, 1, 2)
            else:
                a, b, c, k = (1 - y) / 2, (1 + x) / 2, (y - x) / 2, (0, 2, 3)
            if vtan == "rotated":
                # Interpolated, not normalized (over the unit normal's length, 1 here).
                tan = a * t[k[0]] + b * t[k[1]] + c * t[k[2]]
                sign = SIGN
            else:  # dP/du of the UVs and their orientation
                tan = np.array([-1.0 if mirror else 1.0, 0.0, 0.0])
                sign = -1.0 if mirror else 1.0
            n = np.array([0.0, 0.0, 1.0])  # the side the winding faces
            if what == "tangent":
                v = 0.5 * tan + 0.5
            elif what == "sign":
                v = np.array([0.5 * sign + 0.5, 1.0 if back else 0.0, 0.0])
            else:  # Cycles' tangent-space normal map, turned on the back face
                cc = 2 * (COLOR - 0.5)
                m = cc[0] * tan + cc[1] * sign * np.cross(n, tan) + cc[2] * n
                m /= np.linalg.norm(m)
                v = 0.5 * (-m if back else m) + 0.5
            out[row, col] = v
    return out


def check(image, what, back, mirror, vtan):
    with open(image, "rb") as f:
        got = read_exr(f.read())[:, :, :3]
    want = expected(what, back, mirror, vtan)
    err = np.abs(got - want).max(axis=2)
    worst = np.unravel_index(np.argmax(err), err.shape)
    print("%s: max error %.4f at pixel %s: got %s, expected %s" % (
        what, err.max(), worst, got[worst].round(4).tolist(), want[worst].round(4).tolist()))
    if err.max() > 0.01:
        sys.exit("tangent_scene.py: %s differs by more than 0.01" % what)


def main():
    args = sys.argv[1:]
    back, mirror = "--back" in args, "--mirror" in args
    vtan = ["rotated"]
    if "--vtan" in args:
        vtan = args[args.index("--vtan") + 1:]
        vtan = [v for v in vtan if v not in ("--back", "--mirror")]
    args = [a for a in args if a not in ("--back", "--mirror")]
    if args[0] == "scene":
        scene(args[1], args[2], vtan, back, mirror)
    else:
        check(args[1], args[2], back, mirror, vtan[0])


if __name__ == "__main__":
    main()
