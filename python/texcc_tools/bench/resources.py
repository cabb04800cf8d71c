"""Figure 3: stack frame and registers of each mode's texture kernel on GPU targets, compiled
offline (no GPU needed): clang-15 -> AMDGPU gfx90a with -Rpass-analysis=kernel-resource-usage
and libclc's amdgcn--amdhsa.bc linked (without a math library every math call is an external
call and the backend assumes a 16 KiB stack), and clang-15 -> NVPTX sm_80 with libclc's
nvptx64--nvidiacl.bc linked, then ptxas -v when the CUDA toolkit's ptxas is on PATH."""
import os
import re
import shutil
import subprocess

from texcc_tools import manifest
from texcc_tools.bench import common

PAPER_STACK = {"rust": (604, 464), "scratches": (412, 336)}
GRAPHS = {"rust": "examples/rust/graph.json", "scratches": "examples/scratches/graph.json"}
CLC = ("/usr/lib/clc", "/usr/share/clc")
CLANG = "clang-15"
CL_FLAGS = ["-x", "cl", "-cl-std=CL1.2", "-D__OPENCL_VERSION__=120", "-Xclang",
            "-finclude-default-header", "-O3"]


def libclc(name):
    for folder in CLC:
        path = os.path.join(folder, name)
        if os.path.exists(path):
            return path
    raise common.BenchError("libclc %s not found in %s" % (name, " or ".join(CLC)))


def link(bc):
    return ["-Xclang", "-mlink-builtin-bitcode", "-Xclang", bc]


def amdgpu(src, work, entries):
    cmd = [CLANG] + CL_FLAGS + ["-target", "amdgcn-amd-amdhsa", "-mcpu=gfx90a", "-nogpulib",
                                "-Rpass-analysis=kernel-resource-usage", "-c", src,
                                "-o", os.path.join(work, "amdgpu.o")]
    cmd += link(libclc("amdgcn--amdhsa.bc"))
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    if r.returncode != 0:
        raise common.BenchError("AMDGPU compile failed: %s\n%s" % (" ".join(cmd), r.stderr[-2000:]))
    kernels, current = {}, None
    for line in r.stderr.splitlines():
        m = re.search(r"remark: Function Name: (\S+)", line)
        if m:
            current = m.group(1) if m.group(1) in entries else None
            if current:
                kernels[current] = {}
            continue
        m = re.search(r"remark:\s+([A-Za-z ]+?)(?: \[[^\]]*\])?: (\d+)", line)
        if m and current:
            kernels[current][m.group(1).strip()] = int(m.group(2))
    return {"command": " ".join(cmd), "kernels": kernels}


def nvptx(src, work, entries):
    ptx = os.path.join(work, "kernel.ptx")
    cmd = [CLANG] + CL_FLAGS + ["-target", "nvptx64-nvidia-cuda", "-S", src, "-o", ptx]
    cmd += link(libclc("nvptx64--nvidiacl.bc"))
    common.run(cmd)
    ptxas = shutil.which("ptxas") or ("/usr/local/cuda/bin/ptxas"
                                      if os.access("/usr/local/cuda/bin/ptxas", os.X_OK) else None)
    if ptxas is None:
        return {"command": " ".join(cmd), "ptxas": None, "kernels": {}}
    pcmd = [ptxas, "-v", "--gpu-name", "sm_80", ptx, "-o", os.path.join(work, "kernel.cubin")]
    r = subprocess.run(pcmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    if r.returncode != 0:
        raise common.BenchError("ptxas failed: %s\n%s" % (" ".join(pcmd), r.stderr[-2000:]))
    return {"command": " ".join(cmd) + " && " + " ".join(pcmd), "ptxas": ptxas,
            "kernels": parse_ptxas(r.stdout + r.stderr, entries)}


def parse_ptxas(text, entries):
    kernels, current = {}, None
    for line in text.splitlines():
        m = re.search(r"(?:Compiling entry function|Function properties for) '?([\w]+)'?", line)
        if m:
            current = m.group(1) if m.group(1) in entries else None
            if current:
                kernels.setdefault(current, {})
            continue
        if not current:
            continue
        m = re.search(r"(\d+) bytes stack frame, (\d+) bytes spill stores", line)
        if m:
            kernels[current]["stackFrame"] = int(m.group(1))
            kernels[current]["spillStores"] = int(m.group(2))
        m = re.search(r"Used (\d+) registers", line)
        if m:
            kernels[current]["registers"] = int(m.group(1))
            s = re.search(r"(\d+) bytes cumulative stack size", line)
            kernels[current]["cumulativeStack"] = int(s.group(1)) if s else None
    return kernels


def entries_of(src):
    """The texture kernels of a generated file: not shape mode's texcc_uniforms, which one
    work-item runs once per upload of args.bin (its registers do not limit the per-hit work)."""
    with open(src) as f:
        return set(re.findall(r"__kernel\s+(?:__attribute__\(\(.*?\)\)\s+)?void\s+(\w+)",
                              f.read())) - {"texcc_uniforms"}


def int_arguments(layout_path):
    """NODE.ARG of every constant int argument (the "mode" arguments: op codes, octave counts,
    switches) of the live nodes in a layout.json: what --bake is meant for."""
    layout = manifest.load(layout_path)
    types = {fn["name"]: {p["name"]: p["type"] for p in fn["params"]} for fn in layout["functions"]}
    return ["%s.%s" % (n["id"], a["name"]) for n in layout["nodes"] for a in n["args"]
            if a["source"] == "const" and types[n["fn"]].get(a["name"]) == "int"]


# (row name, texcc mode, whether the int arguments are baked)
CONFIGS = [(m, m, False) for m in common.MODES] + [("shape+bake", "shape", True)]


def measure(tools, quick):
    rows = []
    for tex, graph in GRAPHS.items():
        for name, mode, bake in CONFIGS:
            folder = os.path.join(tools.work, "res-%s-%s" % (tex, name.replace("+", "-")))
            extra = []
            if bake:
                # The int arguments of the graph, read from an unbaked compile's layout.json.
                plain = folder + "-plain"
                common.texcc(tools, os.path.join(common.ROOT, graph), plain, mode)
                for arg in int_arguments(os.path.join(plain, "layout.json")):
                    extra += ["--bake", arg]
            common.texcc(tools, os.path.join(common.ROOT, graph), folder, mode, extra)
            src = os.path.join(folder, "proctex.cl")
            entries = entries_of(src)
            common.log("resources %s %s (%d kernels)" % (tex, name, len(entries)))
            amd = amdgpu(src, folder, entries)
            nv = nvptx(src, folder, entries)
            if set(amd["kernels"]) != entries:
                raise common.BenchError("AMDGPU remarks missing for %s" % (entries - set(amd["kernels"])))
            rows.append({"texture": tex, "mode": name, "kernels": sorted(entries),
                         "baked": [extra[i + 1] for i in range(0, len(extra), 2)],
                         "amdgpu": amd["kernels"], "nvptx": nv["kernels"],
                         "ptxas": nv.get("ptxas"), "paperStack": PAPER_STACK[tex],
                         "commands": {"amdgpu": amd["command"], "nvptx": nv["command"],
                                      "texcc": " ".join(["texcc", "--mode=" + mode, "--graph",
                                                         graph] + extra)}})
    return {"rows": rows, "clang": common.run([CLANG, "--version"])[1].splitlines()[0]}
