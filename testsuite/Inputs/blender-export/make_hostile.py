"""make_hostile.py OUT.blend: one .blend, one scene per hostile case of the exporter's tests
(issue 40 item 7, issue 37 item 4), so that one bpy launch makes them all:

"Ids": seven planes, seven materials of seven colours whose names sanitise alike in pairs
("C\\x01", "C\\x02", "C?"; "S*/x", "S*|x"; "M@Plane7", and "M" whose per-object copy would be
"M@Plane7" too), and in material "Nodes" two Math nodes named "N\\x01" and "N\\x02" (one id once
sanitised) and a node named "G/N" beside a group "G" holding a node "N" (one path).
"Deep": a chain of 1,500 Math nodes (each adds 0.0001) into a Diffuse BSDF's colour: 30
chained instances of a group of 50.
"Nan": an unlinked Math input NaN, a Value node's output NaN, an RGB node's colour NaN (Blender
clamps an infinity to the float range itself).
"Defaults": Blender's factory render settings (AgX, denoiser, adaptive sampling, Blackman-Harris
1.5 px, indirect clamp 10, light tree, Filter Glossy 1, Diffuse/Glossy bounces 4 of 12), a
Bump whose Filter Width is 0.5 in a material whose Bump Map Correction is off, a Sky Texture
feeding a colour, an object that casts no shadow (ray visibility) and a point light: every
problem at once.
"""
import sys

import bpy

from texcc_tools.testing.make_blend import reproducible  # noqa: E402  (after bpy)


def new_scene(name):
    scene = bpy.data.scenes.new(name)
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = 32, 24
    scene.cycles.samples = 4
    scene.cycles.max_bounces = 4
    reproducible(scene)
    cam = bpy.data.objects.new("Camera " + name, bpy.data.cameras.new("Camera " + name))
    cam.location = (0.0, -12.0, 6.0)
    cam.rotation_euler = (1.1, 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    return scene


def plane(scene, name, material, x):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)], [],
                     [(0, 1, 2, 3)])
    obj = bpy.data.objects.new(name, mesh)
    obj.location.x = x
    obj.data.materials.append(material)
    scene.collection.objects.link(obj)
    return obj


def diffuse(name, color):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    tree = m.node_tree
    tree.nodes.clear()
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    bsdf = tree.nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = color + (1.0,)
    tree.links.new(bsdf.outputs[0], out.inputs["Surface"])
    return m, tree, bsdf


def ids():
    scene = new_scene("Ids")
    names = ["C\x01", "C\x02", "C?", "S*/x", "S*|x", "M@Plane7", "M"]
    for k, name in enumerate(names):
        m, _, _ = diffuse(name, ((k + 1) / 8.0, 0.5, 1.0 - (k + 1) / 8.0))
        plane(scene, "Plane%d" % k, m, 1.2 * k - 4.0)
    # "M" on a second object whose Generated bounds differ: a per-object copy "M@Plane7"
    # (taken by the material of that name). A Noise reads Generated coordinates.
    m = bpy.data.materials["M"]
    noise = m.node_tree.nodes.new("ShaderNodeTexNoise")
    bsdf = next(n for n in m.node_tree.nodes if n.bl_idname == "ShaderNodeBsdfDiffuse")
    m.node_tree.links.new(noise.outputs["Color"], bsdf.inputs["Color"])
    other = plane(scene, "Plane7", m, 4.5)
    other.data.vertices[2].co.z = 2.0  # other bounds
    m, tree, bsdf = diffuse("Nodes", (0.5, 0.5, 0.5))
    a, b, g_n = (tree.nodes.new("ShaderNodeMath") for _ in range(3))
    a.name, b.name, g_n.name = "N\x01", "N\x02", "G/N"
    a.inputs[1].default_value, b.inputs[1].default_value, g_n.inputs[1].default_value = 0.1, \
        0.2, 0.3
    group = bpy.data.node_groups.new("G", "ShaderNodeTree")
    group.interface.new_socket("Value", in_out="OUTPUT", socket_type="NodeSocketFloat")
    inner = group.nodes.new("ShaderNodeMath")
    inner.name = "N"
    inner.inputs[1].default_value = 0.4
    gout = group.nodes.new("NodeGroupOutput")
    group.links.new(inner.outputs[0], gout.inputs[0])
    gnode = tree.nodes.new("ShaderNodeGroup")
    gnode.name = "G"
    gnode.node_tree = group
    combine = tree.nodes.new("ShaderNodeCombineXYZ")
    add = tree.nodes.new("ShaderNodeMath")
    add.name = "Sum"
    tree.links.new(a.outputs[0], combine.inputs[0])
    tree.links.new(b.outputs[0], combine.inputs[1])
    tree.links.new(g_n.outputs[0], add.inputs[0])
    tree.links.new(gnode.outputs[0], add.inputs[1])
    tree.links.new(add.outputs[0], combine.inputs[2])
    tree.links.new(combine.outputs[0], bsdf.inputs["Color"])
    plane(scene, "PlaneNodes", m, 0.0).location.y = 2.0


def deep():
    """1,500 chained Math nodes: 30 instances, chained, of a group of 50 (bpy takes about 15 ms
    per node, link and value set in a tree this size: a flat chain took 21 s to build)."""
    scene = new_scene("Deep")
    m, tree, bsdf = diffuse("Deep", (0.5, 0.5, 0.5))
    group = bpy.data.node_groups.new("Chain", "ShaderNodeTree")
    group.interface.new_socket("In", in_out="INPUT", socket_type="NodeSocketFloat")
    group.interface.new_socket("Out", in_out="OUTPUT", socket_type="NodeSocketFloat")
    previous = group.nodes.new("NodeGroupInput")
    for k in range(50):
        node = group.nodes.new("ShaderNodeMath")
        node.name = "Add%02d" % k
        node.inputs[1].default_value = 0.0001
        group.links.new(previous.outputs[0], node.inputs[0])
        previous = node
    group.links.new(previous.outputs[0], group.nodes.new("NodeGroupOutput").inputs[0])
    previous = None
    for k in range(30):
        instance = tree.nodes.new("ShaderNodeGroup")
        instance.name = "Chain%02d" % k
        instance.node_tree = group
        if previous is not None:
            tree.links.new(previous.outputs[0], instance.inputs[0])
        previous = instance
    tree.links.new(previous.outputs[0], bsdf.inputs["Color"])
    plane(scene, "PlaneDeep", m, 0.0)


def nan():
    scene = new_scene("Nan")
    m, tree, bsdf = diffuse("Nan", (0.5, 0.5, 0.5))
    math_node = tree.nodes.new("ShaderNodeMath")
    math_node.name = "Bad Math"
    math_node.inputs[1].default_value = float("nan")
    value = tree.nodes.new("ShaderNodeValue")
    value.name = "Bad Value"
    value.outputs[0].default_value = float("nan")
    rgb = tree.nodes.new("ShaderNodeRGB")
    rgb.name = "Bad RGB"
    rgb.outputs[0].default_value = (float("nan"), 0.5, 0.5, 1.0)
    tree.links.new(value.outputs[0], math_node.inputs[0])
    combine = tree.nodes.new("ShaderNodeMix")
    combine.data_type = "RGBA"
    tree.links.new(math_node.outputs[0], combine.inputs["Factor"])
    tree.links.new(rgb.outputs[0], combine.inputs["A"])
    tree.links.new(combine.outputs["Result"], bsdf.inputs["Color"])
    plane(scene, "PlaneNan", m, 0.0)


def defaults():
    scene = bpy.context.scene  # the factory scene: Blender's default render settings
    scene.name = "Defaults"
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = 32, 24
    cam = bpy.data.objects.new("Camera Defaults", bpy.data.cameras.new("Camera Defaults"))
    cam.location = (0.0, -12.0, 6.0)
    cam.rotation_euler = (1.1, 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    m, tree, bsdf = diffuse("Bumpy", (0.5, 0.5, 0.5))
    m.cycles.use_bump_map_correction = False
    bump = tree.nodes.new("ShaderNodeBump")
    bump.inputs["Filter Width"].default_value = 0.5
    noise = tree.nodes.new("ShaderNodeTexNoise")
    tree.links.new(noise.outputs["Fac"], bump.inputs["Height"])
    tree.links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    sky = tree.nodes.new("ShaderNodeTexSky")
    sky.name = "Sky"
    tree.links.new(sky.outputs["Color"], bsdf.inputs["Color"])
    plane(scene, "PlaneDefaults", m, 0.0).visible_shadow = False
    lamp = bpy.data.objects.new("Lamp", bpy.data.lights.new("Lamp", "POINT"))
    lamp.data.normalize = False  # texrender's lamps are normalized
    scene.collection.objects.link(lamp)


def main():
    out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else sys.argv[1]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    defaults()
    ids()
    deep()
    nan()
    bpy.ops.wm.save_as_mainfile(filepath=out)


main()
