"""texture_nodes.py: the .blend of export-texture-nodes.test and its Cycles reference (bpy; run
with .venv's Python).

    texture_nodes.py OUT.blend            writes the scene
    texture_nodes.py OUT.blend refusals   writes the scene of the refused cases (make_refusals)
    texture_nodes.py OUT.blend bumped     writes the scene with a Bump into Fresnel's and Layer
                                          Weight's Normal (make_bumped)
    texture_nodes.py --reference bumped   its reference: cycles-texture-nodes-bumped.json
    texture_nodes.py --reference [--spp N] renders it with Cycles (cycles_render.py) and writes
                                          cycles-texture-nodes.json (region_means.py --write
                                          --edges: 8x8 block means, silhouette blocks marked)

The scene: a smooth UV sphere seen by a camera, no lights, a black world, 128x96, an Emission
material that uses the texture-side nodes of issue 37 item 3, each on what Cycles gives it while
rendering: Layer Weight (Blend 0.35, Normal unlinked: the shading normal) Facing plus the sphere's
Object z through Vector Curves (Extend Extrapolated) picks a colour of a Color Ramp in HSV mode
(Far hue interpolation); RGB Curves (C and R bent) then a Mix by Layer Weight's Fresnel towards
green make the Color; Fresnel (IOR 1.45) through a Float Curve (0 -> 0.4, 1 -> 2.5) is the
Strength. Fresnel and Layer Weight read the incoming direction (texrender's ViewDir) and the
normal, so the image checks them where the fixtures (a bake, one incoming direction) cannot.
"""
import os
import subprocess
import sys
import tempfile

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
from texcc_tools.testing.make_blend import new_scene  # noqa: E402


def ident(sockets, identifier):
    return next(s for s in sockets if s.identifier == identifier)


def curve(mapping, index, points, extend="EXTRAPOLATED"):
    mapping.extend = extend
    c = mapping.curves[index]
    while len(c.points) < len(points):
        c.points.new(0.5, 0.5)
    for point, (x, y) in zip(c.points, points):
        point.location = (x, y)
    mapping.update()


def material():
    m = bpy.data.materials.new("Nodes")
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    new = t.nodes.new
    out = new("ShaderNodeOutputMaterial")
    weight = new("ShaderNodeLayerWeight")
    weight.name = "Weight"
    weight.inputs["Blend"].default_value = 0.35
    coords = new("ShaderNodeTexCoord")
    vcurves = new("ShaderNodeVectorCurve")
    vcurves.name = "VCurves"
    curve(vcurves.mapping, 2, [(-1.0, -0.6), (0.0, 0.2), (1.0, 0.4)])
    separate = new("ShaderNodeSeparateXYZ")
    add = new("ShaderNodeMath")
    add.operation = "ADD"
    ramp = new("ShaderNodeValToRGB")
    ramp.name = "Ramp"
    ramp.color_ramp.color_mode = "HSV"
    ramp.color_ramp.hue_interpolation = "FAR"
    ramp.color_ramp.elements[0].position = 0.1
    ramp.color_ramp.elements[0].color = (0.9, 0.15, 0.1, 1.0)
    ramp.color_ramp.elements[1].position = 0.9
    ramp.color_ramp.elements[1].color = (0.1, 0.2, 0.85, 1.0)
    rgb = new("ShaderNodeRGBCurve")
    rgb.name = "RGBCurves"
    curve(rgb.mapping, 3, [(0.0, 0.0), (0.4, 0.6), (1.0, 1.0)])
    curve(rgb.mapping, 0, [(0.0, 0.1), (1.0, 0.8)])
    mix = new("ShaderNodeMix")
    mix.data_type = "RGBA"
    ident(mix.inputs, "B_Color").default_value = (0.1, 0.8, 0.2, 1.0)
    fresnel = new("ShaderNodeFresnel")
    fresnel.name = "Fresnel"
    fresnel.inputs["IOR"].default_value = 1.45
    fcurve = new("ShaderNodeFloatCurve")
    fcurve.name = "FCurve"
    curve(fcurve.mapping, 0, [(0.0, 0.4), (0.5, 1.2), (1.0, 2.5)])
    emission = new("ShaderNodeEmission")
    link = t.links.new
    link(coords.outputs["Object"], vcurves.inputs["Vector"])
    link(vcurves.outputs["Vector"], separate.inputs["Vector"])
    link(weight.outputs["Facing"], add.inputs[0])
    link(separate.outputs["Z"], add.inputs[1])
    link(add.outputs["Value"], ramp.inputs["Fac"])
    link(ramp.outputs["Color"], rgb.inputs["Color"])
    link(rgb.outputs["Color"], ident(mix.inputs, "A_Color"))
    link(weight.outputs["Fresnel"], ident(mix.inputs, "Factor_Float"))
    link(ident(mix.outputs, "Result_Color"), emission.inputs["Color"])
    link(fresnel.outputs["Fac"], fcurve.inputs["Value"])
    link(fcurve.outputs["Value"], emission.inputs["Strength"])
    link(emission.outputs["Emission"], out.inputs["Surface"])
    return m


def make(path):
    scene = new_scene(128, 96, 16, strength=0.0)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.location = (0.0, -4.0, 0.0)
    cam.rotation_euler = (1.5707963, 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=1.0)
    sphere = bpy.context.active_object
    sphere.name = "Sphere"
    bpy.ops.object.shade_smooth()
    sphere.data.materials.append(material())
    bpy.ops.wm.save_as_mainfile(filepath=path)


def make_bumped(path):
    """The scene with Fresnel's and Layer Weight's Normal from a Bump node (a Noise height,
    Strength 0.4, Distance 0.05) instead of the shading normal."""
    make(path)
    t = bpy.data.objects["Sphere"].data.materials[0].node_tree
    noise = t.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 4.0
    bump = t.nodes.new("ShaderNodeBump")
    bump.name = "Bump"
    bump.inputs["Strength"].default_value = 0.4
    bump.inputs["Distance"].default_value = 0.05
    t.links.new(noise.outputs["Fac"], bump.inputs["Height"])
    for name in ("Weight", "Fresnel"):
        t.links.new(bump.outputs["Normal"], t.nodes[name].inputs["Normal"])
    bpy.ops.wm.save_as_mainfile(filepath=path)


def make_refusals(path):
    """The scene whose texture nodes the exporter refuses, each once: the sphere's colour from an
    Attribute node reading a colour attribute "Col", its strength from one reading the second
    UV map "Second" (not the render one), a Bump's Normal into Fresnel's IOR, and a cube whose
    Object Info Random is its colour, instanced by a collection instance "Copies"."""
    make(path)
    sphere = bpy.data.objects["Sphere"]
    sphere.data.color_attributes.new("Col", "FLOAT_COLOR", "POINT")
    sphere.data.uv_layers.new(name="Second")
    sphere.data.uv_layers[0].active_render = True
    t = sphere.data.materials[0].node_tree
    emission = next(n for n in t.nodes if n.bl_idname == "ShaderNodeEmission")
    colour = t.nodes.new("ShaderNodeAttribute")
    colour.name, colour.attribute_name = "Colour", "Col"
    t.links.new(colour.outputs["Color"], emission.inputs["Color"])
    second = t.nodes.new("ShaderNodeAttribute")
    second.name, second.attribute_name = "SecondUV", "Second"
    t.links.new(second.outputs["Fac"], emission.inputs["Strength"])
    copies = bpy.data.collections.new("Copied")
    bpy.context.scene.collection.children.link(copies)
    mesh = bpy.data.meshes.new("cube")
    mesh.from_pydata([(0, 0, 0), (0.3, 0, 0), (0, 0.3, 0)], [], [(0, 1, 2)])
    cube = bpy.data.objects.new("Cube", mesh)
    copies.objects.link(cube)
    m = bpy.data.materials.new("Random")
    m.use_nodes = True
    info = m.node_tree.nodes.new("ShaderNodeObjectInfo")
    info.name = "Info"
    diffuse = m.node_tree.nodes["Principled BSDF"]
    m.node_tree.links.new(info.outputs["Random"], diffuse.inputs["Base Color"])
    bump = m.node_tree.nodes.new("ShaderNodeBump")  # a bumped normal as a roughness
    bump.name = "Bump"
    m.node_tree.links.new(bump.outputs["Normal"], diffuse.inputs["Roughness"])
    mesh.materials.append(m)
    empty = bpy.data.objects.new("Copies", None)
    empty.instance_type, empty.instance_collection = "COLLECTION", copies
    empty.location = (0.0, 0.0, 1.2)
    bpy.context.scene.collection.objects.link(empty)
    bpy.ops.wm.save_as_mainfile(filepath=path)


def reference(spp, case):
    from texcc_tools.testing.cycles_render import render_npy
    work = tempfile.mkdtemp()
    blend = os.path.join(work, "nodes.blend")
    (make_bumped if case == "bumped" else make)(blend)
    exr = blend + ".exr"
    render_npy(bpy.context.scene, spp, exr, exr + ".npy", True)
    expected = os.path.join(HERE, "cycles-texture-nodes%s.json" % ("-bumped" if case else ""))
    subprocess.check_call([sys.executable, os.path.join(HERE, "region_means.py"), exr + ".npy",
                           expected, "--write", "--edges"])
    print("texture_nodes: %s (%d spp)" % (expected, spp))


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    if argv[:1] == ["--reference"]:
        reference(int(argv[argv.index("--spp") + 1]) if "--spp" in argv else 1024,
                  "bumped" if "bumped" in argv else "")
    elif argv[1:2] == ["refusals"]:
        make_refusals(argv[0])
    elif argv[1:2] == ["bumped"]:
        make_bumped(argv[0])
    else:
        make(argv[0])
