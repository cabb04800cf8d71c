"""The charts of BENCHMARKS.md (matplotlib, Agg backend), one function per figure."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from texcc_tools.bench import common

COLORS = {"interp": "tab:blue", "inline": "tab:orange", "wavefront": "tab:green",
          "shape": "tab:red"}


def _save(fig, name):
    os.makedirs(common.CHARTS, exist_ok=True)
    path = os.path.join(common.CHARTS, name + ".png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return "bench/charts/%s.png" % name


def table1(data):
    fig, ax = plt.subplots(figsize=(8, 3.8))
    labels = ["Cycles-sim (paper)", "RTX (paper)", "paper's texcc"] + \
        ["texcc %s (ours)" % m for m in common.MODES]
    textures = ["rust", "scratches"]
    width = 0.8 / len(labels)
    for i, label in enumerate(labels):
        values = []
        for tex in textures:
            rows = [r for r in data["rows"] if r["texture"] == tex]
            if i < 3:
                values.append(rows[0]["paper"][("cycles", "rtx", "paper")[i]])
            else:
                values.append(next(r["increasePercent"] for r in rows
                                   if r["mode"] == common.MODES[i - 3]))
        xs = [t + (i - (len(labels) - 1) / 2) * width for t in range(len(textures))]
        ax.bar(xs, values, width, label=label, hatch="//" if i < 3 else None,
               color=("0.3", "0.55", "0.8")[i] if i < 3 else COLORS[common.MODES[i - 3]],
               edgecolor="black", linewidth=0.4)
    ax.set_xticks(range(len(textures)), textures)
    ax.set_ylabel("render time increase over diffuse (%)")
    ax.set_title("Table 1 on the atrium (%s, %d spp; CPU, PoCL)" % (data["size"], data["spp"]))
    ax.legend(fontsize=7, ncol=2)
    return _save(fig, "table1")


def edits(data):
    fig, ax = plt.subplots(figsize=(8, 3.8))
    rows = data["rows"]
    labels = ["%s\n%s" % (r["mode"], r["edit"]) for r in rows]
    texcc = [r["texccSeconds"] for r in rows]
    build = [r["buildUploadSeconds"] for r in rows]
    frame = [r["frameSeconds"] for r in rows]
    xs = range(len(rows))
    ax.bar(xs, texcc, label="texcc")
    ax.bar(xs, build, bottom=texcc, label="kernel build + upload")
    ax.bar(xs, frame, bottom=[a + b for a, b in zip(texcc, build)], label="first frame")
    ax.set_xticks(list(xs), labels, fontsize=6)
    ax.set_ylabel("seconds")
    ax.set_title("Edit to frame on the atrium with rust (%s, 1 spp)" % data["size"])
    ax.legend(fontsize=7)
    return _save(fig, "edits")


def accuracy(data):
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
    for ax, metric in zip(axes, ("rmse", "flip")):
        for mode in common.MODES:
            pts = sorted((p for p in data["points"] if p["mode"] == mode and p[metric] is not None),
                         key=lambda p: p["renderSeconds"])
            if not pts:
                continue
            ax.plot([p["renderSeconds"] for p in pts], [p[metric] for p in pts], "o-",
                    color=COLORS[mode], label=mode, markersize=3)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("frame time (s)")
        ax.set_ylabel(metric.upper() + " against the reference")
        ax.legend(fontsize=7)
    fig.suptitle("Speed against accuracy, atrium with rust (%s; spp x AO rays sweep)"
                 % data["size"], fontsize=9)
    return _save(fig, "accuracy")


def stability(data):
    metrics = [("texccSeconds", "texcc (s)"), ("buildSeconds", "kernel build (s)"),
               ("kernelSeconds", "texture kernel (s)"), ("memoryBytes", "device memory (B)")]
    fig, axes = plt.subplots(2, len(metrics), figsize=(12, 5.5))
    for row, family in enumerate(("nodes", "depth")):
        for col, (key, label) in enumerate(metrics):
            ax = axes[row][col]
            drawn = False
            for mode in common.MODES:
                pts = [p for p in data["points"] if p["family"] == family and p["mode"] == mode]
                ax.plot([p["size"] for p in pts], [max(p[key], 1e-6) for p in pts], "o-",
                        color=COLORS[mode], label=mode, markersize=3)
                drawn = drawn or bool(pts)
            if drawn:  # a sweep cut short may have no point of this family yet
                ax.set_xscale("log")
                ax.set_yscale("log")
            else:
                ax.text(0.5, 0.5, "not measured", ha="center", va="center",
                        transform=ax.transAxes, fontsize=8)
            ax.set_xlabel("node count" if family == "nodes" else "depth")
            ax.set_title(label, fontsize=8)
            ax.tick_params(labelsize=7)
    axes[0][0].legend(fontsize=7)
    return _save(fig, "stability")


PEER_STYLE = {"texrender-sobol": ("tab:blue", "o-", "texrender (Sobol-Owen)"),
              "texrender-sobol-fixed-share": ("tab:cyan", "d:", "texrender (fixed sun share, before)"),
              "texrender-pcg": ("tab:gray", "s--", "texrender (PCG, before)"),
              "cycles": ("tab:red", "^-", "Cycles")}


def accuracy_peer(data):
    """bench/accuracy.py --peer: error against each renderer's converged reference, by spp and
    by frame time, per scene (rows) and metric (RMSE, HDR-FLIP)."""
    scenes = list(data["scenes"])
    fig, axes = plt.subplots(len(scenes), 3, figsize=(12, 3.4 * len(scenes)), squeeze=False)
    for row, name in enumerate(scenes):
        summary = data["scenes"][name]["summary"]
        for col, (x, metric) in enumerate((("spp", "rmse"), ("seconds", "rmse"),
                                           ("seconds", "flip"))):
            ax = axes[row][col]
            for r, (color, style, label) in PEER_STYLE.items():
                pts = sorted((p for p in summary if p["renderer"] == r and p[metric]),
                             key=lambda p: p[x])
                pts = [p for p in pts if p[x] > 0]
                if pts:
                    ax.plot([p[x] for p in pts], [p[metric] for p in pts], style, color=color,
                            label=label, markersize=3)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("samples per pixel" if x == "spp"
                          else data.get("timeAxis", "frame time (s)"))
            ax.set_ylabel(metric.upper() if metric == "rmse" else "HDR-FLIP")
            ax.set_title("%s: %s by %s" % (name, metric.upper(), "spp" if x == "spp" else "time"),
                         fontsize=8)
            ax.tick_params(labelsize=7)
            ax.legend(fontsize=7)
    fig.suptitle("Error against a converged reference (%s spp, each renderer its own), %s"
                 % (data["refSpp"], data["size"]), fontsize=9)
    return _save(fig, "accuracy_peer")
