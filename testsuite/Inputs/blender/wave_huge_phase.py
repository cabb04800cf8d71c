#!/usr/bin/env python3
"""wave_huge_phase.py: Blender's Wave Texture (Bands X, Sine, no distortion) at points whose
phase n is far from 0, against Cycles' own formula 0.5 + 0.5 sin(n - pi/2) in float.

    wave_huge_phase.py write SRC_ROOT DIR     writes DIR/graph.json and DIR/points.txt
    wave_huge_phase.py check POINTS VALUES    compares texcc-eval's output with the formula

n is computed here as the texture computes it, each float operation rounded to float32
(p = (x * scale + 1e-6) * 0.999999, n = p * 20). Prints one line per point range and
"wave huge phase: N of N points within 1e-4" or FAIL lines; exits 1 on a failure.
"""
import json
import math
import os
import struct
import sys

SCALE = 5.0
# |x| from 1 to 1e8 (n from 100 to 1e10), both signs, not round numbers.
XS = [s * m * (1.0 + 0.137 * k) for m in (1.0, 1e3, 1e4, 6e4, 7e4, 1e5, 1e6, 1e7, 1e8)
      for k in range(5) for s in (1.0, -1.0)]


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def expected(x):
    p = f32(f32(f32(f32(x) * f32(SCALE)) + f32(0.000001)) * f32(0.999999))
    n = f32(p * 20.0)
    return 0.5 + 0.5 * math.sin(f32(n - f32(math.pi / 2.0)))


def write(src, out):
    os.makedirs(out, exist_ok=True)
    graph = {"texcc": 1, "sources": [os.path.join(src, "textures", "blender", "noise.cl")],
             "nodes": [{"id": "w", "fn": "blWaveColor", "args": {
                 "vector": {"attr": "ObjectPos"}, "scale": SCALE, "distortion": 0.0,
                 "detail": 2.0, "detailScale": 1.0, "detailRoughness": 0.5, "phaseOffset": 0.0,
                 "waveType": 0, "direction": 0, "profile": 0}}],
             "materials": {"m": {"bsdf": "diffuse", "color": {"node": "w"}}}}
    with open(os.path.join(out, "graph.json"), "w") as f:
        json.dump(graph, f)
    with open(os.path.join(out, "points.txt"), "w") as f:
        for x in XS:
            f.write("%.9g 0.25 -0.5\n" % x)


def check(points, values):
    with open(points) as f:
        xs = [float(line.split()[0]) for line in f if line.strip()]
    with open(values) as f:
        got = [float(line.split()[3]) for line in f if line.strip()]
    if len(got) != len(xs):
        print("FAIL: %d values for %d points" % (len(got), len(xs)))
        return 1
    bad = 0
    for x, v in zip(xs, got):
        e = expected(x)
        if not abs(v - e) <= 1e-4:
            print("FAIL: x %.9g: %.9g, Cycles' formula %.9g" % (x, v, e))
            bad += 1
    print("wave huge phase: %d of %d points within 1e-4" % (len(xs) - bad, len(xs)))
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "write":
        write(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "check":
        sys.exit(check(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(__doc__)
