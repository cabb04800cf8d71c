"""Figure 3b: where interp's value stack lives on a GPU. texcc's
interp kernel (here with --max-quickened=0: no quickened opcodes, whose cases the register
rewrites below would have to rewrite too) keeps it in a private array `float4 stack[TEXCC_STACK_SLOTS]` indexed by slot
numbers read from args.bin ("array"); a GPU cannot index registers by a per-lane value, so the
array goes to scratch memory. (Until 2026-12 texcc could make it a __local array of the
work-group, "local" in bench/results/value_stack.json; removed, bench/refactor-20.md.) This
figure also rewrites the private kernel of rust and scratches two ways that keep the slots in
registers, and compiles all four for gfx90a (bench/resources.py's command): "registers",
one float4 variable per slot, read through a chain of selects and written through an if chain;
"soa", four float arrays (x, y, z, w), which LLVM's AMDGPU alloca promotion turns into
registers. The rewrites are textual, on the kernel texcc writes today (they fail loudly when
its text changes); they are measurements, not a texcc mode. Occupancy: the compiler's remark,
and the bound that local memory puts on it, computed (not measured on a GPU): gfx90a has 64 KiB
of LDS per compute unit and 4 SIMDs, and a work-group of 64 is one wave, so at most
floor(floor(65536 / LDS) / 4) waves per SIMD."""
import os

from texcc_tools.bench import common
from texcc_tools.bench import resources


def registers(n):
    regs = ", ".join("st%d" % i for i in range(n))
    params = ", ".join("float4 st%d" % i for i in range(n))

    def select(i):
        return "st%d" % i if i == n - 1 else "(s == %du ? st%d : %s)" % (i, i, select(i + 1))

    write = " else ".join("if (resultSlot == %du) st%d = r;" % (i, i) for i in range(n - 1))
    write = (write + " else " if write else "") + "st%d = r;" % (n - 1)
    return [("#define TEXCC_SLOT(s) stack[s]\n",
             "#define TEXCC_SLOT_READ(s) texcc_slot_read(%s, (s))\n"
             "static inline float4 texcc_slot_read(%s, uint s) { return %s; }\n" % (
                 regs, params, select(0))),
            ("uint src, uint at, uint n, const float4 *stack) {",
             "uint src, uint at, uint n, %s) {" % params),
            ("v = TEXCC_SLOT(src & 0xFFFFu);", "v = TEXCC_SLOT_READ(src & 0xFFFFu);"),
            ("(at), (n), stack)", "(at), (n), %s)" % regs),
            ("float4 stack[TEXCC_STACK_SLOTS];",
             "float4 %s;" % ", ".join("st%d = (float4)(0.0f)" % i for i in range(n))),
            ("TEXCC_SLOT(resultSlot) = r;", write),
            ("TEXCC_SLOT(fakeStack[prog + 2u + 3u * numInstructions + k]);",
             "TEXCC_SLOT_READ(fakeStack[prog + 2u + 3u * numInstructions + k]);")]


def soa(n):
    return [("#define TEXCC_SLOT(s) stack[s]\n",
             "#define TEXCC_SLOT_READ(s) ((float4)(sx[s], sy[s], sz[s], sw[s]))\n"),
            ("uint src, uint at, uint n, const float4 *stack) {",
             "uint src, uint at, uint n, const float *sx, const float *sy, const float *sz, "
             "const float *sw) {"),
            ("v = TEXCC_SLOT(src & 0xFFFFu);", "v = TEXCC_SLOT_READ(src & 0xFFFFu);"),
            ("(at), (n), stack)", "(at), (n), sx, sy, sz, sw)"),
            ("float4 stack[TEXCC_STACK_SLOTS];",
             "float sx[TEXCC_STACK_SLOTS], sy[TEXCC_STACK_SLOTS], sz[TEXCC_STACK_SLOTS], "
             "sw[TEXCC_STACK_SLOTS];"),
            ("TEXCC_SLOT(resultSlot) = r;",
             "sx[resultSlot] = r.x; sy[resultSlot] = r.y; sz[resultSlot] = r.z; "
             "sw[resultSlot] = r.w;"),
            ("TEXCC_SLOT(fakeStack[prog + 2u + 3u * numInstructions + k]);",
             "TEXCC_SLOT_READ(fakeStack[prog + 2u + 3u * numInstructions + k]);")]


def rewrite(text, edits, what):
    for old, new in edits:
        if old not in text:
            raise common.BenchError("value_stack: %s: the interp kernel no longer contains %r"
                                    % (what, old))
        text = text.replace(old, new)
    return text


def measure(tools, quick):
    rows = []
    for tex, graph in resources.GRAPHS.items():
        folder = os.path.join(tools.work, "vs-%s" % tex)
        # Without quickened opcodes (section 3 has the default kernel): the register rewrites
        # replace the one TEXCC_SLOT macro those cases would use as well.
        common.texcc(tools, os.path.join(common.ROOT, graph), folder, "interp",
                     ["--max-quickened=0"])
        src = os.path.join(folder, "proctex.cl")
        with open(src) as f:
            text = f.read()
        slots = int(text.split("#define TEXCC_STACK_SLOTS ")[1].split()[0])
        for variant, edits in (("array", None), ("registers", registers), ("soa", soa)):
            path = src if edits is None else os.path.join(folder, "proctex-%s.cl" % variant)
            if edits is not None:
                with open(path, "w") as f:
                    f.write(rewrite(text, edits(slots), "%s/%s" % (tex, variant)))
            k = resources.amdgpu(path, folder, {"texcc_proctex"})["kernels"]["texcc_proctex"]
            lds = k.get("LDS Size", 0)
            occupancy = k.get("Occupancy")
            if lds:
                occupancy = min(occupancy, (65536 // lds) // 4)
            common.log("value stack %s %s: %s VGPRs, %s B scratch, %s B LDS" % (
                tex, variant, k.get("VGPRs"), k.get("ScratchSize"), lds))
            rows.append({"texture": tex, "variant": variant, "stackSlots": slots,
                         "VGPRs": k.get("VGPRs"), "scratch": k.get("ScratchSize"),
                         "lds": lds, "occupancy": k.get("Occupancy"),
                         "occupancyWithLds": occupancy})
    return {"rows": rows}
