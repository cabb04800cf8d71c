"""swatches.py: a small rendered swatch per node function, and the node reference.

For every texture function of textures/blender/ that a conformance fixture uses
(testsuite/Inputs/blender/<variant>.json, written by scripts/blender_conformance.py), this script
takes the first fixture output that uses it (its settings are that variant's), evaluates it with
texcc's host target (texcc-eval --points --host) over a SIZE x SIZE grid on the fixtures' tilted
plane (the same plane Cycles baked, so the settings show what they were chosen for), and writes
docs/swatches/<function>.png (likewise for the old library's pattern nodes, OLD below): a scalar
output as grey, a vector as RGB, clamped to [0, 1] and sRGB-encoded. It then rewrites the node
reference in docs/textures.md between the lines "<!-- swatches:begin -->" and
"<!-- swatches:end -->".

    scripts/swatches.py [--build build] [--size 64] [--check]

--check writes nothing and exits 1 when a PNG or the reference would change (for a test).
Needs a built texcc and texcc-eval and a C++ compiler (the host target); not bpy, not OpenCL.
"""

import argparse
import glob
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib

from texcc_tools import manifest
from texcc_tools.paths import ROOT, add_build_argument
from texcc_tools.testing import compare  # the graph of fixture outputs, as the tests build it

FIXTURES = os.path.join(ROOT, "testsuite", "Inputs", "blender")
SWATCHES = os.path.join(ROOT, "docs", "swatches")
DOC = os.path.join(ROOT, "docs", "textures.md")
BEGIN, END = "<!-- swatches:begin -->", "<!-- swatches:end -->"

# The plane of scripts/blender_conformance.py: ORIGIN + u * AXIS_U + v * AXIS_V, (u, v) in [0, 1].
ORIGIN = (-1.3, -0.7, 0.2)
AXIS_U = (4.0, 0.0, 1.0)
AXIS_V = (0.0, 4.0, -1.5)

# The old library's pattern nodes over the point (textures/*.cl), at scale 1 and otherwise their
# documented defaults: (file, function, channels, arguments, signed: a [-1, 1] value shown as 0.5
# + 0.5 x). Nodes over a float2, an image or a __global array have no swatch.
OCTAVES = {"p": "P", "scale": 1.0, "octaves": 5, "lacunarity": 2.0, "gain": 0.5}
CELLS = {"p": "P", "scale": 1.0, "jitter": 1.0}
OLD = [("noise.cl", "perlin3", 1, {"p": "P", "scale": 1.0}, True),
       ("noise.cl", "fbm3", 1, OCTAVES, True),
       ("noise.cl", "turbulence3", 1, OCTAVES, False),
       ("noise.cl", "ridged3", 1, OCTAVES, False),
       ("checker.cl", "checkerMask3", 1, {"p": "P", "scale": 1.0}, False),
       ("checker.cl", "checker3", 3, {"p": "P", "scale": 1.0, "colorA": [0.8, 0.8, 0.8],
                                      "colorB": [0.2, 0.2, 0.2]}, False),
       ("voronoi.cl", "voronoiF1", 1, CELLS, False),
       ("voronoi.cl", "voronoiF2", 1, CELLS, False),
       ("voronoi.cl", "voronoiEdge", 1, CELLS, False),
       ("voronoi.cl", "voronoiCellId", 1, CELLS, False),
       ("voronoi.cl", "voronoiCellColor", 3, CELLS, False)]



def png(width, height, rows):
    """A PNG of 8-bit RGB rows (each a bytes of width * 3)."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\0" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def srgb(x):
    if not math.isfinite(x):
        return 0
    x = min(max(x, 0.0), 1.0)
    x = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(round(255 * x))


def chosen_fixtures():
    """One (fixture, output) per function: the first fixture, by name, whose output uses it."""
    seen, chosen = set(), []
    for path in sorted(glob.glob(os.path.join(FIXTURES, "*.json"))):
        with open(path) as f:
            fx = json.load(f)
        outputs = [o for o in fx["outputs"] if o["fn"] not in seen]
        if not outputs:
            continue
        seen.update(o["fn"] for o in outputs)
        chosen.append(dict(fx, outputs=outputs))
    return chosen


def old_fixtures():
    """The OLD nodes as fixture-shaped entries for compare.build_graph (sources relative to
    textures/blender/)."""
    return [{"variant": "old-" + fn, "source": os.path.join("..", source), "args": args,
             "outputs": [{"socket": "Value" if channels == 1 else "Color", "fn": fn,
                          "channels": channels, "signed": signed}]}
            for source, fn, channels, args, signed in OLD]


def evaluate(build, fixtures, size, work):
    graph, outputs = compare.build_graph(fixtures, ROOT)
    graph_path = os.path.join(work, "graph.json")
    with open(graph_path, "w") as f:
        json.dump(graph, f)
    out_dir = os.path.join(work, "out")
    subprocess.run([os.path.join(build, "bin", "texcc"), "--graph", graph_path, "-o", out_dir,
                    "--target=host"], check=True)
    index = {m["name"]: m["index"] for m in manifest.load(out_dir)["materials"]}
    points = [tuple(ORIGIN[k] + (i + 0.5) / size * AXIS_U[k] + (j + 0.5) / size * AXIS_V[k]
                    for k in range(3)) for j in range(size) for i in range(size)]
    args = type("Args", (), {"eval": os.path.join(build, "bin", "texcc-eval")})
    values = compare.evaluate(args, out_dir, True, points, work, "swatch")
    return [(fx, out, [values[p][index[m]] for p in range(len(points))])
            for fx, out, m in outputs]


def reference(rows, old_rows):
    lines = [BEGIN, "",
             "Generated by `scripts/swatches.py` (do not edit between the markers): each "
             "swatch is",
             "the function evaluated by texcc's host target over the conformance fixtures' "
             "tilted",
             "plane (x from -1.3 to 2.7, y from -0.7 to 3.3), with the settings of the variant "
             "named",
             "(`testsuite/Inputs/blender/<variant>.json`); scalars are grey, vectors RGB, "
             "clamped to",
             "[0, 1] and sRGB-encoded.", "",
             "| swatch | function | output | variant |", "|---|---|---|---|"]
    for fx, out in rows:
        lines.append("| ![%s](swatches/%s.png) | `%s` | %s | %s |" % (
            out["fn"], out["fn"], out["fn"], out["socket"], fx["variant"]))
    lines += ["", "The old library's pattern nodes over the same plane at scale 1 (jitter 1, "
              "5 octaves,",
              "lacunarity 2, gain 0.5; checker colours 0.8 and 0.2); a value in [-1, 1] is "
              "shown as",
              "0.5 + 0.5 x:", "",
              "| swatch | function | file |", "|---|---|---|"]
    for fx, out in old_rows:
        lines.append("| ![%s](swatches/%s.png) | `%s` | `%s` |" % (
            out["fn"], out["fn"], out["fn"], fx["source"][3:]))
    lines += ["", END]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    add_build_argument(ap)
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    fixtures = chosen_fixtures() + old_fixtures()
    with tempfile.TemporaryDirectory() as work:
        results = evaluate(args.build, fixtures, args.size, work)
    changed, total = [], 0
    os.makedirs(SWATCHES, exist_ok=True)
    for fx, out, values in results:
        channels = out["channels"]
        rows = []
        for j in reversed(range(args.size)):  # v up
            row = bytearray()
            for i in range(args.size):
                v = values[j * args.size + i]
                rgb = (v[0], v[0], v[0]) if channels == 1 else v[:3]
                if out.get("signed"):
                    rgb = [0.5 + 0.5 * c for c in rgb]
                row += bytes(srgb(c) for c in rgb)
            rows.append(bytes(row))
        data = png(args.size, args.size, rows)
        total += len(data)
        path = os.path.join(SWATCHES, out["fn"] + ".png")
        old = open(path, "rb").read() if os.path.exists(path) else None
        if old != data:
            changed.append(path)
            if not args.check:
                with open(path, "wb") as f:
                    f.write(data)
    with open(DOC) as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc:
        sys.exit("swatches.py: %s has no %s ... %s section" % (DOC, BEGIN, END))
    new_doc = doc[:doc.index(BEGIN)] + reference(
        [(fx, out) for fx, out, _ in results if not fx["variant"].startswith("old-")],
        [(fx, out) for fx, out, _ in results if fx["variant"].startswith("old-")]) + \
        doc[doc.index(END) + len(END):]
    if new_doc != doc:
        changed.append(DOC)
        if not args.check:
            with open(DOC, "w") as f:
                f.write(new_doc)
    print("swatches.py: %d swatches, %.0f KB of PNG, %d file(s) %s" % (
        len(results), total / 1024.0, len(changed),
        "differ" if args.check else "written"))
    for path in changed:
        print("  " + os.path.relpath(path, ROOT))
    sys.exit(1 if args.check and changed else 0)


if __name__ == "__main__":
    main()
