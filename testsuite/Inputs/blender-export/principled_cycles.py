"""Texrender's Principled BSDF against Cycles' (testsuite/blender-export/principled-cycles.test).

  principled_cycles.py make OUTDIR     sphere.obj, graph.json (one principled material per case)
                                       and a scene per case and lighting: the unit sphere of
                                       glossy_furnace.py filling the view, under a uniform white
                                       sky ("furnace": the directional albedo at each view angle)
                                       or lit by a sun alone (irradiance pi, from the upper left
                                       in front, maxDepth 2: "sun")
  principled_cycles.py check OUTDIR    per case, lighting and ring of view angle (cos wo), the
                                       mean of OUTDIR/<case>-<lighting>.exr's pixels in it against
                                       cycles-principled.json (Cycles 5.0.1's means of the same
                                       pixels)
  principled_cycles.py cycles OUTDIR   (bpy) renders the same scenes with Cycles' Principled BSDF
                                       (Multiscatter GGX, IOR 1.5) at CYCLES_SPP and writes their
                                       ring means to cycles-principled.json next to this script

The cases are those where texrender's Principled differed most from Cycles' before it took
Cycles' model (scripts/principled_conformance.py table; bench/principled.md): the diffuse base's
weight under the specular layer (Cycles: 1 - the layer's estimated albedo F0 + (1 - F0) S times
its multiple-bounce darkening), the dielectric layer's real Fresnel, the height-correlated
masking-shadowing and the multiple-bounce Fresnel of a coloured rough metal.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
from glossy_furnace import DIST, FOV, SIZE, cos_wo
from texcc_tools.testing.sphere_scene import main, make_folder, read_image, write_json

# name: (base colour, roughness, metallic, specular IOR level)
MATERIALS = {
    "orange_r0.5": ([0.8, 0.35, 0.1], 0.5, 0.0, 0.5),
    "white_r1": ([1.0, 1.0, 1.0], 1.0, 0.0, 0.5),
    "orange_r0.3_spec1": ([0.8, 0.35, 0.1], 0.3, 0.0, 1.0),
    "orange_metal_r0.8": ([0.8, 0.35, 0.1], 0.8, 1.0, 0.5),
    "grey_half_metal_r0.5": ([0.5, 0.5, 0.5], 0.5, 0.5, 0.5),
}
LIGHTINGS = ("furnace", "sun")
SUN_DIR = (-0.5, 0.55, 0.67)  # towards the sun (texrender's "direction")
SUN_RADIUS = 2.0  # degrees
# (cos wo from, to): the outer ring stops short of the silhouette
RINGS = ((0.2, 0.45), (0.45, 0.7), (0.7, 0.9), (0.9, 1.0))
TOLERANCE = 0.01
CYCLES_SPP = 2048
REFERENCE = os.path.join(HERE, "cycles-principled.json")


def sun_direction():
    n = math.sqrt(sum(c * c for c in SUN_DIR))
    return [c / n for c in SUN_DIR]


def sun_radiance():
    """The sun's radiance for an irradiance of pi at normal incidence."""
    return math.pi / (2 * math.pi * (1 - math.cos(math.radians(SUN_RADIUS))))


def make(out):
    make_folder(out, 48, 96, {"texcc": 1, "sources": [], "nodes": [], "materials": {
        n: {"bsdf": "principled", "baseColor": c, "roughness": r, "metallic": m,
            "specular": s} for n, (c, r, m, s) in MATERIALS.items()}})
    for n in MATERIALS:
        for lighting in LIGHTINGS:
            if lighting == "furnace":
                lights, depth = [{"type": "sky", "radiance": [1, 1, 1]}], 8
            else:
                lights, depth = [{"type": "sun", "direction": sun_direction(),
                                  "radiance": [sun_radiance()] * 3,
                                  "angularRadius": SUN_RADIUS}], 2
            write_json(os.path.join(out, "%s-%s.json" % (n, lighting)), {
                "texrender": 1,
                "camera": {"position": [0, 0, DIST], "target": [0, 0, 0], "up": [0, 1, 0],
                           "fov": FOV},
                "render": {"maxDepth": depth},
                "lights": lights,
                "meshes": [{"obj": "sphere.obj", "material": n}]})


def ring_means(img):
    import numpy as np
    cos = cos_wo(SIZE)
    return [img[(cos >= lo) & (cos < hi)].mean(axis=0).tolist() for lo, hi in RINGS]


def check(out):
    import numpy as np
    with open(REFERENCE) as f:
        ref = json.load(f)
    ok = True
    for n in MATERIALS:
        for lighting in LIGHTINGS:
            img = read_image(os.path.join(out, "%s-%s.exr" % (n, lighting)))
            img = np.asarray(img[0] if isinstance(img, tuple) else img)[..., :3]
            got = ring_means(img)
            for (lo, hi), g, c in zip(RINGS, got, ref["%s-%s" % (n, lighting)]):
                err = max(abs(a / b - 1) for a, b in zip(g, c))
                good = err <= TOLERANCE
                ok &= good
                print("%-21s %-7s cos wo %.2f-%.2f: %.4f %.4f %.4f  Cycles %.4f %.4f %.4f  "
                      "worst %+.2f%% %s" % (n, lighting, lo, hi, *g, *c, 100 * err,
                                            "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


def cycles(out):
    import bpy
    import numpy as np
    from texcc_tools.testing.cycles_render import render_npy
    ref = {"_": "Cycles 5.0.1 (bpy), %d spp, %dx%d, seed 1: per case-lighting, the mean linear RGB "
                "of the pixels in each ring of cos wo %s (principled_cycles.py cycles)"
                % (CYCLES_SPP, SIZE, SIZE, list(RINGS))}
    os.makedirs(out, exist_ok=True)
    for n, (colour, rough, metal, spec) in MATERIALS.items():
        for lighting in LIGHTINGS:
            bpy.ops.wm.read_factory_settings(use_empty=True)
            scene = bpy.context.scene
            scene.render.engine = "CYCLES"
            scene.render.resolution_x = scene.render.resolution_y = SIZE
            scene.view_settings.view_transform = "Standard"
            c = scene.cycles
            c.use_light_tree = c.use_guiding = False
            c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
            c.blur_glossy = 0.0
            bounces = 6 if lighting == "furnace" else 0
            c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces
            world = bpy.data.worlds.new("W")
            world.use_nodes = True
            bg = world.node_tree.nodes["Background"]
            bg.inputs["Color"].default_value = (1, 1, 1, 1) if lighting == "furnace" else \
                (0, 0, 0, 1)
            scene.world = world
            if lighting == "sun":
                sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
                r = math.radians(SUN_RADIUS)
                sun.data.energy = sun_radiance() * 2 * math.pi * (1 - math.cos(r))
                sun.data.angle = 2 * r
                d = sun_direction()  # the light shines along its local -Z: -Z = -d
                sun.rotation_mode = "QUATERNION"
                from mathutils import Vector
                sun.rotation_quaternion = Vector(d).to_track_quat("Z", "Y")
                scene.collection.objects.link(sun)
            bpy.ops.mesh.primitive_uv_sphere_add(segments=96, ring_count=48, radius=1.0)
            obj = bpy.context.active_object
            obj.data.shade_smooth()
            m = bpy.data.materials.new(n)
            m.use_nodes = True
            p = m.node_tree.nodes["Principled BSDF"]
            p.inputs["Base Color"].default_value = colour + [1]
            p.inputs["Roughness"].default_value = rough
            p.inputs["Metallic"].default_value = metal
            p.inputs["Specular IOR Level"].default_value = spec
            obj.data.materials.append(m)
            cam = bpy.data.objects.new("C", bpy.data.cameras.new("C"))
            cam.location = (0, 0, DIST)  # looks down -Z, up +Y: texrender's camera
            cam.data.sensor_fit, cam.data.sensor_width = "HORIZONTAL", 36.0
            cam.data.lens = 18.0 / math.tan(math.radians(FOV) / 2)
            scene.collection.objects.link(cam)
            scene.camera = cam
            path = os.path.join(out, "%s-%s" % (n, lighting))
            render_npy(scene, CYCLES_SPP, path + ".cycles.exr", path + ".npy")
            ref["%s-%s" % (n, lighting)] = ring_means(np.load(path + ".npy")[..., :3])
    with open(REFERENCE, "w") as f:
        json.dump(ref, f, indent=1)
    return 0


if __name__ == "__main__":
    main({"make": make, "check": check, "cycles": cycles})
