"""compare.py: texcc's Blender nodes (textures/blender/) against the Cycles fixtures.

Each fixture (written by scripts/blender_conformance.py) holds one node variant: the texcc
function and arguments of each output and the values Cycles baked at the points of points.txt.
This script puts every output of the given fixtures in one graph (one material per output),
compiles it with texcc, evaluates it at exactly those points with texcc-eval (on the OpenCL
device, or with --host through the host target's C++), and compares per output channel.

Points near a discontinuity are found without looking at the error: texcc's own value at the
point is compared with its values at the six points +-H along each axis (H = 1e-5), all on the
target under test (one texcc-eval run evaluates the points and their neighbours); a jump above
JUMP (0.01) means a discontinuity (a Voronoi cell border, a Constant ramp step, a floor) lies
within H, where a float rounding in either renderer may pick the other
side. Such points are counted and reported separately ("near a discontinuity"), never dropped
silently: each must equal Cycles within --tol at the point or at one of its six neighbours
(Cycles took the other side; a steep but wrong texcc value fails here), and their error is
reported too. Every other point must be within --tol of Cycles.

    compare.py --texcc T --eval E --src ROOT --work DIR [--host] [--tol 1e-4]
               [--cl-options STR] [--rows FILE.json] FIXTURE.json ...

Prints one line per (variant, output) and exits 1 if any misses the tolerance.
"""

import argparse
import base64
import json
import math
import os
import struct
import subprocess
import sys

from texcc_tools import manifest

H = 1e-5
JUMP = 0.01
NEAR_ZERO = 1e-6


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("command failed (%d): %s\n%s%s" % (r.returncode, " ".join(cmd), r.stdout,
                                                    r.stderr))
    return r.stdout


def decode(text, channels):
    raw = base64.b64decode(text)
    flat = struct.unpack("<%df" % (len(raw) // 4), raw)
    return [flat[i:i + channels] for i in range(0, len(flat), channels)]


def read_points(path):
    with open(path) as f:
        return [tuple(float(x) for x in line.split()) for line in f if line.strip()]


def graph_arg(value, extra):
    """A fixture argument as a graph.json argument: "P" is the shading point, "P.x" one of its
    coordinates (Separate XYZ), "P.x*S+O" that coordinate through Math Multiply Add; the nodes
    these need are added to extra."""
    if value == "P":
        return {"attr": "ObjectPos"}
    if isinstance(value, str) and value.startswith("P*"):
        scale, offset = (float(t) for t in value[2:].split("+"))
        node_id = "affine_p_%d" % len(extra)
        extra.append({"id": node_id, "fn": "blVectorMath",
                      "args": {"a": {"attr": "ObjectPos"}, "b": [scale] * 3, "c": [offset] * 3,
                               "scale": 1.0, "operation": 26}})
        return {"node": node_id}
    if not (isinstance(value, str) and value.startswith("P.")):
        return value
    component = "position_" + value[2]
    if "*" not in value:
        return {"node": component}
    scale, offset = (float(t) for t in value[4:].split("+"))
    node_id = "affine_%s_%d" % (value[2], len(extra))
    extra.append({"id": node_id, "fn": "blMath",
                  "args": {"a": {"node": component}, "b": scale, "c": offset, "operation": 36,
                           "useClamp": 0}})
    return {"node": node_id}


def srgb_to_linear(v):
    """texrender's loader (runtime/lib/Image.cpp srgbToLinear), in float32."""
    v = struct.unpack("<f", struct.pack("<f", v))[0]
    if v <= 0.04045:
        return v / 12.92
    return ((v + 0.055) / 1.055) ** 2.4


def image_texels(image, path):
    """A fixture's image as texcc-eval's --texels file: the linear RGBA texels texrender's loader
    makes of the values Blender holds (sRGB colour decoded; rows top first, Blender's bottom
    first) and the flags texrender gives it (TEXCC_IMAGE_SRGB 1, _DATA 2, _BYTES 4, _SHORTS 8:
    runtime/lib/Renderer.cpp)."""
    w, h = image["width"], image["height"]
    stored = decode(image["pixels"], 4)
    srgb = image["colorspace"] == "sRGB"
    bits = 32 if image["float"] else image.get("bits", 8)
    flags = (2 if image["colorspace"] == "Non-Color" else 0) | (1 if srgb else 0) | \
        {8: 4, 16: 8}.get(bits, 0)
    lines = ["%d %d %d" % (w, h, flags)]
    for row in range(h - 1, -1, -1):
        for x in range(w):
            t = stored[row * w + x]
            rgb = [srgb_to_linear(c) if srgb else c for c in t[:3]]
            lines.append("%.9g %.9g %.9g %.9g" % tuple(rgb + [t[3]]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def build_graph(fixtures, src, work):
    lib = os.path.join(src, "textures", "blender")
    sources, nodes, materials, outputs = [], [], {}, []
    uses_components, uses_vectors, extra = False, False, []
    images, texels = {}, []
    for fx in fixtures:
        path = os.path.join(lib, fx["source"])
        if path not in sources:
            sources.append(path)
        args = {k: graph_arg(v, extra) for k, v in fx["args"].items()}
        if "image" in fx:  # "IMAGE": the fixture's own image, its texels through --texels
            name = "image_%d" % len(images)
            images[name] = {"path": name + ".png", "colorspace": fx["image"]["colorspace"]}
            texels.append(os.path.join(work, name + ".txt"))
            image_texels(fx["image"], texels[-1])
            args = {k: {"image": name} if v == "IMAGE" else a
                    for (k, v), a in zip(fx["args"].items(), args.values())}
        uses_components |= any(isinstance(v, str) and v.startswith("P.")
                               for v in fx["args"].values())
        uses_vectors |= any(isinstance(v, str) and v.startswith("P*")
                            for v in fx["args"].values())
        for out in fx["outputs"]:
            node_id = "%s_%s" % (fx["variant"].replace("-", "_"), out["socket"].lower())
            nodes.append({"id": node_id, "fn": out["fn"],
                          "args": {k: v for k, v in args.items() if k not in out.get("drop", [])}})
            materials["m_" + node_id] = {"bsdf": "diffuse", "color": {"node": node_id}}
            outputs.append((fx, out, "m_" + node_id))
    helpers = (["converter.cl"] if uses_components else []) + \
        (["math.cl"] if any(n["fn"] == "blMath" for n in extra) else []) + \
        (["vector_math.cl"] if uses_vectors else [])
    for helper in helpers:
        if os.path.join(lib, helper) not in sources:
            sources.append(os.path.join(lib, helper))
    nodes += extra
    if uses_components:
        for axis in "xyz":
            nodes.append({"id": "position_" + axis, "fn": "blSeparateXYZ" + axis.upper(),
                          "args": {"vector": {"attr": "ObjectPos"}}})
    graph = {"texcc": 1, "sources": sources, "nodes": nodes, "materials": materials}
    if images:
        graph["images"] = images
    return graph, outputs, texels


def compile_graph(args, graph_path, host):
    out_dir = os.path.join(args.work, "out-host" if host else "out")
    run([args.texcc, "--graph", graph_path, "-o", out_dir] + (["--target=host"] if host else []))
    return out_dir, {m["name"]: m["index"] for m in manifest.load(out_dir)["materials"]}


def evaluate(args, out_dir, host, points, work, tag, texels=()):
    """texcc's values at points: a list, per point, of a list, per material, of (x, y, z)."""
    path = os.path.join(work, "points-%s.txt" % tag)
    with open(path, "w") as f:
        f.write("".join("%.9g %.9g %.9g\n" % p for p in points))
    cmd = [args.eval, out_dir, "--points", path] + (["--host"] if host else [])
    if args.cl_options:
        cmd += ["--cl-options", args.cl_options]
    for t in texels:
        cmd += ["--texels", t]
    values = [[] for _ in points]
    # One line per (point, material, output), in that order; every material here has one
    # output (k = 0), so a point's materials come in index order.
    for line in run(cmd).splitlines():
        hit, mat, k, x, y, z, _ = line.split()
        if k == "0":
            row = values[int(hit)]
            if len(row) != int(mat):
                sys.exit("texcc-eval: unexpected output order at %r" % line)
            row.append((float(x), float(y), float(z)))
    return values


def neighbours(p):
    for axis in range(3):
        for sign in (-1.0, 1.0):
            q = list(p)
            q[axis] += sign * H
            yield tuple(q)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--texcc", required=True)
    ap.add_argument("--eval", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--host", action="store_true")
    ap.add_argument("--cl-options", default="",
                    help="texcc-eval's --cl-options: extra options of the device build")
    ap.add_argument("--tol", type=float, default=1e-4)
    ap.add_argument("--rows", help="write the per-output results (JSON) here")
    ap.add_argument("fixtures", nargs="+")
    args = ap.parse_args()

    fixtures = []
    for path in args.fixtures:
        with open(path) as f:
            fixtures.append(json.load(f))
    points = read_points(os.path.join(os.path.dirname(os.path.abspath(args.fixtures[0])),
                                      fixtures[0]["points"]))
    os.makedirs(args.work, exist_ok=True)
    graph, outputs, texels = build_graph(fixtures, args.src, args.work)
    graph_path = os.path.join(args.work, "graph.json")
    with open(graph_path, "w") as f:
        json.dump(graph, f, indent=1)
    # The target under test evaluates the points and their neighbours, in one texcc-eval run:
    # the host target compiles proctex.cpp once, the device builds proctex.cl once (on PoCL,
    # the seven evaluations per point cost less than compiling and running the host target
    # beside it: 4 s against 17 s for the 52 Voronoi outputs).
    near = [p for pt in points for p in neighbours(pt)]
    out_dir, material_index = compile_graph(args, graph_path, args.host)
    both = evaluate(args, out_dir, args.host, points + near, args.work, "points", texels)
    values, near_values = both[:len(points)], both[len(points):]

    failures, rows = 0, []
    for fx, out, material in outputs:
        m = material_index[material]
        golden = decode(out["values"], out["channels"])
        errors, jumps, worst, unmatched, worst_near = [], 0, None, 0, None
        max_smooth = max_near = 0.0
        for i, p in enumerate(points):
            got = values[i][m][:out["channels"]]
            want = golden[i]
            err = max(abs(a - b) if math.isfinite(a) and math.isfinite(b) else
                      (0.0 if a == b else math.inf) for a, b in zip(got, want))
            jump = max(abs(near_values[6 * i + j][m][c] - values[i][m][c])
                       for j in range(6) for c in range(out["channels"]))
            errors.append(err)
            if not jump <= JUMP:
                # Near a discontinuity Cycles may be on the other side: it must then equal
                # texcc's value there (at one of the six neighbours), else the point fails.
                jumps += 1
                max_near = max(max_near, err)
                side = min([err] + [max(abs(near_values[6 * i + j][m][c] - want[c])
                                        for c in range(out["channels"])) for j in range(6)])
                if not side <= args.tol:
                    unmatched += 1
                    if worst_near is None or side > worst_near[0]:
                        worst_near = (side, i, got, want)
            else:
                if worst is None or err > worst[0]:
                    worst = (err, i, got, want)
                max_smooth = max(max_smooth, err)
        mean = sum(errors) / len(errors)
        within = sum(1 for e in errors if e <= NEAR_ZERO) / len(errors)
        ok = max_smooth <= args.tol and unmatched == 0
        failures += not ok
        name = "%s %s" % (fx["variant"], out["socket"])
        print("%s: %s: %d points (%d near a discontinuity, %d of them matching neither side): "
              "max abs error %.3g (near a discontinuity %.3g), mean %.3g, within 1e-6 %.1f%%" %
              ("OK" if ok else "FAIL", name, len(points), jumps, unmatched, max_smooth, max_near,
               mean, 100.0 * within))
        for label, w in (("worst", worst), ("worst near a discontinuity", worst_near)):
            if not ok and w:
                print("  %s at point %d %s: texcc %s, Cycles %s" %
                      (label, w[1], points[w[1]], w[2], w[3]))
        rows.append((fx, out, len(points), jumps, max_smooth, max_near, mean, within, worst, ok,
                     unmatched))
    if args.rows:
        write_rows(args.rows, rows, points, args.host)
    print("blender conformance: %d of %d outputs within %g of Cycles" %
          (len(outputs) - failures, len(outputs), args.tol))
    sys.exit(1 if failures else 0)


def write_rows(path, rows, points, host):
    """The per-output results as JSON, for scripts/blender_report.py."""
    out = []
    for fx, output, n, jumps, max_smooth, max_near, mean, within, worst, ok, unmatched in rows:
        out.append({"variant": fx["variant"], "output": output["socket"], "node": fx["node"],
                    "blender": fx["blender"], "target": "host" if host else "opencl",
                    "points": n, "near_discontinuity": jumps,
                    "near_discontinuity_matching_neither_side": unmatched,
                    "max_abs_error": max_smooth,
                    "max_abs_error_near_discontinuity": max_near, "mean_abs_error": mean,
                    "within_1e-6": within, "met": ok,
                    "worst": None if worst is None else
                    {"index": worst[1], "position": list(points[worst[1]]),
                     "texcc": list(worst[2]), "cycles": list(worst[3])}})
    with open(path, "w") as f:
        json.dump(out, f, indent=1)

