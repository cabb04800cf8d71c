"""The texture-only figure of bench/cycles.py (--texture-only): the model's material colour
through Emission, no lights, rendered by Cycles and by texrender from the exporter's output of
the same .blend, compared per block (bench/cycles.md)."""
import os

from texcc_tools.bench import common
from texcc_tools.bench.cycles import Cycles, exported, make_blends, texrender_once

TEXTURE_ONLY_VARIANTS = ("rust-model", "scratches-model")




def texture_only(tools, size, spp, variants=TEXTURE_ONLY_VARIANTS, block=8, edge_range=0.5,
                 seed=1, noise_seeds=(), probe=None, pattern=None):
    """Issue 22: the model's material colour through Emission, no lights (make_scene.py
    --texture-only), rendered by Cycles and by texrender from the exporter's output of the same
    .blend; per-block agreement (the worker's blocks()). noise_seeds: both renderers again at
    each of those seeds, and the worker's noise() over all the seeds (the seed-pooled
    difference against its standard error).
    probe: make_scene.py's --texture-probe (rust: "ao", the AO node's output alone;
    "constant-ao", AO replaced by 0.5). pattern: Cycles' sampling pattern (e.g. BLUE_NOISE)."""
    w, h = (int(x) for x in size.split("x"))
    extra = ["--texture-only"] + (["--texture-probe", probe] if probe else [])
    blends = make_blends(tools, variants, extra, "-texture-only" + ("-" + probe if probe else ""))
    cyc = Cycles()
    out = {"size": size, "spp": spp, "cyclesVersion": cyc.version, "results": {},
           "loadAverageBefore": os.getloadavg(), "probe": probe, "cyclesPattern": pattern}
    try:
        for v in variants:
            mask = os.path.join(tools.work, "to-mask-%s.exr" % v)
            cyc.call(op="mask", blend=blends[v], size=[w, h], spp=16, exr=mask)
            cexr = os.path.join(tools.work, "to-cycles-%s.exr" % v)
            t = cyc.call(op="render", blend=blends[v], size=[w, h], spp=spp, seed=seed,
                         exr=cexr, pattern=pattern)["seconds"]
            own = {v: exported(tools, blends[v], v + "-texture-only")}
            r, texr = texrender_once(tools, own, v, "auto", size, spp, "to-" + v, exr=True,
                                     seed=seed)
            res = cyc.call(op="blocks", a=cexr, b=texr, mask=mask, block=block,
                           edgeRange=edge_range, dump=os.path.join(tools.work, "to-%s.npz" % v))
            res.update({"cyclesSeconds": t, "texrenderSeconds": r["frame"],
                        "images": {"cycles": cexr, "texrender": texr, "mask": mask}})
            if noise_seeds:
                ca, tb = [cexr], [texr]
                for ns in noise_seeds:
                    ca.append(os.path.join(tools.work, "to-cycles-%s-%d.exr" % (v, ns)))
                    cyc.call(op="render", blend=blends[v], size=[w, h], spp=spp, seed=ns,
                             exr=ca[-1], pattern=pattern)
                    tb.append(texrender_once(tools, own, v, "auto", size, spp,
                                             "to-%s-%d" % (v, ns), exr=True, seed=ns)[1])
                    common.log("texture-only %s: seed %d done" % (v, ns))
                res["noise"] = cyc.call(op="noise", a=ca, b=tb, mask=mask, block=block,
                                        edgeRange=edge_range)
                res["noise"]["seeds"] = [seed] + list(noise_seeds)
                res["images"].update({"cyclesSeeds": ca, "texrenderSeeds": tb})
            out["results"][v] = res
            common.log("texture-only %s: smooth blocks %s" % (v, res.get("smooth")))
    finally:
        cyc.close()
    out["loadAverageAfter"] = os.getloadavg()
    return out
