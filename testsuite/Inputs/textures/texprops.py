"""texprops.py: evaluate texture-library nodes through texcc's host target, for property tests.

A test script describes the nodes it wants (function, arguments) in a small graph; this module
writes graph.json (one material per node, the node as its diffuse colour), runs
`texcc --target=host`, compiles the generated proctex.cpp into a shared library, and calls its
extern "C" entry texcc_host_evaluate at hits whose attributes the test chooses. The values are
texcc's own (the same renamed, lowered user code as every device mode), so the properties hold
for what the renderer runs, not for a re-implementation.

Usage inside a test script:

    from texprops import Oracle, check, main_args
    args = main_args()
    o = Oracle(args, "noise", sources=["noise.cl"], nodes={
        "p3": ("perlin3", {"p": {"attr": "ObjectPos"}, "scale": 1.0}),
    })
    v = o.eval("p3", pos=(0.5, 0.25, 0.0))[0]
    check(abs(v) <= 1.0, "perlin3 out of range: %g" % v)

Scripts exit 0 when every check passes and print one line per failed check otherwise.
"""

import argparse
import ctypes
import json
import os
import subprocess
import sys

from texcc_tools import manifest

FAILURES = []


def main_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--compiler", required=True, help="the texcc binary")
    ap.add_argument("--cxx", required=True, help="a C++ compiler (clang-15 or g++)")
    ap.add_argument("--src", required=True, help="the repository root")
    ap.add_argument("--work", required=True, help="a scratch folder (lit's %%t)")
    return ap.parse_args()


def check(cond, message):
    if not cond:
        FAILURES.append(message)
        print("FAIL: " + message)
    return cond


def finish():
    if FAILURES:
        print("%d property check(s) failed" % len(FAILURES))
        sys.exit(1)
    print("all property checks passed")
    sys.exit(0)


class Float4(ctypes.Structure):
    _fields_ = [("s", ctypes.c_float * 4)]


class HitAttrs(ctypes.Structure):
    # kernels/common/texcc_abi.h TexccHitAttrs
    _fields_ = [("worldPos", Float4), ("objectPos", Float4), ("normal", Float4),
                ("geomNormal", Float4), ("tangent", Float4), ("viewDir", Float4),
                ("uvAO", Float4)]


class Settings(ctypes.Structure):
    _fields_ = [("cameraPos", Float4), ("time", ctypes.c_float), ("frame", ctypes.c_int),
                ("pad0", ctypes.c_int), ("pad1", ctypes.c_int)]


class ImageInfo(ctypes.Structure):
    _fields_ = [("offset", ctypes.c_int), ("width", ctypes.c_int), ("height", ctypes.c_int),
                ("pad", ctypes.c_int)]


def _f4(v):
    f = Float4()
    for i, x in enumerate(list(v)[:4]):
        f.s[i] = float(x)
    return f


class Oracle:
    """One compiled graph and its host evaluator."""

    def __init__(self, args, name, sources, nodes, images=None):
        self.work = os.path.join(args.work, name)
        os.makedirs(self.work, exist_ok=True)
        lib_dir = os.path.join(args.src, "textures")
        srcs = [s if os.path.isabs(s) else os.path.join(lib_dir, s) for s in sources]
        graph = {"texcc": 1, "sources": srcs, "nodes": [], "materials": {}}
        if images:
            graph["images"] = {k: os.path.join(args.src, v) for k, v in images.items()}
        for node_id, (fn, fn_args) in nodes.items():
            graph["nodes"].append({"id": node_id, "fn": fn, "args": fn_args})
            graph["materials"]["m_" + node_id] = {"bsdf": "diffuse", "color": {"node": node_id}}
        graph_path = os.path.join(self.work, "graph.json")
        with open(graph_path, "w") as f:
            json.dump(graph, f, indent=1)
        out = os.path.join(self.work, "out")
        run([args.compiler, "--target=host", "--graph", graph_path, "-o", out])
        lib = os.path.join(self.work, "proctex.so")
        run([args.cxx, "-x", "c++", "-std=c++17", "-O1", "-fPIC", "-shared", "-w",
             "-I", os.path.join(args.src, "kernels", "common"),
             os.path.join(out, "proctex.cpp"), "-o", lib, "-lstdc++", "-lm"])
        self.layout = manifest.load(out)
        self.material = {m["name"]: m["index"] for m in self.layout["materials"]}
        self.lib = ctypes.CDLL(lib)
        self.fn = self.lib.texcc_host_evaluate
        self.fn.restype = ctypes.c_int
        self.fn.argtypes = [ctypes.c_int, ctypes.POINTER(HitAttrs), ctypes.POINTER(Settings),
                            ctypes.POINTER(Float4), ctypes.POINTER(ImageInfo),
                            ctypes.POINTER(ctypes.c_float)]
        self.settings = Settings()
        self.outputs = (ctypes.c_float * 64)()
        self.set_images([])

    def set_images(self, images):
        """images: [(width, height, [(r, g, b, a), ...] row-major, row 0 first)], in the
        graph's image order (layout.json "images" index)."""
        texels, infos = [], []
        for w, h, px in images:
            infos.append((len(texels), w, h))
            texels += px
        self.texels = (Float4 * max(1, len(texels)))()
        for i, t in enumerate(texels):
            self.texels[i] = _f4(t)
        self.images = (ImageInfo * max(1, len(infos)))()
        for i, (off, w, h) in enumerate(infos):
            self.images[i].offset, self.images[i].width, self.images[i].height = off, w, h

    def image_index(self, name):
        for im in self.layout.get("images", []):
            if im["name"] == name:
                return im["index"]
        raise KeyError(name)

    def eval(self, node_id, pos=(0.0, 0.0, 0.0), uv=(0.0, 0.0), ao=1.0, normal=(0.0, 1.0, 0.0),
             world=None):
        """The node's value (4 floats; a float in [0]) at a hit with these attributes."""
        hit = HitAttrs()
        hit.objectPos = _f4(tuple(pos) + (1.0,))
        hit.worldPos = _f4(tuple(world if world is not None else pos) + (1.0,))
        hit.normal = _f4(tuple(normal) + (0.0,))
        hit.geomNormal = _f4(tuple(normal) + (0.0,))
        hit.uvAO = _f4((uv[0], uv[1], ao, 0.0))
        n = self.fn(self.material["m_" + node_id], ctypes.byref(hit), ctypes.byref(self.settings),
                    self.texels, self.images, self.outputs)
        if n < 1:
            raise RuntimeError("texcc_host_evaluate returned %d for node %s" % (n, node_id))
        return tuple(self.outputs[i] for i in range(4))

    def scalar(self, node_id, **kw):
        return self.eval(node_id, **kw)[0]


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        print("command failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stdout))
        sys.exit(2)


def lcg_points(count, lo, hi, seed=12345, dims=3):
    """Deterministic pseudo-random points in [lo, hi)^dims (no random module state)."""
    state = seed & 0xFFFFFFFF
    pts = []
    for _ in range(count):
        p = []
        for _ in range(dims):
            state = (state * 1664525 + 1013904223) & 0xFFFFFFFF
            p.append(lo + (hi - lo) * (state >> 8) / float(1 << 24))
        pts.append(tuple(p))
    return pts
