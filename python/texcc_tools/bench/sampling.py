"""Where texrender's variance comes from (issue 26): the per-pixel variance of the image split by
light (sun, sky, emissive meshes) and by path length, for texrender and for Cycles on the same
scene (the atrium, examples/blender/make_scene.py).

texrender: the kernels are copied into a scratch folder with `#define RT_SPLIT_LIGHTS mask`
(and RT_SPLIT_MIN_LENGTH / RT_SPLIT_MAX_LENGTH) put in front of shade.cl (kernels/shade.cl: only
those contributions reach the image, the random stream is unchanged), and rendered with
`--kernels` once per part; every part is rendered with `--seed 1..S`. `--samplers pcg,sobol`:
the PCG stream of before issue 26 (RT_SAMPLER_PCG) and the Owen-scrambled Sobol sampler.
Cycles (bpy, .venv): one render per seed with light groups (sun, sky) and the Diffuse / Glossy
Direct / Indirect and Environment passes (direct = path length 2, indirect = 3 and more,
environment = the sky seen from the camera, length 1).
For each part: the mean per-pixel variance of the image across the S seeds (unbiased, mean over
pixels and RGB), which is what the error of one image at that spp is made of.

    python3 bench/sampling.py [--size 128x128] [--spp 64] [--seeds 4] [--variant diffuse]
        [--build build] [--work /tmp/texcc-sampling] [--no-cycles] [--json bench/results/sampling.json]
"""
import argparse
import json
import os
import subprocess
import sys
import time

from texcc_tools import exr
from texcc_tools.bench import common
from texcc_tools.bench.sampling_cycles import TAG, spread

from texcc_tools.paths import VENV_PYTHON  # noqa: E402
MAKE_SCENE = os.path.join(common.ROOT, "examples", "blender", "make_scene.py")
SCENES = {"diffuse": ("bench/inputs/diffuse/graph.json", "examples/atrium/scene-diffuse.json"),
          "rust-model": ("examples/rust/graph.json", "examples/atrium/scene.json")}
# kernels/shade.cl's RT_SPLIT_* bits
MESH, SUN, SKY, MATERIAL = 1, 2, 4, 8
# part: (light mask, min length, max length)
PARTS = {"all": (15, 0, 1000000), "sun": (SUN, 0, 1000000), "sky": (SKY, 0, 1000000),
         "meshes": (MESH | MATERIAL, 0, 1000000), "length1": (15, 1, 1), "direct": (15, 2, 2),
         "indirect": (15, 3, 1000000), "sun-direct": (SUN, 2, 2), "sky-direct": (SKY, 2, 2),
         "sun-indirect": (SUN, 3, 1000000), "sky-indirect": (SKY, 3, 1000000)}


def sampler_defines(sampler):
    """A sampler spec, BASE[:NAME=VALUE[+NAME=VALUE...]] (e.g. sobol:RT_SUN_SHARE=0), as its base
    (pcg or sobol) and the bench-only defines to put in front of shade.cl."""
    base, _, rest = sampler.partition(":")
    if base not in ("pcg", "sobol"):
        raise common.BenchError("unknown sampler %r (pcg or sobol)" % base)
    defines = "".join("#define %s %s\n" % tuple(d.split("=", 1)) for d in rest.split("+") if d)
    return base, defines


def split_kernels(work, part, sampler="sobol"):
    """A copy of kernels/ whose shade.cl keeps only `part` (and, with sampler "pcg", whose
    sampler is the PCG stream of before issue 26: RT_SAMPLER_PCG in rt_sampling.h; a sampler
    spec's defines go in front of shade.cl)."""
    mask, lo, hi = PARTS[part]
    base, defines = sampler_defines(sampler)
    prepend = {"shade.cl": "#define RT_SPLIT_LIGHTS %d\n#define RT_SPLIT_MIN_LENGTH %d\n"
                           "#define RT_SPLIT_MAX_LENGTH %d\n%s" % (mask, lo, hi, defines)}
    if base == "pcg":
        prepend["common/rt_sampling.h"] = "#define RT_SAMPLER_PCG 1\n"
    tag = sampler.replace(":", "-").replace("=", "").replace("+", "-")
    return common.kernel_variant(work, "%s-%s" % (tag, part), prepend)


def read_exr(path):
    import numpy as np
    return np.asarray(exr.read_file(path), np.float64)


def children_cpu():
    """User + system CPU seconds of this process's finished children (all their threads)."""
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def texrender_split(tools, args, textures, scene, samplers):
    """Every sampler's parts, rendered seed by seed with the samplers in an order that rotates
    with the seed (the shared machine's load drifts; CPU times are compared between samplers)."""
    raw = {(s, part): {"imgs": [], "seconds": [], "cpu": [], "inner": [], "shadow": []}
           for s in samplers for part in args.parts.split(",")}
    kdirs = {key: split_kernels(tools.work, key[1], key[0]) for key in raw}
    for seed in range(1, args.seeds + 1):
        k = (seed - 1) % len(samplers)
        for sampler in samplers[k:] + samplers[:k]:
            for part in args.parts.split(","):
                kdir = kdirs[sampler, part]
                common.log("sampling: texrender %s %s seed %d" % (sampler, part, seed))
                name = "split-%s-%d" % (os.path.basename(kdir), seed)
                cache = os.path.join(tools.work, "cache-%s" % os.path.basename(kdir))
                opts = ["--size", args.size, "--spp", str(args.spp), "--seed", str(seed),
                        "--kernels", kdir, "--variance",
                        os.path.join(tools.work, name + ".var.exr")]
                if seed == 1:  # builds the kernels into the cache: not timed
                    common.texrender(tools, scene, textures, name, opts, image="exr",
                                     cache=cache)
                c0 = children_cpu()
                stats, path, _ = common.texrender(tools, scene, textures, name, opts,
                                                  image="exr", cache=cache)
                r = raw[sampler, part]
                r["cpu"].append(children_cpu() - c0)
                r["imgs"].append(read_exr(path))
                r["inner"].append(float(read_exr(
                    os.path.join(tools.work, name + ".var.exr")).mean()))
                r["seconds"].append(stats["renderSeconds"])
                r["shadow"].append(stats["rays"]["shadow"]["count"])
    out = {}
    for (sampler, part), r in raw.items():
        o = out.setdefault(sampler, {})[part] = spread(r["imgs"])
        # texrender --variance: the sample variance / spp of each pixel, mean over the seeds
        o["meanPixelVarianceWithinImage"] = sum(r["inner"]) / len(r["inner"])
        o["renderSeconds"] = common.median(r["seconds"])
        # CPU seconds of the whole texrender process (warm caches), median over the seeds
        o["cpuSeconds"] = common.median(r["cpu"])
        o["shadowRays"] = sum(r["shadow"]) / len(r["shadow"])  # per image: the work, load-free
    return out


def cycles_split(tools, args):
    blend = os.path.join(tools.work, "atrium-%s.blend" % args.variant)
    common.run([VENV_PYTHON, MAKE_SCENE, blend, "--variant", args.variant])
    w, h = (int(x) for x in args.size.split("x"))
    req = {"blend": blend, "size": [w, h], "spp": args.spp, "seeds": args.seeds,
           "work": tools.work}
    common.log("sampling: Cycles, %d seeds" % args.seeds)
    p = subprocess.run([VENV_PYTHON, "-P", "-m", "texcc_tools.bench.sampling_cycles",
                        json.dumps(req)], stdout=subprocess.PIPE, text=True)
    for line in p.stdout.splitlines():
        if line.startswith(TAG):
            return json.loads(line[len(TAG):])
    raise common.BenchError("cycles split worker failed (exit %d)" % p.returncode)


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--cycles-worker":
        subprocess.run([VENV_PYTHON, "-P", "-m", "texcc_tools.bench.sampling_cycles", sys.argv[2]])
        return
    ap = argparse.ArgumentParser()
    common.add_build_argument(ap)
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--variant", default="diffuse", choices=sorted(SCENES))
    ap.add_argument("--work", default="/tmp/texcc-sampling")
    ap.add_argument("--samplers", default="pcg,sobol",
                    help="texrender's samplers to split: pcg (before issue 26), sobol; each "
                    "may carry bench-only shade.cl defines: sobol:RT_SUN_SHARE=0+NAME=VALUE")
    ap.add_argument("--parts", default="all,sun,sky,length1,direct,indirect",
                    help="comma-separated, of: " + ",".join(PARTS))
    ap.add_argument("--no-cycles", action="store_true")
    ap.add_argument("--no-texrender", action="store_true")
    ap.add_argument("--json", default=os.path.join(common.ROOT, "bench", "results",
                                                   "sampling.json"))
    args = ap.parse_args()
    tools = common.Tools(args.build, args.work)
    graph, scene = SCENES[args.variant]
    result = {"size": args.size, "spp": args.spp, "seeds": args.seeds, "variant": args.variant,
              "loadBefore": os.getloadavg()[0], "machine": common.machine(),
              "command": " ".join(sys.argv),
              "date": time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime())}
    if not args.no_texrender:
        textures = os.path.join(tools.work, "tex-" + args.variant)
        common.texcc(tools, os.path.join(common.ROOT, graph), textures, "interp")
        split = texrender_split(tools, args, textures, os.path.join(common.ROOT, scene),
                                args.samplers.split(","))
        for sampler, parts in split.items():
            result["texrender-" + sampler] = parts
    if not args.no_cycles:
        result["cycles"] = cycles_split(tools, args)
    result["loadAfter"] = os.getloadavg()[0]
    os.makedirs(os.path.dirname(args.json), exist_ok=True)
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1)
    for r in [k for k in result if k.startswith("texrender")] + ["cycles"]:
        parts = result.get(r, {}).get("parts", result.get(r, {}))
        for k, v in parts.items():
            if isinstance(v, dict) and "meanPixelVariance" in v:
                print("%-16s %-13s var %.3e  mean %.4f%s" % (
                    r, k, v["meanPixelVariance"], v["mean"],
                    "  cpu %.2f s  shadow rays %d" % (v["cpuSeconds"], v["shadowRays"])
                    if "cpuSeconds" in v else ""))


if __name__ == "__main__":
    main()
