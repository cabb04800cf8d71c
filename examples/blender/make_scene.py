#!/usr/bin/env python3
"""make_scene.py: the atrium (examples/atrium) as a .blend, exactly as texrender sees it.

    python examples/blender/make_scene.py OUT.blend [--variant diffuse|rust-model|rust-all|
        scratches-model] [--scene examples/atrium/scene.json] [--spp N] [--size WxH]

Runs with the bpy wheel (bpy==5.0.1, installed into .venv/ on first use, like
scripts/blender_conformance.py) or inside Blender (`blender -b --python make_scene.py -- OUT.blend`).

What it reads, what it writes:
- Geometry: the OBJ files scene.json names (examples/atrium/generated/*.obj, made by
  `python3 scripts/make_scenes.py --only atrium`; they carry normals), imported without axis
  conversion, so each object's local coordinates are the OBJ's own (texrender's ObjectPos = Blender's
  Object texture coordinate). The y-up to z-up change is in each object's matrix:
  M_blender = C * M_texrender with C: (x, y, z) -> (x, -z, y) (+90 degrees about X).
- Camera: position/target/up as a rotation; `fov` over `fovAxis` (x, y, smaller) as a 36 mm sensor
  with the matching sensor fit and lens = 18 / tan(fov / 2).
- Sun: texrender's disc of radiance R and half-angle r is Blender's sun of irradiance
  R * 2 pi (1 - cos r) (strength = the largest channel, colour = the ratio), angle 2r.
- Sky: the world's Background colour = the sky radiance, strength 1.
- Render: Cycles, CPU, no denoising, no adaptive sampling, box filter 1 px, no clamping, light
  tree and path guiding off; max_bounces = maxDepth - 2 (texrender's maxDepth has Mitsuba's meaning:
  2 = direct light only = Cycles' 0 bounces); diffuse/glossy bounces the same.
- Materials (--variant): "diffuse": every mesh the gray diffuse (0.45). "rust-model": the model
  rusty, the rest gray. "rust-all": every mesh rusty. "scratches-model": the model scratched.
  The rust and scratches node trees are Blender versions of examples/rust and examples/scratches
  built from nodes textures/blender/ implements (docs/blender-nodes.md): see rust() and scratches().
- --texture-only: the texture alone, for issue 22's per-block check (bench/cycles.py
  --texture-only): the model's material colour (each BSDF's Color, Mix Shaders as a colour Mix by
  the same Fac) through an Emission shader of strength 1; no sun, a black world; the other meshes
  keep their diffuse, which is black without light (and still occludes the AO node's rays). The
  Bump and Normal inputs drop out: this view checks what the texture computes, not the shading.
  The camera keeps its direction and moves towards the model until its bounding sphere's radius
  is 0.75 of the half-view, so that many 8x8 blocks lie wholly on the gears.
  --texture-probe ao | ao-squared | constant-ao (rust): the AO node's AO output alone through
  the Emission, its square, or the colour with the AO node replaced by a constant 0.5 (bisecting issue 22's rust blocks).
"""

import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
try:
    from texcc_tools.bpy_env import ensure_bpy  # the project's package (scripts/setup.sh)
except ImportError:  # another Python than .venv's: re-run with it
    _venv = os.path.join(ROOT, ".venv", "bin", "python")
    if os.path.realpath(sys.prefix) == os.path.realpath(os.path.join(ROOT, ".venv")):
        sys.exit("make_scene.py: error: texcc_tools is not installed in .venv: run scripts/setup.sh")
    os.execv(_venv, [_venv] + sys.argv)
VARIANTS = ("diffuse", "rust-model", "rust-all", "scratches-model")


# --- Coordinates -------------------------------------------------------------------------------

def to_blender(v):
    """A point or direction of texrender's y-up world in Blender's z-up world."""
    return (v[0], -v[2], v[1])


def texrender_matrix(transform):
    """texrender's mesh transform (docs/scene.md) as a 4x4 row-major list."""
    if transform is None:
        return [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    if "matrix" in transform:
        m = transform["matrix"]
        return [list(m[4 * i:4 * i + 4]) for i in range(4)] if len(m) == 16 else m
    s = transform.get("scale", [1, 1, 1])
    a = math.radians(transform.get("rotateY", 0.0))
    t = transform.get("translate", [0, 0, 0])
    c, n = math.cos(a), math.sin(a)
    # scale, then rotate about y, then translate
    return [[c * s[0], 0, n * s[2], t[0]],
            [0, s[1], 0, t[1]],
            [-n * s[0], 0, c * s[2], t[2]],
            [0, 0, 0, 1]]


# --- Materials ---------------------------------------------------------------------------------

def new_material(bpy, name):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    out = t.nodes.new("ShaderNodeOutputMaterial")
    out.name = "Output"
    return m, t, out


def node(tree, kind, name, **inputs):
    n = tree.nodes.new(kind)
    n.name = n.label = name
    for key, value in inputs.items():
        n.inputs[key.replace("_", " ")].default_value = value
    return n


def gray(bpy):
    m, t, out = new_material(bpy, "gray")
    d = node(t, "ShaderNodeBsdfDiffuse", "Diffuse", Color=(0.45, 0.45, 0.45, 1.0))
    t.links.new(d.outputs["BSDF"], out.inputs["Surface"])
    return m


def rust(bpy, ao_samples, ao_distance):
    """examples/rust in Blender nodes. Patches: a Noise Texture (Object coordinates, scale 2.2,
    detail 4, roughness 0.55) mapped to [0, 1] by Map Range; grain: a finer Noise (scale 14);
    tone: their mix (0.45) through a 6-stop Color Ramp (the example's stops). Mask: coverage
    0.5 (1 - AO) + 0.5 patches (AO node: 8 samples, distance 0.5, the scene's aoSamples and
    aoDistance) through Map Range's smoothstep from 0.28 to 0.44. Shader: Mix Shader of the clean
    metal (Diffuse 0.5) and the rust (Diffuse, the ramp's colour) by the mask."""
    m, t, out = new_material(bpy, "rusty")
    coord = node(t, "ShaderNodeTexCoord", "Coordinates")
    patches = node(t, "ShaderNodeTexNoise", "Patches", Scale=2.2, Detail=4.0, Roughness=0.55,
                   Lacunarity=2.0)
    patches.noise_dimensions = "3D"
    t.links.new(coord.outputs["Object"], patches.inputs["Vector"])
    patches01 = node(t, "ShaderNodeMapRange", "Patches01")
    patches01.interpolation_type = "LINEAR"
    patches01.clamp = True
    for key, value in (("From Min", 0.3), ("From Max", 0.7), ("To Min", 0.0), ("To Max", 1.0)):
        patches01.inputs[key].default_value = value
    t.links.new(patches.outputs["Fac"], patches01.inputs["Value"])
    grain = node(t, "ShaderNodeTexNoise", "Grain", Scale=14.0, Detail=3.0, Roughness=0.5,
                 Lacunarity=2.1)
    grain.noise_dimensions = "3D"
    t.links.new(coord.outputs["Object"], grain.inputs["Vector"])
    tone = node(t, "ShaderNodeMix", "Tone")
    tone.data_type = "FLOAT"
    tone.inputs["Factor"].default_value = 0.45
    t.links.new(patches01.outputs["Result"], tone.inputs["A"])
    t.links.new(grain.outputs["Fac"], tone.inputs["B"])
    ramp = node(t, "ShaderNodeValToRGB", "RustColor")
    ramp.color_ramp.interpolation = "LINEAR"
    stops = [(0.00, 0.060, 0.028, 0.016), (0.25, 0.180, 0.060, 0.022),
             (0.45, 0.380, 0.130, 0.040), (0.62, 0.560, 0.240, 0.070),
             (0.80, 0.300, 0.120, 0.045), (1.00, 0.150, 0.075, 0.040)]
    elements = ramp.color_ramp.elements
    while len(elements) < len(stops):
        elements.new(0.5)
    for e, (pos, r, g, b) in zip(elements, stops):
        e.position = pos
        e.color = (r, g, b, 1.0)
    t.links.new(tone.outputs["Result"], ramp.inputs["Fac"])
    ao = t.nodes.new("ShaderNodeAmbientOcclusion")
    ao.name = ao.label = "AO"
    ao.samples = ao_samples
    ao.only_local = False
    ao.inside = False
    ao.inputs["Distance"].default_value = ao_distance
    exposed = node(t, "ShaderNodeMath", "Occlusion")
    exposed.operation = "SUBTRACT"
    exposed.inputs[0].default_value = 1.0
    t.links.new(ao.outputs["AO"], exposed.inputs[1])
    coverage = node(t, "ShaderNodeMix", "Coverage")
    coverage.data_type = "FLOAT"
    coverage.inputs["Factor"].default_value = 0.5
    t.links.new(exposed.outputs["Value"], coverage.inputs["A"])
    t.links.new(patches01.outputs["Result"], coverage.inputs["B"])
    mask = node(t, "ShaderNodeMapRange", "Mask")
    mask.interpolation_type = "SMOOTHSTEP"
    mask.clamp = True
    for key, value in (("From Min", 0.28), ("From Max", 0.44), ("To Min", 0.0), ("To Max", 1.0)):
        mask.inputs[key].default_value = value
    t.links.new(coverage.outputs["Result"], mask.inputs["Value"])
    clean = node(t, "ShaderNodeBsdfDiffuse", "Clean", Color=(0.5, 0.5, 0.5, 1.0))
    rusty = node(t, "ShaderNodeBsdfDiffuse", "Rust")
    t.links.new(ramp.outputs["Color"], rusty.inputs["Color"])
    mix = node(t, "ShaderNodeMixShader", "Blend")
    t.links.new(mask.outputs["Result"], mix.inputs["Fac"])
    t.links.new(clean.outputs["BSDF"], mix.inputs[1])
    t.links.new(rusty.outputs["BSDF"], mix.inputs[2])
    t.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return m


def scratches(bpy):
    """examples/scratches in Blender nodes. Two families of scratch lines: Object coordinates
    through a Mapping (rotation about the local y axis, then a stretch of 14 and 9 along one axis),
    a Voronoi Texture's Distance to Edge (scale 9 and 13), turned into thin lines by Map Range
    (1 at the edge, 0 at width 0.07 / 0.06) and thinned where a Noise Texture (scale 3) is low
    (Map Range of the noise times the lines); the two families combined by Maximum. The mask
    picks the scratch (Diffuse 0.85) over the brushed metal (Glossy 0.55, roughness 0.2) and,
    through a Bump node (strength 0.4, distance 0.02, inverted: scratches are grooves), tilts
    both BSDFs' normals."""
    m, t, out = new_material(bpy, "scratched")
    coord = node(t, "ShaderNodeTexCoord", "Coordinates")
    where = node(t, "ShaderNodeTexNoise", "Where", Scale=3.0, Detail=0.0)
    where.noise_dimensions = "3D"
    t.links.new(coord.outputs["Object"], where.inputs["Vector"])
    lines = []
    for label, angle, stretch, scale, width, density in (("A", 0.5, 14.0, 9.0, 0.07, 0.55),
                                                         ("B", 2.2, 9.0, 13.0, 0.06, 0.45)):
        space = node(t, "ShaderNodeMapping", "Space" + label)
        space.vector_type = "POINT"
        space.inputs["Rotation"].default_value = (0.0, angle, 0.0)
        space.inputs["Scale"].default_value = (1.0, 1.0, stretch)
        t.links.new(coord.outputs["Object"], space.inputs["Vector"])
        vor = node(t, "ShaderNodeTexVoronoi", "Edge" + label, Scale=scale, Randomness=1.0)
        vor.voronoi_dimensions = "3D"
        vor.feature = "DISTANCE_TO_EDGE"
        t.links.new(space.outputs["Vector"], vor.inputs["Vector"])
        line = node(t, "ShaderNodeMapRange", "Line" + label)
        line.interpolation_type = "LINEAR"
        line.clamp = True
        for key, value in (("From Min", 0.0), ("From Max", width), ("To Min", 1.0),
                           ("To Max", 0.0)):
            line.inputs[key].default_value = value
        t.links.new(vor.outputs["Distance"], line.inputs["Value"])
        keep = node(t, "ShaderNodeMapRange", "Density" + label)
        keep.interpolation_type = "SMOOTHSTEP"
        keep.clamp = True
        for key, value in (("From Min", 1.0 - density - 0.05), ("From Max", 1.0 - density + 0.05),
                           ("To Min", 0.0), ("To Max", 1.0)):
            keep.inputs[key].default_value = value
        t.links.new(where.outputs["Fac"], keep.inputs["Value"])
        both = node(t, "ShaderNodeMath", "Lines" + label)
        both.operation = "MULTIPLY"
        t.links.new(line.outputs["Result"], both.inputs[0])
        t.links.new(keep.outputs["Result"], both.inputs[1])
        lines.append(both)
    mask = node(t, "ShaderNodeMath", "Mask")
    mask.operation = "MAXIMUM"
    t.links.new(lines[0].outputs["Value"], mask.inputs[0])
    t.links.new(lines[1].outputs["Value"], mask.inputs[1])
    bump = node(t, "ShaderNodeBump", "Bump", Strength=0.4, Distance=0.02)
    bump.invert = True
    t.links.new(mask.outputs["Value"], bump.inputs["Height"])
    metal = node(t, "ShaderNodeBsdfGlossy", "Metal", Color=(0.55, 0.55, 0.57, 1.0),
                 Roughness=0.2)
    scratch = node(t, "ShaderNodeBsdfDiffuse", "Scratch", Color=(0.85, 0.84, 0.82, 1.0))
    t.links.new(bump.outputs["Normal"], metal.inputs["Normal"])
    t.links.new(bump.outputs["Normal"], scratch.inputs["Normal"])
    mix = node(t, "ShaderNodeMixShader", "Blend")
    t.links.new(mask.outputs["Value"], mix.inputs["Fac"])
    t.links.new(metal.outputs["BSDF"], mix.inputs[1])
    t.links.new(scratch.outputs["BSDF"], mix.inputs[2])
    t.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return m


def material_colour(t, socket):
    """(link output or None, constant RGBA): the colour of the shader feeding socket: a BSDF's
    Color, a Mix Shader as a colour Mix (RGBA, same Fac) of its two shaders' colours."""
    if not socket.is_linked:
        return None, (0.0, 0.0, 0.0, 1.0)
    n = socket.links[0].from_node
    if n.bl_idname == "ShaderNodeMixShader":
        mix = node(t, "ShaderNodeMix", n.name + "Colour")
        mix.data_type = "RGBA"
        mix.blend_type = "MIX"
        mix.clamp_factor = True
        fac = n.inputs["Fac"]
        if fac.is_linked:
            t.links.new(fac.links[0].from_socket, mix.inputs["Factor"])
        else:
            mix.inputs["Factor"].default_value = fac.default_value
        for shader, ident in ((n.inputs[1], "A_Color"), (n.inputs[2], "B_Color")):
            target = next(s for s in mix.inputs if s.identifier == ident)
            link, value = material_colour(t, shader)
            if link is not None:
                t.links.new(link, target)
            else:
                target.default_value = value
        return mix.outputs["Result"], None
    colour = n.inputs["Color"] if "Color" in n.inputs else n.inputs["Base Color"]
    if colour.is_linked:
        return colour.links[0].from_socket, None
    return None, tuple(colour.default_value)


def texture_only(m, probe=None):
    """The material's colour through an Emission shader (strength 1), in place of its surface.
    probe (rust only, issue 22's bisection): "ao": the AO node's AO output instead of the
    colour; "ao-squared": its square (with "ao": the spread of the 8-ray estimate);
    "constant-ao": the colour, with the AO node's output replaced by a constant 0.5
    (the Occlusion node's input), so that the mask depends on the patches alone."""
    t = m.node_tree
    out = t.nodes["Output"]
    link, value = material_colour(t, out.inputs["Surface"])
    if probe is not None and "AO" not in t.nodes:
        sys.exit("make_scene: --texture-probe is for the rust material (it has the AO node)")
    if probe == "ao":
        link, value = t.nodes["AO"].outputs["AO"], None
    elif probe == "ao-squared":
        square = node(t, "ShaderNodeMath", "AOSquared")
        square.operation = "MULTIPLY"
        t.links.new(t.nodes["AO"].outputs["AO"], square.inputs[0])
        t.links.new(t.nodes["AO"].outputs["AO"], square.inputs[1])
        link, value = square.outputs["Value"], None
    elif probe == "constant-ao":
        occlusion = t.nodes["Occlusion"]
        t.links.remove(occlusion.inputs[1].links[0])
        occlusion.inputs[1].default_value = 0.5
        t.nodes.remove(t.nodes["AO"])
    em = node(t, "ShaderNodeEmission", "TextureOnly", Strength=1.0)
    if link is not None:
        t.links.new(link, em.inputs["Color"])
    else:
        em.inputs["Color"].default_value = value
    t.links.new(em.outputs["Emission"], out.inputs["Surface"])
    return m


# --- Scene -------------------------------------------------------------------------------------

def import_obj(bpy, path, name):
    if path.endswith(".gz"):
        sys.exit("make_scene: %s: gzip-compressed OBJ is not supported here" % path)
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    new = [o for o in bpy.data.objects if o not in before]
    if len(new) != 1:
        sys.exit("make_scene: %s: expected one object, got %d" % (path, len(new)))
    obj = new[0]
    obj.name = obj.data.name = name
    return obj


def build(args):
    import bpy
    import mathutils

    with open(args.scene) as f:
        scene_json = json.load(f)
    base = os.path.dirname(os.path.abspath(args.scene))
    render = scene_json.get("render", {})
    film = scene_json.get("film", {})
    width, height = film.get("width", 256), film.get("height", 256)
    if args.size:
        width, height = (int(v) for v in args.size.lower().split("x"))

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.name = "atrium"
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp if args.spp else render.get("spp", 16)
    c.use_denoising = False
    c.use_adaptive_sampling = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.use_light_tree = False
    c.use_guiding = False
    c.seed = render.get("seed", 1)
    depth = render.get("maxDepth", 8)
    bounces = max(depth - 2, 0) if depth >= 0 else 1024
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = bounces
    c.blur_glossy = 0.0
    scene.render.threads_mode = "AUTO"

    # Camera
    cam_json = scene_json.get("camera", {})
    pos = mathutils.Vector(to_blender(cam_json.get("position", [0, 0, 1])))
    target = mathutils.Vector(to_blender(cam_json.get("target", [0, 0, 0])))
    up = mathutils.Vector(to_blender(cam_json.get("up", [0, 1, 0])))
    forward = (target - pos).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    rot = mathutils.Matrix((right, true_up, -forward)).transposed()
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.matrix_world = mathutils.Matrix.Translation(pos) @ rot.to_4x4()
    fov = math.radians(cam_json.get("fov", 40.0))
    axis = cam_json.get("fovAxis", "smaller")
    if axis == "smaller":
        axis = "x" if width <= height else "y"
    cam.data.sensor_fit = "HORIZONTAL" if axis == "x" else "VERTICAL"
    cam.data.sensor_width = cam.data.sensor_height = 36.0
    cam.data.lens = 18.0 / math.tan(fov / 2.0)
    cam.data.clip_start = 1e-3
    cam.data.clip_end = 1e4
    scene.collection.objects.link(cam)
    scene.camera = cam

    # Lights
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    scene.world = world
    for i, light in enumerate(scene_json.get("lights", [])):
        if args.texture_only:
            continue  # no light: the world stays black, no sun
        if light["type"] == "sky":
            r = light["radiance"]
            bg.inputs["Color"].default_value = (r[0], r[1], r[2], 1.0)
        elif light["type"] == "sun":
            r = light["radiance"]
            half = math.radians(light.get("angularRadius", 0.27))
            irradiance = [v * 2.0 * math.pi * (1.0 - math.cos(half)) for v in r]
            strength = max(irradiance)
            sun = bpy.data.objects.new("Sun%d" % i if i else "Sun",
                                       bpy.data.lights.new("Sun", "SUN"))
            sun.data.energy = strength
            sun.data.color = tuple(v / strength for v in irradiance)
            sun.data.angle = 2.0 * half
            d = mathutils.Vector(to_blender(light["direction"])).normalized()
            sun.rotation_mode = "QUATERNION"
            sun.rotation_quaternion = d.to_track_quat("Z", "Y")  # the sun shines along its -Z
            scene.collection.objects.link(sun)
        else:
            sys.exit("make_scene: light %d: type %r is not supported" % (i, light["type"]))

    # Materials and meshes
    mats = {"gray": gray(bpy)}
    if args.variant in ("rust-model", "rust-all"):
        mats["rusty"] = rust(bpy, render.get("aoSamples", 8), render.get("aoDistance", 0.5))
    if args.variant == "scratches-model":
        mats["scratched"] = scratches(bpy)
    model_material = {"diffuse": "gray", "rust-model": "rusty", "rust-all": "rusty",
                      "scratches-model": "scratched"}[args.variant]
    other_material = "rusty" if args.variant == "rust-all" else "gray"
    if args.texture_only:
        if args.variant == "rust-all":
            sys.exit("make_scene: --texture-only is for the model's material (rust-model, "
                     "scratches-model, diffuse)")
        model = mats[model_material].copy()
        model.name = model_material + "-texture-only"
        mats[model_material] = texture_only(model, args.texture_probe)
    conv = mathutils.Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    for mesh in scene_json["meshes"]:
        path = os.path.join(base, mesh["obj"])
        name = os.path.splitext(os.path.basename(path))[0]
        obj = import_obj(bpy, path, name)
        obj.matrix_world = conv @ mathutils.Matrix(texrender_matrix(mesh.get("transform")))
        is_model = name == "model"
        mat = mats[model_material if is_model else other_material]
        obj.data.materials.clear()
        obj.data.materials.append(mat)
        if "emission" in mesh:
            sys.exit("make_scene: %s: emissive meshes are not supported here" % mesh["obj"])
    if args.texture_only:
        # Frame the model (the camera keeps its direction): 8x8 blocks wholly on it are what
        # the per-block check compares, and in the atrium's view the gears hold few of them.
        model = bpy.data.objects["model"]
        corners = [model.matrix_world @ mathutils.Vector(c) for c in model.bound_box]
        centre = sum(corners, mathutils.Vector()) / 8.0
        radius = max((c - centre).length for c in corners)
        cam.matrix_world = mathutils.Matrix.Translation(
            centre - forward * (0.75 * radius / math.tan(fov / 2.0))) @ rot.to_4x4()
    bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.out))
    print("make_scene: %s (%s%s, %dx%d, %d spp, max_bounces %d)" %
          (args.out, args.variant, ", texture only" if args.texture_only else "", width, height,
           c.samples, bounces))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", help="the .blend to write")
    ap.add_argument("--variant", choices=VARIANTS, default="diffuse")
    ap.add_argument("--scene", default=os.path.join(ROOT, "examples", "atrium", "scene.json"),
                    help="texrender scene to rebuild (default: examples/atrium/scene.json)")
    ap.add_argument("--spp", type=int, help="Cycles samples (default: the scene's spp)")
    ap.add_argument("--size", help="WxH (default: the scene's film)")
    ap.add_argument("--texture-only", action="store_true",
                    help="the model's material colour through Emission, no lights (issue 22)")
    ap.add_argument("--texture-probe", choices=("ao", "ao-squared", "constant-ao"),
                    help="with --texture-only, rust: the AO node's output alone (ao), its square "
                    "(ao-squared), or the "
                    "colour with AO replaced by a constant 0.5 (constant-ao)")
    args = ap.parse_args(argv)
    if args.texture_probe and not args.texture_only:
        ap.error("--texture-probe needs --texture-only")
    ensure_bpy("make_scene")
    build(args)


if __name__ == "__main__":
    main()
