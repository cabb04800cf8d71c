"""Writes a .blend for bench/coldstart.py: a sphere on a plane under a sun and a sky, the sphere
with a 10-node Principled material with Bump (Texture Coordinate, Mapping, Noise -> Color Ramp
for the base colour, Voronoi -> Map Range for the roughness, a second Noise -> Math -> Bump for
the normal, Principled BSDF, Material Output), the plane grey. Run with .venv's Python (bpy):

    .venv/bin/python bench/inputs/principled_bump_blend.py OUT.blend
"""
import math
import sys

import bpy


def node(tree, kind, name, **inputs):
    n = tree.nodes.new(kind)
    n.name = n.label = name
    for key, value in inputs.items():
        n.inputs[key.replace("_", " ")].default_value = value
    return n


def material():
    m = bpy.data.materials.new("painted")
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    out = t.nodes.new("ShaderNodeOutputMaterial")
    coord = node(t, "ShaderNodeTexCoord", "Coordinates")
    space = node(t, "ShaderNodeMapping", "Space")
    space.inputs["Scale"].default_value = (1.5, 1.5, 1.5)
    t.links.new(coord.outputs["Object"], space.inputs["Vector"])
    colour = node(t, "ShaderNodeTexNoise", "Colour", Scale=3.0, Detail=5.0, Roughness=0.6)
    colour.noise_dimensions = "3D"
    t.links.new(space.outputs["Vector"], colour.inputs["Vector"])
    ramp = node(t, "ShaderNodeValToRGB", "Paint")
    ramp.color_ramp.elements[0].color = (0.05, 0.12, 0.35, 1.0)
    ramp.color_ramp.elements[1].color = (0.85, 0.55, 0.20, 1.0)
    t.links.new(colour.outputs["Fac"], ramp.inputs["Fac"])
    cells = node(t, "ShaderNodeTexVoronoi", "Cells", Scale=6.0, Randomness=1.0)
    cells.voronoi_dimensions = "3D"
    t.links.new(space.outputs["Vector"], cells.inputs["Vector"])
    rough = node(t, "ShaderNodeMapRange", "Roughness")
    rough.clamp = True
    for key, value in (("From Min", 0.0), ("From Max", 1.0), ("To Min", 0.25), ("To Max", 0.7)):
        rough.inputs[key].default_value = value
    t.links.new(cells.outputs["Distance"], rough.inputs["Value"])
    dents = node(t, "ShaderNodeTexNoise", "Dents", Scale=12.0, Detail=3.0, Roughness=0.5)
    dents.noise_dimensions = "3D"
    t.links.new(space.outputs["Vector"], dents.inputs["Vector"])
    height = node(t, "ShaderNodeMath", "Height")
    height.operation = "MULTIPLY"
    height.inputs[1].default_value = 0.8
    t.links.new(dents.outputs["Fac"], height.inputs[0])
    bump = node(t, "ShaderNodeBump", "Bump", Strength=0.5, Distance=0.05)
    t.links.new(height.outputs["Value"], bump.inputs["Height"])
    bsdf = node(t, "ShaderNodeBsdfPrincipled", "Principled", Metallic=0.2)
    t.links.new(ramp.outputs["Color"], bsdf.inputs["Base Color"])
    t.links.new(rough.outputs["Result"], bsdf.inputs["Roughness"])
    t.links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    t.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


def main():
    out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else sys.argv[1]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 16
    c = scene.cycles
    # What the exporter accepts (scripts/blender_export.py; examples/blender/make_scene.py).
    c.use_light_tree = False
    c.use_guiding = False
    c.use_denoising = False
    c.use_adaptive_sampling = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    scene.view_settings.view_transform = "Standard"
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = 2
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = 2
    scene.render.resolution_x = scene.render.resolution_y = 256
    scene.render.resolution_percentage = 100
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.28, 0.36, 0.5, 1.0)
    scene.world = world
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(40), 0.0, math.radians(30))
    scene.collection.objects.link(sun)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.location = (0.0, -4.0, 1.6)
    cam.rotation_euler = (math.radians(72), 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, location=(0.0, 0.0, 1.0), segments=48,
                                         ring_count=24)
    bpy.context.active_object.data.materials.append(material())
    bpy.ops.mesh.primitive_plane_add(size=8.0)
    grey = bpy.data.materials.new("grey")
    grey.use_nodes = True
    grey.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.45, 0.45, 0.45, 1.0)
    bpy.context.active_object.data.materials.append(grey)
    bpy.ops.wm.save_as_mainfile(filepath=out)


main()
