"""ao_coplanar_cycles.py: Cycles' AO node on ao-coplanar's two coincident quads (issue 22).

    .venv/bin/python testsuite/Inputs/blender-export/ao_coplanar_cycles.py [OUT.exr]

Builds ao-coplanar/scene.json's scene in bpy (quads A, x -1..0.5, and B, x -0.5..1, both in the
plane z = 0; an Emission of an AO node, 8 samples, distance 0.7; camera 2 above, looking down,
53.13 degrees across x; no lights, a black world), renders it with Cycles (CPU, 16 spp, box
filter 1 px) and prints the mean of each quarter of the 32x16 image, left to right. With Cycles
5.0.1: 1.0, 0.0, 0.0, 1.0: where the quads overlap every AO ray is occluded, since it starts on
the hit point (tmin 0, its own triangle skipped) and the other quad's face passes through it.
ao-coplanar.test expects the same of texrender.
"""
import math
import sys

import bpy
import numpy as np


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "/tmp/ao_coplanar_cycles.exr"
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device, c.samples, c.use_denoising, c.use_adaptive_sampling = "CPU", 16, False, False
    c.pixel_filter_type, c.filter_width = "BOX", 1.0
    scene.render.resolution_x, scene.render.resolution_y = 32, 16
    scene.render.resolution_percentage = 100
    scene.world = bpy.data.worlds.new("World")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    m = bpy.data.materials.new("AO")
    m.use_nodes = True
    t = m.node_tree
    t.nodes.clear()
    ao = t.nodes.new("ShaderNodeAmbientOcclusion")
    ao.samples = 8
    ao.inputs["Distance"].default_value = 0.7
    emission = t.nodes.new("ShaderNodeEmission")
    output = t.nodes.new("ShaderNodeOutputMaterial")
    t.links.new(ao.outputs["AO"], emission.inputs["Color"])
    t.links.new(emission.outputs["Emission"], output.inputs["Surface"])
    for name, x0, x1 in (("A", -1.0, 0.5), ("B", -0.5, 1.0)):
        mesh = bpy.data.meshes.new(name)
        mesh.from_pydata([(x0, -1, 0), (x1, -1, 0), (x1, 1, 0), (x0, 1, 0)], [], [(0, 1, 2, 3)])
        mesh.materials.append(m)
        scene.collection.objects.link(bpy.data.objects.new(name, mesh))
    cam = bpy.data.cameras.new("Camera")
    cam.sensor_fit, cam.angle = "HORIZONTAL", math.radians(53.13010235415598)
    obj = bpy.data.objects.new("Camera", cam)
    obj.location = (0.0, 0.0, 2.0)
    scene.collection.objects.link(obj)
    scene.camera = obj
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(out)
    px = np.array(img.pixels[:]).reshape(16, 32, 4)[::-1, :, 0]
    print("quarters:", ", ".join("%.4f" % px[:, 8 * i:8 * i + 8].mean() for i in range(4)))


if __name__ == "__main__":
    main()
