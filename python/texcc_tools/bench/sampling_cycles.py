"""The Cycles side of bench/sampling.py: one render per seed of the atrium .blend with light
groups (sun, sky) and the Diffuse / Glossy Direct / Indirect and Environment passes, each part's
spread over the seeds. Runs in its own bpy process:

    .venv/bin/python -P -m texcc_tools.bench.sampling_cycles REQUEST

(-P: no script folder on the module path, so that bench/cycles.py cannot shadow Blender's own
"cycles" add-on). The reply is one line, TAG + JSON, on stdout."""
import json
import os
import sys
import time

from texcc_tools import exr

TAG = "SAMPLINGJSON "


def spread(imgs):
    """Mean per-pixel variance across seeds (unbiased), the image mean, and the mean pair RMSE."""
    import numpy as np
    imgs = np.stack(imgs)
    pairs = [float(np.sqrt(((imgs[i] - imgs[j]) ** 2).mean()))
             for i in range(len(imgs)) for j in range(i + 1, len(imgs))]
    return {"meanPixelVariance": float(imgs.var(axis=0, ddof=1).mean()),
            "mean": float(imgs.mean()), "meanPairRmse": float(np.mean(pairs))}


def cycles_worker(req):
    channel = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    import bpy
    import numpy as np
    bpy.ops.wm.open_mainfile(filepath=req["blend"])
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = req["size"]
    scene.render.resolution_percentage = 100
    scene.cycles.samples = req["spp"]
    vl = scene.view_layers[0]
    for name in ("sun", "sky"):
        vl.lightgroups.add(name=name)
    for obj in scene.objects:
        if obj.type == "LIGHT":
            obj.lightgroup = "sun"
    scene.world.lightgroup = "sky"
    vl.use_pass_diffuse_direct = vl.use_pass_diffuse_indirect = vl.use_pass_diffuse_color = True
    vl.use_pass_glossy_direct = vl.use_pass_glossy_indirect = vl.use_pass_glossy_color = True
    vl.use_pass_environment = vl.use_pass_emit = True
    if hasattr(scene.render.image_settings, "media_type"):  # Blender 5
        scene.render.image_settings.media_type = "MULTI_LAYER_IMAGE"
    scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
    scene.render.image_settings.color_depth = "32"
    parts = {}
    seconds = []
    for seed in range(1, req["seeds"] + 1):
        scene.cycles.seed = seed
        scene.render.filepath = os.path.join(req["work"], "cycles-split-%d.exr" % seed)
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds.append(time.perf_counter() - t0)
        ch = exr.read_channels(scene.render.filepath)

        def rgb(pass_name):
            return np.stack([np.asarray(ch["ViewLayer.%s.%s" % (pass_name, c)], np.float64)
                             for c in "RGB"], axis=-1)
        d = {"all": rgb("Combined"), "sun": rgb("Combined_sun"), "sky": rgb("Combined_sky"),
             "length1": rgb("Environment") + rgb("Emission"),
             "direct": rgb("Diffuse Direct") * rgb("Diffuse Color")
             + rgb("Glossy Direct") * rgb("Glossy Color"),
             "indirect": rgb("Diffuse Indirect") * rgb("Diffuse Color")
             + rgb("Glossy Indirect") * rgb("Glossy Color")}
        for k, v in d.items():
            parts.setdefault(k, []).append(v)
    out = {k: spread(v) for k, v in parts.items()}
    for k in out:
        out[k]["renderSeconds"] = float(np.median(seconds))
    channel.write(TAG + json.dumps({"parts": out, "version": bpy.app.version_string}) + "\n")
    channel.flush()


if __name__ == "__main__":
    cycles_worker(json.loads(sys.argv[1]))
