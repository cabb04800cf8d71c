import os
import sys
import tempfile

from texcc_tools.bench import accuracy, startup_split

WORK, WORKER = "10/11", "10/12"
SAMPLES = [
    (WORK, ["asm_exc_page_fault", "clear_page_erms"]),
    (WORK, ["fastNumber (inlined)", "texrender::objFromTextFast", "texrender::loadObj",
            "texrender::buildSceneData", "texrender::Renderer::Renderer", "start_thread"]),
    (WORK, ["[unknown]", "rtcBuildBVH", "texrender::buildBvh", "texrender::buildSceneData",
            "start_thread"]),
    (WORKER, ["[unknown]", "[unknown]", "start_thread"]),
    (WORKER, ["[unknown]", "start_thread"]),
    (WORK, ["rtcCommitScene", "texrender::makeEmbreeTrace", "texrender::Renderer::Renderer"]),
    (WORKER, ["[unknown]", "start_thread"]),
]
with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
    for i, (ids, frames) in enumerate(SAMPLES):
        f.write("%8s %d.%06d: \n" % (ids, 100, i))
        for fr in frames:
            f.write("\t%16x %s\n" % (0x1000 + i, fr))
        f.write("\n")
total, counts = startup_split.split(f.name)
os.unlink(f.name)
print("samples %d" % total)
for phase in ("OBJ loading (read, parse, checks, normals)", "wide BVH (Embree's builder, flattening)",
              "Embree scene BVH (trace backend)"):
    print("%s %d" % (phase, counts[phase]))

order = []
cpu = {"texrender-sobol": iter([2.5, 1.0, 2.0]), "cycles": iter([0.3, 0.2, 0.9])}


def tr(sampler, spp, seed, name, size=None):
    if name.startswith("peer-warm"):
        return {"cpu": 9.0, "wall": 9.0, "seconds": 9.0}, None
    order.append("texrender-" + sampler)
    c = next(cpu["texrender-" + sampler])
    return {"cpu": c, "wall": c, "seconds": c}, None


def cy(spp, seed, exr, size=None):
    if size is None:
        return {"cpu": 9.0, "wall": 9.0, "seconds": 9.0}
    order.append("cycles")
    c = next(cpu["cycles"])
    return {"cpu": c, "wall": c, "seconds": c}


fixed = accuracy.fixed_parts(tr, cy, ["sobol"], reps=3)
print("order " + " ".join(order))
print("median texrender-sobol %.1f cycles %.1f" % (fixed["texrender-sobol"]["cpu"],
                                                   fixed["cycles"]["cpu"]))
