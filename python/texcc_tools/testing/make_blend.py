"""make_blend.py: small .blend files for the exporter's tests (bpy; run with .venv's Python).

    make_blend.py OUT.blend [CASE]

CASE "scene" (default): a camera, a sun, a uniform world, a ground plane with a grey diffuse, a
subdivided cube (a Subdivision Surface modifier: the exporter applies it) whose material mixes a
diffuse coloured by Noise -> Color Ramp with a glossy by the noise's Fac (Mix Shader), and an
emissive quad. The other cases break one thing each, for the error tests:
"no-camera", "empty" (a camera and nothing to render), "unsupported-node" (a Sky Texture feeds the
cube's colour), "loop" (two Math nodes feed each other), "point-light". CASE "ao": an Ambient
Occlusion node (4 samples, distance 0.7) times the noise drives the Mix Shader; "ao-conflict":
also the ground's colour through a second AO node with another distance; "principled-coat": the
ground is a Principled BSDF with Coat Weight 0.5 (an input the renderer does not have);
"ggx-distribution": the ground's Principled BSDF and the cube's Glossy BSDF set to GGX (not
Blender's default Multiscatter GGX);
"render-settings": the cube's Subdivision renders at level 2 (viewport 1), the panel is hidden in
renders only; "texture-only": the cube alone, its ramp's colour through an Emission shader, no
lights, a black world, 128x96, a 100 mm lens (the texture's values, compared with Cycles per
8x8 block); "name-clash": the cube is named "a b" and the ground "a_b" (one file name for both
once sanitised); "group": the cube's Noise and Color Ramp sit in a node group "NoiseRamp"
whose Scale input (3.0 on the group node) feeds the Noise's Scale, and whose Color and Fac outputs
feed the Diffuse BSDF and the Mix Shader; "options": the cube moves from z 0 (frame 1) to z 1
(frame 10), a second camera "Side" looks along +Y, and a second scene "Other" (32x32) holds
"Side", the sun and the ground; "world-texture": a Sky Texture feeds the world's Background; "instances": the cube is
also instanced twice through a collection, at x -1.5 and +1.5, y +1; "principled": the ground is
a Principled BSDF (Base Color 0.2 0.3 0.4, Metallic 0.5, Roughness 0.3, Specular IOR Level 0.7)
whose Roughness comes from the cube's kind of Noise through a Map Range; "ao-spread": no lights,
a black world, 128x96, the ground and the cube both an Emission of an AO node (8 samples,
distance 0.7) through a Map Range smoothstep from 0.45 to 0.75 (issue 22: the block means
depend on the spread of the AO node's 8-ray estimate, not only on its mean).
"""
import sys

import bpy


def material_rust(name):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    out = t.nodes.new("ShaderNodeOutputMaterial")
    noise = t.nodes.new("ShaderNodeTexNoise")
    noise.name = "Noise"
    noise.inputs["Scale"].default_value = 3.0
    noise.inputs["Detail"].default_value = 4.0
    ramp = t.nodes.new("ShaderNodeValToRGB")
    ramp.name = "Ramp"
    ramp.color_ramp.elements[0].position = 0.35
    ramp.color_ramp.elements[0].color = (0.6, 0.25, 0.08, 1.0)
    ramp.color_ramp.elements[1].position = 0.65
    ramp.color_ramp.elements[1].color = (0.3, 0.3, 0.32, 1.0)
    diffuse = t.nodes.new("ShaderNodeBsdfDiffuse")
    glossy = t.nodes.new("ShaderNodeBsdfGlossy")
    glossy.inputs["Roughness"].default_value = 0.3
    glossy.inputs["Color"].default_value = (0.9, 0.9, 0.9, 1.0)
    mix = t.nodes.new("ShaderNodeMixShader")
    t.links.new(noise.outputs["Fac"], ramp.inputs["Fac"])
    t.links.new(ramp.outputs["Color"], diffuse.inputs["Color"])
    t.links.new(noise.outputs["Fac"], mix.inputs["Fac"])
    t.links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    t.links.new(glossy.outputs["BSDF"], mix.inputs[2])
    t.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return m, t, ramp, diffuse


def simple(name, bl_idname, color, strength=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    out = t.nodes.new("ShaderNodeOutputMaterial")
    node = t.nodes.new(bl_idname)
    node.inputs["Color"].default_value = color
    if strength is not None:
        node.inputs["Strength"].default_value = strength
    t.links.new(node.outputs[0], out.inputs["Surface"])
    return m


def ambient_occlusion(tree, name, samples, distance):
    ao = tree.nodes.new("ShaderNodeAmbientOcclusion")
    ao.name = name
    ao.samples = samples
    ao.inputs["Distance"].default_value = distance
    return ao


def add_mesh(name, mesh, material):
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    mesh.materials.append(material)
    return obj


def quad(name, size, z, flip=False):
    s = size / 2.0
    mesh = bpy.data.meshes.new(name)
    face = (0, 1, 2, 3) if not flip else (3, 2, 1, 0)
    mesh.from_pydata([(-s, -s, z), (s, -s, z), (s, s, z), (-s, s, z)], [], [face])
    uv = mesh.uv_layers.new(name="UV")
    for loop, coord in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        uv.data[loop].uv = coord
    return mesh


def cube_mesh():
    mesh = bpy.data.meshes.new("cube")
    v = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0.0, 1.0)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(v, [], faces)
    return mesh


def group_noise_ramp(tree, ramp):
    """Moves the Noise and the Ramp into a node group; returns the group node."""
    group = bpy.data.node_groups.new("NoiseRamp", "ShaderNodeTree")
    group.interface.new_socket("Scale", in_out="INPUT", socket_type="NodeSocketFloat")
    group.interface.new_socket("Color", in_out="OUTPUT", socket_type="NodeSocketColor")
    group.interface.new_socket("Fac", in_out="OUTPUT", socket_type="NodeSocketFloat")
    g_in = group.nodes.new("NodeGroupInput")
    g_out = group.nodes.new("NodeGroupOutput")
    noise = group.nodes.new("ShaderNodeTexNoise")
    noise.name = "Noise"
    noise.inputs["Detail"].default_value = 4.0
    inner = group.nodes.new("ShaderNodeValToRGB")
    inner.name = "Ramp"
    for a, b in zip(inner.color_ramp.elements, ramp.color_ramp.elements):
        a.position, a.color = b.position, b.color
    group.links.new(g_in.outputs["Scale"], noise.inputs["Scale"])
    group.links.new(noise.outputs["Fac"], inner.inputs["Fac"])
    group.links.new(inner.outputs["Color"], g_out.inputs["Color"])
    group.links.new(noise.outputs["Fac"], g_out.inputs["Fac"])
    node = tree.nodes.new("ShaderNodeGroup")
    node.node_tree = group
    node.name = "NoiseRamp"
    node.inputs["Scale"].default_value = 3.0
    diffuse = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeBsdfDiffuse")
    mix = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeMixShader")
    tree.links.new(node.outputs["Color"], diffuse.inputs["Color"])
    tree.links.new(node.outputs["Fac"], mix.inputs["Fac"])
    tree.nodes.remove(tree.nodes["Noise"])
    tree.nodes.remove(ramp)
    return node


def reproducible(scene):
    """The render settings texrender reproduces (docs/blender.md, "Render settings"): the
    exporter refuses the others (Blender's defaults include several)."""
    scene.view_settings.view_transform = "Standard"
    c = scene.cycles
    c.use_denoising = c.use_adaptive_sampling = c.use_light_tree = False
    c.pixel_filter_type, c.filter_width = "BOX", 1.0
    c.sample_clamp_direct = c.sample_clamp_indirect = c.blur_glossy = 0.0
    c.diffuse_bounces = c.glossy_bounces = c.max_bounces


def new_scene(width, height, samples, max_bounces=6, color=None, strength=None):
    """An empty Cycles scene of width x height pixels at `samples`, with the settings
    texrender reproduces (reproducible) and a world whose Background has the colour and strength
    given (Blender's defaults where None). Returns the scene; its world is scene.world."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.cycles.samples = samples
    scene.cycles.max_bounces = max_bounces
    reproducible(scene)
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    if color is not None:
        background.inputs["Color"].default_value = color
    if strength is not None:
        background.inputs["Strength"].default_value = strength
    scene.world = world
    return scene


def main():
    out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else sys.argv[1]
    args = sys.argv[sys.argv.index(out) + 1:]
    case = args[0] if args else "scene"
    scene = new_scene(64, 48, 16, color=(0.2, 0.25, 0.3, 1.0), strength=1.0)
    world = scene.world
    if case == "world-texture":
        sky = world.node_tree.nodes.new("ShaderNodeTexSky")
        world.node_tree.links.new(sky.outputs["Color"],
                                  world.node_tree.nodes["Background"].inputs["Color"])
    if case != "no-camera":
        cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
        cam.data.lens = 35.0
        cam.location = (3.0, -3.0, 2.2)
        cam.rotation_euler = (1.15, 0.0, 0.785398)
        scene.collection.objects.link(cam)
        scene.camera = cam
    if case == "empty":
        bpy.ops.wm.save_as_mainfile(filepath=out)
        return
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.data.angle = 0.00918
    sun.rotation_euler = (0.6, 0.2, 0.4)
    scene.collection.objects.link(sun)
    if case == "point-light":
        lamp = bpy.data.objects.new("Lamp", bpy.data.lights.new("Lamp", "POINT"))
        scene.collection.objects.link(lamp)
    rust, tree, ramp, diffuse = material_rust("Rust")
    if case == "group":
        group_noise_ramp(tree, ramp)
    if case == "unsupported-node":
        sky = tree.nodes.new("ShaderNodeTexSky")
        sky.name = "Sky"
        tree.links.new(sky.outputs["Color"], diffuse.inputs["Color"])
    if case == "loop":
        a = tree.nodes.new("ShaderNodeMath")
        a.name = "MathA"
        b = tree.nodes.new("ShaderNodeMath")
        b.name = "MathB"
        tree.links.new(a.outputs[0], b.inputs[0])
        tree.links.new(b.outputs[0], a.inputs[0])
        tree.links.new(a.outputs[0], ramp.inputs["Fac"])
    if case in ("ao", "ao-conflict"):
        ao = ambient_occlusion(tree, "AO", 4, 0.7)
        times = tree.nodes.new("ShaderNodeMath")
        times.name = "Times"
        times.operation = "MULTIPLY"
        tree.links.new(ao.outputs["AO"], times.inputs[0])
        tree.links.new(tree.nodes["Noise"].outputs["Fac"], times.inputs[1])
        mix = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeMixShader")
        tree.links.new(times.outputs[0], mix.inputs["Fac"])
    grey = simple("Grey", "ShaderNodeBsdfDiffuse", (0.5, 0.5, 0.5, 1.0))
    if case == "ao-conflict":
        ao = ambient_occlusion(grey.node_tree, "Ground AO", 4, 1.5)
        bsdf = next(n for n in grey.node_tree.nodes if n.bl_idname == "ShaderNodeBsdfDiffuse")
        grey.node_tree.links.new(ao.outputs["Color"], bsdf.inputs["Color"])
    if case == "principled":
        grey = bpy.data.materials.new("Metal")
        tree = grey.node_tree
        principled = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeBsdfPrincipled")
        principled.inputs["Base Color"].default_value = (0.2, 0.3, 0.4, 1.0)
        principled.inputs["Metallic"].default_value = 0.5
        principled.inputs["Specular IOR Level"].default_value = 0.7
        noise = tree.nodes.new("ShaderNodeTexNoise")
        noise.inputs["Scale"].default_value = 2.0
        to_roughness = tree.nodes.new("ShaderNodeMapRange")
        to_roughness.inputs["To Min"].default_value = 0.2
        to_roughness.inputs["To Max"].default_value = 0.6
        tree.links.new(noise.outputs["Fac"], to_roughness.inputs["Value"])
        tree.links.new(to_roughness.outputs["Result"], principled.inputs["Roughness"])
    if case == "ggx-distribution":
        grey = bpy.data.materials.new("PlainGGX")
        tree = grey.node_tree
        principled = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeBsdfPrincipled")
        principled.distribution = "GGX"
        glossy = rust.node_tree.nodes["Glossy BSDF"]
        glossy.distribution = "GGX"
    if case == "principled-coat":
        grey = bpy.data.materials.new("Coated")
        tree = grey.node_tree
        principled = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeBsdfPrincipled")
        principled.inputs["Coat Weight"].default_value = 0.5
    add_mesh("Ground", quad("ground", 6.0, 0.0), grey)
    cube = add_mesh("Cube", cube_mesh(), rust)
    cube.location = (0.2, 0.1, 0.0)
    cube.rotation_euler = (0.0, 0.0, 0.5)
    sub = cube.modifiers.new("Subdivision", "SUBSURF")
    sub.levels = sub.render_levels = 1
    lamp = add_mesh("Panel", quad("panel", 1.0, 2.5, flip=True),
                    simple("Light", "ShaderNodeEmission", (1.0, 0.9, 0.8, 1.0), 5.0))
    lamp.location = (-1.0, 0.5, 0.0)
    if case == "options":
        cube.keyframe_insert("location", frame=1)
        cube.location.z = 1.0
        cube.keyframe_insert("location", frame=10)
        scene.frame_set(1)
        side = bpy.data.objects.new("Side", bpy.data.cameras.new("Side"))
        side.location = (0.0, -6.0, 1.0)
        side.rotation_euler = (1.5707963, 0.0, 0.0)
        scene.collection.objects.link(side)
        other = bpy.data.scenes.new("Other")
        other.render.resolution_x = other.render.resolution_y = 32
        other.world = scene.world
        for obj in (side, sun, scene.objects["Ground"]):
            other.collection.objects.link(obj)
        other.camera = side
        reproducible(other)
    if case == "instances":
        props = bpy.data.collections.new("Props")
        props.objects.link(cube)
        scene.collection.children.link(props)
        for i, x in enumerate((-1.5, 1.5)):
            empty = bpy.data.objects.new("Instance%d" % i, None)
            empty.instance_type = "COLLECTION"
            empty.instance_collection = props
            empty.location = (x, 1.0, 0.0)
            scene.collection.objects.link(empty)
    if case == "name-clash":
        cube.name, scene.objects["Ground"].name = "a b", "a_b"
    if case == "texture-only":
        for obj in (lamp, sun, scene.objects["Ground"]):
            bpy.data.objects.remove(obj)
        scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
        scene.render.resolution_x, scene.render.resolution_y = 128, 96
        scene.camera.data.lens = 100.0  # the cube fills most of the frame
        emission = tree.nodes.new("ShaderNodeEmission")
        tree.links.new(ramp.outputs["Color"], emission.inputs["Color"])
        output = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial")
        tree.links.new(emission.outputs["Emission"], output.inputs["Surface"])
    if case == "ao-spread":
        # Issue 22: the AO node's 8-ray estimate through a smoothstep, on the ground and the
        # cube, as an Emission with no lights: the block means depend on how the estimate
        # spreads, not only on its mean.
        for obj in (lamp, sun):
            bpy.data.objects.remove(obj)
        scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
        scene.render.resolution_x, scene.render.resolution_y = 128, 96
        cam.location = (1.5, -1.9, 0.9)  # close to the cube's foot: the ground's AO varies
        cam.rotation_euler = (1.2, 0.0, 0.6)
        spread = bpy.data.materials.new("AOSpread")
        spread.use_nodes = True
        t = spread.node_tree
        t.nodes.clear()
        output = t.nodes.new("ShaderNodeOutputMaterial")
        ao = ambient_occlusion(t, "AO", 8, 0.7)
        step = t.nodes.new("ShaderNodeMapRange")
        step.name = "Step"
        step.interpolation_type = "SMOOTHSTEP"
        step.inputs["From Min"].default_value = 0.45
        step.inputs["From Max"].default_value = 0.75
        emission = t.nodes.new("ShaderNodeEmission")
        t.links.new(ao.outputs["AO"], step.inputs["Value"])
        t.links.new(step.outputs["Result"], emission.inputs["Color"])
        t.links.new(emission.outputs["Emission"], output.inputs["Surface"])
        for obj in (cube, scene.objects["Ground"]):
            obj.data.materials[0] = spread
    if case == "render-settings":
        sub.render_levels = 2
        lamp.hide_render = True
    bpy.ops.wm.save_as_mainfile(filepath=out)
