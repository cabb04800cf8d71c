"""Principled BSDF conformance against Cycles (issue 37 item 5).

Run with .venv's Python (bpy 5.0.1, numpy):

  principled_conformance.py sphere [--variants user,nobump,plain] [--size 128x128]
      [--spp 256] [--seeds 1-4] [--depth 2]
      The user's scene (bench/inputs/principled_bump_blend.py: a Principled sphere on a grey
      Principled plane under a sun and a sky): Cycles renders the .blend, texrender what
      scripts/blender_export.py exports from it, at each seed; the seed means are compared per
      16x16 block (|texrender / Cycles - 1|, the worst channel) with each block's standard
      error from the seed-to-seed spread. Variants: user (as written), nobump (the Bump node
      unlinked), plain (constant inputs: base 0.5 grey, roughness 0.5, metallic 0.2). --depth N
      sets Cycles' max bounces (texrender's maxDepth N + 2); --light sun|sky keeps one light.

  principled_conformance.py table [--size 64x64] [--spp 256] [--seeds 1-2] [--cases ...]
      Per variant (roughness x metallic x specular x base colour), a unit sphere filling the
      view, Cycles' Principled BSDF against texrender's, each case in two lightings: the
      furnace (a uniform white world, no lamp, 8 bounces: the sphere's directional albedo at
      each view angle) and a single bounce (a sun from the camera's upper left, a black world,
      direct light only). Per case: the mean over rings of cos(wo) and the max / mean relative
      error over the rings.

Prints the tables; --json FILE writes them.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

from texcc_tools import exr, process
from texcc_tools.paths import ROOT, VENV_PYTHON as PY, add_build_argument


def seed_list(text):
    if "-" in text:
        a, b = text.split("-")
        return list(range(int(a), int(b) + 1))
    return [int(x) for x in text.split(",")]


def run(cmd):
    try:
        return process.run(cmd, tail=3000).stdout
    except process.RunError as e:
        sys.exit("principled_conformance: %s" % e)


def read_exr(path):
    import numpy as np
    return np.asarray(exr.read_file(path), np.float64)


class Tools:
    def __init__(self, build, work):
        self.texcc = os.path.join(build, "bin", "texcc")
        self.texrender = os.path.join(build, "bin", "texrender")
        self.work = work

    def export(self, blend, name):
        out = os.path.join(self.work, "export-" + name)
        run([PY, os.path.join(ROOT, "scripts", "blender_export.py"), blend, "-o", out])
        run([self.texcc, "--graph", os.path.join(out, "graph.json"), "-o", out + "-tex"])
        return os.path.join(out, "scene.json"), out + "-tex"

    def render(self, scene, textures, exr, size, spp, seed, extra=()):
        run([self.texrender, scene, "--textures", textures, "--size", size, "--spp", str(spp),
             "--seed", str(seed), "--quiet", "-o", exr] + list(extra))
        return read_exr(exr)


def cycles_render(scene, w, h, spp, seed, path):
    """Cycles at w x h, spp, seed; the linear RGB image (top row first)."""
    import numpy as np
    from texcc_tools.testing.cycles_render import render_npy
    scene.render.resolution_x, scene.render.resolution_y = w, h
    scene.render.resolution_percentage = 100
    scene.cycles.seed = seed
    render_npy(scene, spp, path + ".exr", path + ".npy")
    return np.load(path + ".npy")[..., :3].astype(np.float64)


# --- The user's sphere ---------------------------------------------------------------------

def sphere_blend(work, variant, depth, light):
    import bpy
    blend = os.path.join(work, "sphere-%s-d%d-%s.blend" % (variant, depth, light))
    run([PY, os.path.join(ROOT, "bench", "inputs", "principled_bump_blend.py"), blend])
    bpy.ops.wm.open_mainfile(filepath=blend)
    scene = bpy.context.scene
    mat = bpy.data.materials["painted"]
    t = mat.node_tree
    bsdf = t.nodes["Principled"]
    if variant in ("nobump", "plain"):
        for link in list(bsdf.inputs["Normal"].links):
            t.links.remove(link)
    if variant == "plain":
        for name in ("Base Color", "Roughness"):
            for link in list(bsdf.inputs[name].links):
                t.links.remove(link)
        for n in list(t.nodes):
            if n.name not in ("Principled",) and n.bl_idname != "ShaderNodeOutputMaterial":
                t.nodes.remove(n)
        bsdf.inputs["Base Color"].default_value = (0.5, 0.5, 0.5, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.5
    c = scene.cycles
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = depth
    if light == "sun":
        scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    elif light == "sky":
        bpy.data.objects["Sun"].data.energy = 0.0
    bpy.ops.wm.save_as_mainfile(filepath=blend)
    return blend


def block_compare(cyc, tex, block=16):
    """Seed means compared per block: (rel, z, means) arrays per block and channel."""
    import numpy as np
    a, b = np.mean(cyc, axis=0), np.mean(tex, axis=0)
    h, w = a.shape[:2]

    def tiles(x):
        return x.reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))

    ta, tb = tiles(a), tiles(b)
    floor = 0.05 * a.mean()
    rel = (tb - ta) / np.maximum(ta, floor)
    n = len(cyc)
    if n > 1:
        se2 = sum(np.var([tiles(x) for x in xs], axis=0, ddof=1) / n for xs in (cyc, tex))
        se = np.sqrt(np.maximum(se2, 1e-30)) / np.maximum(ta, floor)
    else:
        se = np.full_like(rel, np.nan)
    return rel, se, ta, tb


def sphere(args, tools):
    import bpy  # noqa: F401  (imported before numpy's use in cycles_render)
    import numpy as np
    w, h = (int(x) for x in args.size.split("x"))
    out = {}
    for variant in args.variants.split(","):
        blend = sphere_blend(tools.work, variant, args.depth, args.light)
        scene_json, textures = tools.export(blend, "sphere-" + variant)
        builds = [("", tools)]
        if args.before:
            builds.append(("before", Tools(os.path.abspath(args.before), tools.work)))
        cyc, texs = [], {label: [] for label, _ in builds}
        for seed in args.seeds:
            bpy.ops.wm.open_mainfile(filepath=blend)
            cyc.append(cycles_render(bpy.context.scene, w, h, args.spp, seed,
                                     os.path.join(tools.work, "cyc-%s-%d" % (variant, seed))))
            for label, tl in builds:
                texs[label].append(tl.render(
                    scene_json, textures,
                    os.path.join(tools.work, "tex%s-%s-%d.exr" % (label, variant, seed)),
                    args.size, args.spp, seed))
        for label, _ in builds:
            key = variant + ("-" + label if label else "")
            out[key] = sphere_table(cyc, texs[label], "%s%s" % (
                variant, " [before: %s]" % args.before if label else ""), args)
    return out


def sphere_table(cyc, tex, variant, args):
    import numpy as np
    rel, se, ta, tb = block_compare(cyc, tex)
    worst = np.abs(rel).max(axis=-1)
    within = worst <= 0.01
    mean_rel = np.mean(tex, axis=(0, 1, 2)) / np.mean(cyc, axis=(0, 1, 2)) - 1
    r = {"blocks": int(within.size), "within1": int(within.sum()),
         "worstPercent": 100 * float(worst.max()),
         "meanRelPercent": (100 * mean_rel).tolist(),
         "relPercent": (100 * rel.mean(axis=-1)).round(2).tolist(),
         "sePercent": (100 * se.mean(axis=-1)).round(2).tolist()}
    print("sphere %-7s depth %d light %s: image mean %+.2f/%+.2f/%+.2f%%, 16x16 blocks within"
          " 1%%: %d/%d, worst %.2f%%" % (variant, args.depth, args.light, *r["meanRelPercent"],
                                         r["within1"], r["blocks"], r["worstPercent"]))
    print("  per block, texrender / Cycles - 1 (%, grey mean of channels; se in brackets):")
    for i in range(rel.shape[0]):
        print("  " + " ".join("%+5.1f(%3.1f)" % (100 * rel[i, j].mean(), 100 * se[i, j].mean())
                              for j in range(rel.shape[1])))
    sys.stdout.flush()
    return r


# --- The table: one sphere per case on a grid, furnace and single bounce ---------------------

ROUGH = (0.1, 0.3, 0.5, 0.8, 1.0)
BASES = {"white": (1.0, 1.0, 1.0), "orange": (0.8, 0.35, 0.1)}
COLS, CELL, SPACING, DIST = 10, 32, 3.0, 120.0
RINGS = ((0.2, 0.45), (0.45, 0.7), (0.7, 0.9), (0.9, 1.0))


def cases():
    """(name, roughness, metallic, specular IOR level, base name) of every variant."""
    out = []
    for r in ROUGH:
        for m in (0.0, 0.5, 1.0):
            for spec in ((0.5,) if m == 1.0 else (0.0, 0.5, 1.0)):
                for b in BASES:
                    out.append(("r%g_m%g_s%g_%s" % (r, m, spec, b), r, m, spec, b))
    return out


def render_settings(scene, bounces):
    c = scene.cycles
    scene.render.engine = "CYCLES"
    c.device = "CPU"
    c.use_light_tree = c.use_guiding = c.use_denoising = c.use_adaptive_sampling = False
    c.pixel_filter_type, c.filter_width = "BOX", 1.0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    scene.view_settings.view_transform = "Standard"
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = bounces


def grid_blend(work, which, lighting):
    """The spheres of `which` on a grid in the XZ plane facing a far camera on -Y; lighting
    furnace (a white world of strength 1, 8 bounces) or single (a black world, a sun of 3 W/m^2
    from the upper left in front, direct light only)."""
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    render_settings(scene, 8 if lighting == "furnace" else 0)
    rows = (len(which) + COLS - 1) // COLS
    w, h = COLS * CELL, rows * CELL
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (1, 1, 1, 1) if lighting == "furnace" else (0, 0, 0, 1)
    scene.world = world
    if lighting == "single":
        sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
        sun.data.energy = 3.0
        sun.data.angle = math.radians(1.0)
        sun.rotation_euler = (math.radians(60), 0.0, math.radians(-40))
        scene.collection.objects.link(sun)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.location = (0.0, -DIST, 0.0)
    cam.rotation_euler = (math.radians(90), 0.0, 0.0)
    cam.data.sensor_fit, cam.data.sensor_width = "HORIZONTAL", 36.0
    width = COLS * SPACING
    cam.data.lens = 36.0 * DIST / width
    scene.collection.objects.link(cam)
    scene.camera = cam
    for k, (name, r, m, spec, b) in enumerate(which):
        row, col = divmod(k, COLS)
        x = (col - (COLS - 1) / 2) * SPACING
        z = ((rows - 1) / 2 - row) * SPACING
        bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, location=(x, 0, z), segments=64,
                                             ring_count=32)
        obj = bpy.context.active_object
        obj.data.shade_smooth()
        mat = bpy.data.materials.new(name)
        mat.use_nodes = True
        p = mat.node_tree.nodes["Principled BSDF"]
        p.inputs["Base Color"].default_value = BASES[b] + (1.0,)
        p.inputs["Roughness"].default_value = r
        p.inputs["Metallic"].default_value = m
        p.inputs["Specular IOR Level"].default_value = spec
        obj.data.materials.append(mat)
    scene.render.resolution_x, scene.render.resolution_y = w, h
    blend = os.path.join(work, "grid-%s.blend" % lighting)
    bpy.ops.wm.save_as_mainfile(filepath=blend)
    return blend, w, h, rows


def sphere_rings(k, w, h, rows):
    """Pixel masks of sphere k's rings of cos(wo) (the far camera as orthographic)."""
    import numpy as np
    row, col = divmod(k, COLS)
    cx, cy = (col + 0.5) * CELL, (row + 0.5) * CELL + (h - rows * CELL) / 2
    rad = CELL / SPACING  # pixels per unit: w / (COLS * SPACING)
    yy, xx = np.mgrid[0:h, 0:w] + 0.5
    rr = np.hypot(xx - cx, yy - cy) / rad
    cos = np.sqrt(np.clip(1 - rr * rr, 0, 1))
    ok = rr < 0.97
    return [ok & (cos >= lo) & (cos < hi) for lo, hi in RINGS]


def table(args, tools):
    import bpy
    import numpy as np
    which = cases()
    if args.cases:
        keep = args.cases.split(",")
        which = [c for c in which if any(k in c[0] for k in keep)]
    out = {}
    for lighting in ("furnace", "single"):
        blend, w, h, rows = grid_blend(tools.work, which, lighting)
        scene_json, textures = tools.export(blend, "grid-" + lighting)
        builds = [("", tools)] + [("before", Tools(os.path.abspath(args.before), tools.work))
                                  if args.before else None]
        builds = [b for b in builds if b]
        cyc, tex = [], {label: [] for label, _ in builds}
        for seed in args.seeds:
            bpy.ops.wm.open_mainfile(filepath=blend)
            cyc.append(cycles_render(bpy.context.scene, w, h, args.spp, seed,
                                     os.path.join(tools.work, "cyc-%s-%d" % (lighting, seed))))
            for label, tl in builds:
                tex[label].append(tl.render(
                    scene_json, textures,
                    os.path.join(tools.work, "tex%s-%s-%d.exr" % (label, lighting, seed)),
                    "%dx%d" % (w, h), args.spp, seed))
        a = np.mean(cyc, axis=0)
        for label, _ in builds:
            out[lighting + ("-" + label if label else "")] = ring_table(
                which, a, np.mean(tex[label], axis=0), w, h, rows,
                "%s%s (%dx%d, %d spp x %d seeds)" % (
                    lighting, " [%s: %s]" % (label, args.before) if label else "", w, h,
                    args.spp, len(args.seeds)))
    return out


def ring_table(which, a, b, w, h, rows, title):
    import numpy as np
    lighting = title.split()[0]
    print("\n%s: per ring of cos wo, Cycles' mean (grey) and texrender / Cycles - 1 (worst"
          " channel)" % title)
    print("%-22s %s | %8s %8s" % ("case", " ".join("%15s" % ("%.2f-%.2f" % r) for r in RINGS),
                                  "max", "mean"))
    res = {}
    for k, (name, r, m, spec, base) in enumerate(which):
        errs, cells = [], []
        for mask in sphere_rings(k, w, h, rows):
            ca, tb = a[mask].mean(axis=0), b[mask].mean(axis=0)
            e = tb / np.maximum(ca, 1e-6) - 1
            worst = e[np.argmax(np.abs(e))]
            errs.append(float(worst))
            cells.append("%6.4f %+6.2f%%" % (ca.mean(), 100 * worst))
        res[name] = {"roughness": r, "metallic": m, "specular": spec, "base": base,
                     "ringErrorsPercent": [100 * e for e in errs],
                     "maxPercent": 100 * max(abs(e) for e in errs),
                     "meanPercent": 100 * float(np.mean(np.abs(errs)))}
        print("%-22s %s | %7.2f%% %7.2f%%" % (name, " ".join("%15s" % c for c in cells),
                                             res[name]["maxPercent"],
                                             res[name]["meanPercent"]))
    allmax = max(v["maxPercent"] for v in res.values())
    print("%s: worst ring %.2f%%, mean of the cases' mean %.2f%%" % (
        lighting, allmax, float(np.mean([v["meanPercent"] for v in res.values()]))))
    sys.stdout.flush()
    return res



def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("what", choices=("sphere", "table"))
    add_build_argument(ap)
    ap.add_argument("--size")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--seeds", type=seed_list, default=[1])
    ap.add_argument("--variants", default="user,nobump,plain")
    ap.add_argument("--depth", type=int, default=2)
    ap.add_argument("--light", choices=("both", "sun", "sky"), default="both")
    ap.add_argument("--cases", help="table: only the cases whose names contain one of these "
                    "(comma-separated), e.g. m0_s0.5,r1_")
    ap.add_argument("--before", help="also texrender of this build folder (bin/, "
                    "kernels/) against the same Cycles images")
    ap.add_argument("--json")
    args = ap.parse_args()
    tools = Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-principled-"))
    t0, load0 = time.time(), os.getloadavg()
    if args.what == "sphere":
        args.size = args.size or "128x128"
        data = sphere(args, tools)
    else:
        args.size = args.size or "64x64"
        data = table(args, tools)
    meta = {"command": " ".join(sys.argv), "seconds": time.time() - t0, "loadBefore": load0,
            "loadAfter": os.getloadavg(), "date": time.strftime("%Y-%m-%d %H:%M UTC",
                                                                 time.gmtime())}
    print("load %.1f -> %.1f, %.0f s" % (load0[0], meta["loadAfter"][0], meta["seconds"]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"meta": meta, "results": data}, f, indent=1)


if __name__ == "__main__":
    main()
