"""BENCHMARKS.md section 2g: the texture code's speed against its C reference
(bench/texture_speed.py) and against Cycles per node (bench/per_node_cycles.py)."""
from texcc_tools.bench import common


def texture_speed_section(d):
    """Section 2g (issue 39): bench/results/texture_speed.json, a standalone run of
    bench/texture_speed.py; where the time went is in bench/texture-speed.md."""
    if not d or not d.get("graphs"):
        return []
    loads = d.get("loadAverage1min") or [0.0]
    lines = ["## 2g. Texture code against the same code compiled as C (issue 39)", "",
             "Nanoseconds per sample on one thread, medians of %d x %d interleaved rounds over %d "
             "points (`bench/texture_speed.py`, at %s, load average %.1f-%.1f): texrender's "
             "modes on PoCL (texcc-eval --time), the texture function compiled by clang-15 -O3 "
             "as C over an array of points with run-time and folded parameters (ref), and "
             "texcc's generated kernel compiled the same way (native). Ratios are to the folded "
             "reference; instructions per sample by callgrind (-march=haswell builds). Every "
             "reference value equals texrender's at the same point. Where the time went, before "
             "and after: [bench/texture-speed.md](bench/texture-speed.md)." % (
                 d["reps"], d["rounds"], d["grid"], d["git"], min(loads), max(loads)), ""]
    order = ("ref-folded", "ref-runtime", "native-inline", "native-interp", "texrender-inline",
             "texrender-interp", "texrender-shape")
    lines += ["| graph | configuration | ns/sample (median) | min | ratio to ref-folded | "
              "instructions/sample |", "|---|---|---|---|---|---|"]
    for g, row in d["graphs"].items():
        for k in order:
            c = row["configs"].get(k)
            if not c:
                continue
            ir = "%.0f" % c["irPerSample"] if "irPerSample" in c else "-"
            lines.append("| %s | %s | %.1f | %.1f | %.2f | %s |" % (
                g, k, c["medianNsPerSample"], c["minNsPerSample"], c["ratioToRefFolded"], ir))
    return lines + ["", "Where the time went (bench/texture-speed.md): texcc's own code (loop "
                    "budget, fault guards, interp's dispatch) costs little - its generated kernel "
                    "compiled by clang -O3 (native) is as fast as the bare function - while PoCL's "
                    "build of the same kernel cost 1.34-1.37x it. PoCL 3.1's kernel library "
                    "computes floor, ceil and trunc in software (a branch in the scalar form, no "
                    "round instruction): Noise Color Detail 7 takes 72 floors per sample. "
                    "texcc_device.h now maps them to clang's rounding builtins (1bf469f, "
                    "da5f673); in one process, without and with them: noise inline 750.5 -> "
                    "622.1 ns, interp 747.2 -> 638.8, user fBM inline 339.2 -> 289.8, interp "
                    "342.9 -> 290.8 (load 2.6); 398b2a8's noise kernels, inline 946.5 and "
                    "interp 745.2 ns, ran in the same process. The work-item loop is not "
                    "vectorised by PoCL in any of these kernels; inline mode's literals fold "
                    "but the octave loops are not unrolled, in PoCL's build or clang's.", ""] + \
        per_node_cycles_lines(common.load("per_node_cycles"))


def per_node_cycles_lines(d):
    """The per-node table (bench/per_node_cycles.py, a standalone run): Cycles SVM and OSL,
    texrender per mode and the C reference, per node, from interleaved rounds."""
    if not d or not d.get("nodes"):
        return []
    if not d.get("interleaved"):
        return per_node_cycles_lines_svm(d)
    loads = d.get("loadAverage1min") or [0.0]

    def ns(row, key):
        c = row.get(key)
        return "%.1f" % c["medianNsPerSample"] if c else "-"

    def ratio(row, key, mode="inline"):
        q = row.get(key)
        return "**%.2fx**" % q[mode] if q else "-"

    lines = ["### Per node: Cycles SVM, Cycles OSL, texrender per mode, the C reference", "",
             "Nanoseconds per sample, one thread each, medians of %d interleaved rounds "
             "(`bench/per_node_cycles.py --spp %d --reps %d`, at %s, load average %.1f-%.1f). "
             "Each round renders in Cycles (bpy, CPU) every node and a constant Emission once "
             "with the SVM and once with the OSL shading system (%dx%d, %d spp, two bpy "
             "processes kept up; Blender's own nodes run as Cycles' OSL shaders under OSL), "
             "runs texrender's modes (texcc-eval --time, %d inner rounds, kernel time per hit) "
             "and the C reference (the same texture source compiled by clang-15 -O3 over an "
             "array of points, folded and run-time parameters, thread CPU time, %d inner "
             "rounds), in an order rotating with the round. Cycles' figure is the node "
             "render's CPU time less the constant's of the same process and round, over the "
             "samples. The user fBM has no SVM form (a Script node runs under OSL only). "
             "Every reference value equals texrender's inline value at the same 4096 points "
             "(max abs difference in the last column); the reference inlines every function into "
             "its loop, as PoCL does." % (
                 d["reps"], d["spp"], d["reps"], d["git"], min(loads), max(loads), d["size"],
                 d["size"], d["spp"], d["inner"], d["inner"]), "",
             "| node | Cycles SVM | Cycles OSL | texrender inline | interp | shape | C ref "
             "folded | C ref run-time | inline / SVM | inline / OSL | inline / C ref folded | "
             "C ref = texrender |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, r in d["nodes"].items():
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2fx | %s |" % (
            name, ns(r, "cyclesSvm"), ns(r, "cyclesOsl"), ns(r, "texrender-inline"),
            ns(r, "texrender-interp"), ns(r, "texrender-shape"), ns(r, "ref-folded"),
            ns(r, "ref-runtime"), ratio(r, "ratioToCyclesSvm"), ratio(r, "ratioToCyclesOsl"),
            r["ratioToRefFolded"]["inline"],
            "max diff %g" % r["refMaxAbsDiff"]))
    spread = []
    for name, r in d["nodes"].items():
        for kind in ("Svm", "Osl"):
            c = r.get("cycles" + kind)
            if c:
                spread.append("%s %s %.0f-%.0f" % (name, kind.upper(), min(c["rounds"]),
                                                   max(c["rounds"])))
    before_after = (
        "Where the time went, before and after (texrender inline, ns per sample, one thread, "
        "texcc-eval --time over 4096 points; bench/texture-speed.md has each step and how it "
        "was found): at ca2db5c Noise 3D Color fBM 624.5, Ridged 653.2, Voronoi 3D F1 380.4, "
        "Wave 245.5 (load 7.8). PoCL had not vectorised the scalar Perlin and Voronoi: the "
        "lattice hashes and gradients on uint4/float4 and Color's channels interleaved "
        "(e9cfb50) gave 437.7, 444.1, 236.1, 201.3. Then, at 992dc9c against now in one process "
        "(load 6.8): Noise 438.4 -> 336.1, Ridged 449.4 -> 346.5 (the 100000 wrap tested once "
        "per fractal instead of per octave, whose fmod calls had kept the octave's values in "
        "memory; Perlin 3D's lanes by vector adds), Voronoi 235.0 -> 79.3 (the running minimum "
        "as values under selects instead of pointers kept in memory with a branch per "
        "candidate), Wave 176.8 -> 141.5 (the wrap and lanes, and Cycles' own sine formula "
        "by a reduction and series: PoCL's sin had cost 14-36 ns). The user fBM: 339.2 -> "
        "289.8 when floor/ceil/trunc became clang's rounding builtins (1bf469f, da5f673); it "
        "stays about 1.1x the folded reference.")
    return lines + ["", before_after, "",
                    "Cycles' per-round costs (CPU time differences, ns per sample): %s; "
                    "the medians of the per-round ratios texrender inline / Cycles: %s. Where "
                    "the time went before and after, node by node: "
                    "[bench/texture-speed.md](bench/texture-speed.md)." % (
                        "; ".join(spread), "; ".join(
                            "%s %s %.2fx" % (name, kind.upper(), r["roundRatioToCycles" + kind])
                            for name, r in d["nodes"].items() for kind in ("Svm", "Osl")
                            if "roundRatioToCycles" + kind in r)), ""]


def per_node_cycles_lines_svm(d):
    """Single Blender nodes against Cycles SVM (bench/per_node_cycles.py, a standalone run)."""
    if not d or not d.get("nodes"):
        return []
    loads = d.get("loadAverage1min") or [0.0]
    lines = ["Single Blender nodes against Cycles SVM, one thread each (`bench/per_node_cycles.py`, "
             "at %s, load average %.1f-%.1f): Cycles' cost per sample is the median over %d "
             "rounds of a %dx%d, %d spp render of the node into Emission minus a constant "
             "Emission's (bpy, CPU; %s time of the bpy process); texrender's is texcc-eval --time's kernel time per hit "
             "(%d rounds). The user fBM runs in Cycles as OSL (bench/cpp_reference/userfbm.osl "
             "in a Script node, against a constant Emission under OSL). The rounds' "
             "differences spread widely on this machine (bench/texture-speed.md)." % (
                 d["git"], min(loads), max(loads), d["reps"], d["size"], d["size"], d["spp"],
                 "CPU" if d.get("clock") == "cpu" else "wall", d["rounds"]), "",
             "| node | Cycles | ns/sample | texrender inline | interp | shape |",
             "|---|---|---|---|---|---|"]
    for name, r in d["nodes"].items():
        kind = "OSL" if "cyclesOslNsPerSample" in r else "SVM"
        t, q = r["texrenderNsPerSample"], r["ratioToCycles" + kind.capitalize()]
        lines.append("| %s | %s | %.1f | %s |" % (
            name, kind, r["cycles%sNsPerSample" % kind.capitalize()], " | ".join(
                "%.1f (%.2fx)" % (t[m], q[m]) for m in ("inline", "interp", "shape"))))
    return lines + [""]
