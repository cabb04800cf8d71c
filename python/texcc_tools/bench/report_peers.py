"""BENCHMARKS.md's sections on texrender beside Blender Cycles (bench/cycles.py), on single
Blender nodes (bench/per_hit.py --nodes) and on error against converged references beside Cycles
(bench/accuracy.py --peer); texcc_tools.bench.report assembles the page."""
from texcc_tools.bench import charts, common
from texcc_tools.bench.common import fmt, pct


def cycles_overheads():
    """({"rust": %, "scratches": %}, spp): measured Cycles' overhead over diffuse
    (bench/results/cycles.json), the model textured as in Table 1, at the highest spp measured
    for all three (at 1 spp a Cycles frame of 512x512 is under 0.6 s and the variants' fixed
    parts differ by a fifth of it: bench/cycles.md, session 10)."""
    d = common.load("cycles") or {}
    rows = {(r["renderer"], r["spp"], r["variant"]): r for r in d.get("rows", [])}
    spps = [s for s in sorted({r["spp"] for r in d.get("rows", [])}, reverse=True)
            if all(("cycles", s, v) in rows for v in ("diffuse", "rust-model", "scratches-model"))]
    if not spps:
        return {}, None
    base = rows[("cycles", spps[0], "diffuse")]
    out = {}
    for v in ("rust-model", "scratches-model"):
        r = rows[("cycles", spps[0], v)]
        f, fb = (x.get("fixedSeconds", d["cyclesFixedSeconds"][x["variant"]]) for x in (r, base))
        out[v.split("-")[0]] = 100 * (common.median(
            [(t - f) / (b - fb) for t, b in zip(r["raw"], base["raw"])]) - 1)
    return out, spps[0]


def cycles_section(d):
    """bench/cycles.py: texrender against measured Cycles on the atrium (issues 22 and 24)."""
    lines = ["## Side by side with Cycles (atrium)", ""]
    if not d or not d.get("rows"):
        return lines + ["Not measured yet: run `python3 bench/cycles.py` (or `bench/run --only "
                        "cycles`); how to run it and what it measures: "
                        "[bench/cycles.md](bench/cycles.md).", ""]
    runs = {}  # the runs that measured the rows, oldest first (rows before session 10: d's)
    for r in d["rows"]:
        run = r.get("run") or {k: d.get(k) for k in ("command", "date", "size", "repetitions",
                                                     "loadAverage1min", "complete")}
        runs.setdefault((run["date"], run["command"]), (run, []))[1].append(r)
    lines += ["Cycles %s (bpy, CPU, both threads), max depth %d (Cycles max_bounces %d), "
              "repetitions interleaved (every renderer and variant in each, rotating order), "
              "medians. Cycles: `render.render()` in one warm process, which includes Cycles' "
              "scene sync and BVH build (a 16x16 1-spp render of the same file is that fixed "
              "part; \"Cycles less fixed\" subtracts it). texrender: `renderSeconds` (the frame, "
              "without BVH and kernel builds), default mode; rust and scratches are the examples' "
              "texcc graphs, not the Blender node trees, so their rows compare work, not pixels. "
              "Method and caveats: [bench/cycles.md](bench/cycles.md)." % (
                  d.get("cyclesVersion", "?"), d["maxDepth"], d["cyclesMaxBounces"]), "",
              "Measured by:", ""]
    for (date, command), (run, rows) in sorted(runs.items()):
        loads = run.get("loadAverage1min") or [0.0]
        fixed = [r["fixedSeconds"] for r in rows if "fixedSeconds" in r]
        lines.append("- `%s`, %s, %s, %d repetitions, 1-minute load average %.1f-%.1f on 2 "
                     "cores%s%s: %s" % (
                         command, date, run["size"], run["repetitions"], min(loads), max(loads),
                         "" if run.get("complete", True) else " (cut short)",
                         ", Cycles' fixed part %.2f-%.2f s" % (min(fixed), max(fixed))
                         if fixed else "",
                         ", ".join(sorted({"%d spp" % r["spp"] for r in rows}))))
    lines.append("")
    lines += ["| spp | variant | Cycles | Cycles less fixed | texrender auto (Embree) | "
              "texrender opencl | auto / Cycles | auto / Cycles less fixed | overhead over diffuse: "
              "Cycles | auto | opencl |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    rows = {(r["spp"], r["renderer"], r["variant"]): r for r in d["rows"]}
    for spp in sorted({r["spp"] for r in d["rows"]}):
        for v in ("diffuse", "rust-model", "rust-all", "scratches-model"):
            c, a, o = (rows.get((spp, n, v)) for n in ("cycles", "texrender-auto",
                                                      "texrender-opencl"))
            if not (c and a):
                continue
            lines.append("| %d | %s | %.2f s | %.2f s | %.2f s | %s | **%.2fx** | %.2fx | %s | "
                         "%s | %s |"
                         % (spp, v, c["median"], c["medianWithoutFixed"], a["median"],
                            "%.2f s" % o["median"] if o else "not run", a["overCyclesRender"],
                            a["overCyclesFrame"], pct(c["overheadPercent"]),
                            pct(a["overheadPercent"]), pct(o["overheadPercent"]) if o else "-"))
    top = max(r["spp"] for r in d["rows"])
    lines += ["", "Where texrender's time goes at %d spp (median stage seconds, stats.json; the "
              "Embree stages are wall time, the OpenCL ones device time):" % top, ""]
    for r in d["rows"]:
        if r["spp"] == top and r["renderer"] != "cycles" and r["variant"] in ("diffuse",
                                                                               "rust-all"):
            total = sum(r["stages"].values()) or 1.0
            big = sorted(r["stages"].items(), key=lambda kv: -kv[1])[:5]
            lines.append("- %s, %s: %s" % (r["variant"], r["renderer"], ", ".join(
                "`%s` %.2f s (%.0f%%)" % (n, t, 100 * t / total) for n, t in big)))
    lines += ["", "Raw times (seconds, in repetition order):", ""]
    for r in d["rows"]:
        lines.append("- %d spp, %s, %s: %s" % (r["spp"], r["variant"], r["renderer"],
                                               ", ".join("%.2f" % t for t in r["raw"])))
    ag = d.get("agreement")
    if ag:
        lines += ["", "Image agreement: each renderer at high spp; mean linear RGB, texrender "
                  "relative to Cycles, per region (model: pixels wholly on the gears; rest: "
                  "pixels wholly off them), and mean HDR-FLIP between the two images (noise "
                  "included). Diffuse: texrender's own atrium scene; rust and scratches: what "
                  "`scripts/blender_export.py` exports from the very .blend Cycles renders "
                  "(the Blender node trees through textures/blender/).", "",
                  "| variant | size, spp | region | pixels | Cycles RGB | texrender RGB | "
                  "difference | FLIP |", "|---|---|---|---|---|---|---|---|"]
        for v, res in ag["results"].items():
            if "error" in res:
                lines.append("| %s | - | not measured: %s | | | | | |" % (
                    v, res["error"].replace("|", "/")))
                continue
            for name, g in res["regions"].items():
                n = len(res.get("seeds", [1]))
                lines.append("| %s | %s, %d%s | %s | %d | %s | %s | %s | %s |" % (
                    v, res.get("size", ag.get("size")), res.get("spp", ag.get("spp")),
                    " (%d seeds)" % n if n > 1 else "", name,
                    g["pixels"], ", ".join("%.4f" % x for x in g["a"]),
                    ", ".join("%.4f" % x for x in g["b"]),
                    ", ".join(pct(x) for x in g["relDiffPercent"]), fmt(res.get("flip"))))
        by = sorted({(r["run"]["date"], r["run"]["command"], v) for v, r in ag["results"].items()
                     if "run" in r})
        if by:
            lines += [""] + ["%s: `%s`, %s." % (v, c, t) for t, c, v in by]
    return lines + [""]


def per_hit_nodes_section(d):
    """Issue 21's rows: single Blender nodes, inline and interp (bench/per_hit.py --nodes)."""
    title = "## 2f. Per-hit cost of single Blender nodes (textures/blender/)"
    if not d or "textures" not in d:
        return [title, "", "Not measured yet (`bench/per_hit.py --nodes`).", ""]
    load = d["loadAverage"]["before"]
    lines = [title, "",
             "`bench/per_hit.py --nodes` (not part of `bench/run`): every node's inline and interp "
             "kernels in one `texcc-eval --time %d --grid %d` process, rotating order, PoCL on one "
             "thread; median (minimum) ns per textured hit and the median of per-round ratios to "
             "the first row's inline. git %s, load average %.1f %.1f %.1f."
             % (d["rounds"], d["grid"], d["git"], load[0], load[1], load[2]), "",
             "| node graph | inline | interp | inline / first | interp / first |",
             "|---|---|---|---|---|"]
    for name, r in d["textures"].items():
        c = r["configs"]
        lines.append("| %s (`%s`) | %.0f (%.0f) | %.0f (%.0f) | %.3fx | %.3fx |" % (
            name, r["graph"], c["inline"]["medianNsPerHit"], c["inline"]["minNsPerHit"],
            c["interp"]["medianNsPerHit"], c["interp"]["minNsPerHit"],
            c["inline"]["medianRatioToFirst"], c["interp"]["medianRatioToFirst"]))
    return lines + [""]


def peer_section(d):
    """4b: bench/accuracy.py --peer, error against converged references beside Cycles."""
    if not d or not d.get("scenes"):
        return []
    lines = ["## 4b. Error against converged references, beside Cycles", "",
             "`bench/accuracy.py --peer` (details and the runs' notes: bench/sampling.md): %s, "
             "each renderer against its own %d-spp reference; RMSE: RMS over the repetitions "
             "(seeds 1..). Time axis: the renderer's CPU time (user + system, all threads) per "
             "frame, i.e. less its fixed part (texrender's process start, scene load and BVH; "
             "Cycles' scene sync and BVH), from a fit of each renderer's CPU time as fixed + "
             "per sample x spp over the medians at each spp (the measured frame times are in "
             "the results file). Ratios are texrender's RMSE over Cycles' at equal spp and at the "
             "CPU time Cycles spends on that spp (texrender's RMSE read off its own "
             "RMSE-against-spp curve in log-log at the spp it renders in that time), with 95%% bootstrap intervals over "
             "the repetitions; \"whole process\" counts the fixed parts too (- : texrender's "
             "fixed part alone is longer than Cycles' whole render). Load %s-%s during the "
             "run."
             % (d["size"], d["refSpp"], _fmt_load(d, min), _fmt_load(d, max)), ""]
    for scene, s in d["scenes"].items():
        rows = {}
        for r in s["summary"]:
            rows.setdefault(r["spp"], {})[r["renderer"]] = r
        ratios = s.get("ratios", {})
        fixed = s.get("fixed", {})
        if not ratios or "texrender-sobol" not in fixed:
            continue
        tm = ratios.get("timeModel", {})
        fit = ""
        if "texrender-sobol" in tm and "cycles" in tm:
            fit = "; CPU s fitted as fixed + per sample x spp: texrender %.2f + %.4f spp, " \
                  "Cycles %.2f + %.4f spp" % tuple(tm["texrender-sobol"] + tm["cycles"])
        lines += ["%s (fixed part, CPU s of a 16x16 1 spp render: texrender %.2f, Cycles "
                  "%.2f%s):" % (scene, fixed["texrender-sobol"]["cpu"], fixed["cycles"]["cpu"],
                                fit), "",
                  "| spp | reps | Cycles RMSE | texrender RMSE | equal spp | Cycles CPU s "
                  "(fit) | texrender CPU s (fit) | equal time | equal time, whole process |",
                  "|---|---|---|---|---|---|---|---|---|"]

        def ci(v):
            if not v or v["ratio"] is None:
                return "-"
            return "**%.3f** [%.3f, %.3f]" % ((v["ratio"],) + tuple(v["ci95"]))
        for spp in sorted(rows):
            c, t = rows[spp].get("cycles"), rows[spp].get("texrender-sobol")
            if not c or not t:
                continue
            q = ratios.get(str(spp), {})
            lines.append("| %d | %d | %.5f | %.5f | %s | %.2f | %.2f | %s | %s |" % (
                spp, t["n"], c["rmse"], t["rmse"], ci(q.get("equalSpp")), c["seconds"],
                t["seconds"],
                ci(q.get("equalTime-cpu")), ci(q.get("equalTime-cpuTotal"))))
        lines.append("")
    chart = charts.accuracy_peer(d)
    return lines + ["![error against converged references](%s)" % chart, ""]


def _fmt_load(d, f):
    loads = d.get("loads") or [0.0]
    return "%.1f" % f(loads)
