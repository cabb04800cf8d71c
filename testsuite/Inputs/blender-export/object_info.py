"""object_info.py: Object Info and Attribute through the exporter against Cycles (bpy 5.0.1).

    object_info.py

Four planes with their own names (one not ASCII), locations, Object Colors, Pass Indices and
materials (their own Pass Index), each with an Emission of one output of an Object Info node
(Location, Color, Alpha, Object Index, Material Index, Random) or of an Attribute node that
reads the render UV map "UVMap" (Vector, Fac, Alpha; each plane has a second UV map): Cycles
bakes each (a 1x1 image: one texel per plane), the exporter translates the same node on the same
object, and the constant it passes (Object Info) or what its function makes of TexCoord0
(Attribute: Cycles' Texture Coordinate UV baked at the same texel) must equal Cycles' value. Prints one line per output with the largest error over the planes,
then "object info: N of M outputs within 1e-6 of Cycles".
"""
import argparse
import os
import sys

import bpy
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
from texcc_tools.blender import export as blender_export

PLANES = [("Plane", (0.0, 0.0, 0.0), (1.0, 1.0, 1.0, 1.0), 0, 0),
          ("Würfel.001", (1.5, -2.25, 0.75), (0.2, 0.6, 0.9, 0.4), 3, 7),
          ("rock_17", (-4.0, 2.0, 10.5), (0.9, 0.1, 0.3, 1.0), 12, 1),
          ("a", (0.25, 0.5, -0.125), (0.0, 0.0, 0.0, 0.0), 1, 255)]
OUTPUTS = [("ShaderNodeObjectInfo", "Location", 3), ("ShaderNodeObjectInfo", "Color", 3),
           ("ShaderNodeObjectInfo", "Alpha", 1), ("ShaderNodeObjectInfo", "Object Index", 1),
           ("ShaderNodeObjectInfo", "Material Index", 1), ("ShaderNodeObjectInfo", "Random", 1),
           ("ShaderNodeAttribute", "Vector", 3), ("ShaderNodeAttribute", "Fac", 1),
           ("ShaderNodeAttribute", "Alpha", 1)]


def plane(name, location, color, pass_index, material_index):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)], [],
                     [(0, 1, 2, 3)])
    uv = mesh.uv_layers.new(name="UVMap")
    for loop, coord in enumerate([(0.1, 0.2), (0.7, 0.2), (0.7, 0.9), (0.1, 0.9)]):
        uv.data[loop].uv = coord
    mesh.uv_layers.new(name="Second")  # another UV map: not the render one
    obj = bpy.data.objects.new(name, mesh)
    obj.location, obj.color, obj.pass_index = location, color, pass_index
    bpy.context.scene.collection.objects.link(obj)
    material = bpy.data.materials.new("M" + name)
    material.pass_index = material_index
    mesh.materials.append(material)
    return obj, material


def bake(obj, material, idname, output):
    """Cycles' value of `output` at the plane's one texel (a 1x1 bake; the node is made
    anew, so bake the exporter's node before anything else)."""
    tree = material.node_tree
    tree.nodes.clear()
    node = tree.nodes.new(idname)
    if idname == "ShaderNodeAttribute":
        node.attribute_name = "UVMap"
    emission = tree.nodes.new("ShaderNodeEmission")
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(node.outputs[output], emission.inputs["Color"])
    tree.links.new(emission.outputs["Emission"], out.inputs["Surface"])
    target = tree.nodes.new("ShaderNodeTexImage")
    target.image = bpy.data.images.get("bake") or bpy.data.images.new(
        "bake", 1, 1, float_buffer=True)
    target.image.colorspace_settings.name = "Non-Color"
    tree.nodes.active = target
    for o in bpy.context.scene.objects:
        o.select_set(o == obj)
    bpy.context.view_layer.objects.active = obj
    bpy.ops.object.bake(type="EMIT")
    pixels = np.empty(4, np.float32)
    target.image.pixels.foreach_get(pixels)
    return node, emission, pixels[:3]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-v", action="store_true", help="print each object's values")
    ap.parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device, scene.cycles.samples = "CPU", 1
    scene.render.bake.margin = 0
    objects = [plane(*p) for p in PLANES]
    for obj, material in objects:
        material.use_nodes = True
    export = blender_export.Export(bpy, argparse.Namespace(lenient=False))
    good = 0
    for idname, output, channels in OUTPUTS:
        worst = 0.0
        for obj, material in objects:
            node, emission, cycles = bake(obj, material, idname, output)
            nodes = []
            translator = blender_export.MaterialTranslator(export, material, "m", obj, nodes)
            value = translator.output_value(node, node.outputs[output], emission,
                                            emission.inputs["Color"])
            graph = next(n for n in nodes if n["id"] == value[1])
            args = list(graph["args"].values())
            if idname == "ShaderNodeAttribute":  # TexCoord0: Cycles' UV where it baked
                uv = bake(obj, material, "ShaderNodeTexCoord", "UV")[2]
                got = {"Vector": [uv[0], uv[1], 0.0], "Fac": [uv[0]] * 3,
                       "Alpha": [1.0] * 3}[output]
                if graph["fn"] != {"Vector": "blAttributeUV", "Fac": "blAttributeUVFac",
                                   "Alpha": "blAttributeUVAlpha"}[output]:
                    got = [float("nan")] * 3
            else:
                got = args[0] if isinstance(args[0], list) else [args[0]] * 3
            if "-v" in sys.argv:
                print("  %s: texcc %s, Cycles %s" % (obj.name, got[:channels], cycles[:channels]))
            worst = max([worst] + [abs(float(g) - float(c)) for g, c in
                                   zip(got[:channels], cycles[:channels])])
        ok = worst <= 1e-6
        good += ok
        print("%s: %s %s: max abs error %.3g over %d objects" % (
            "OK" if ok else "FAIL", idname[len("ShaderNode"):], output, worst, len(objects)))
    if export.problems.errors:
        print("\n".join(export.problems.errors))
    print("object info: %d of %d outputs within 1e-06 of Cycles" % (good, len(OUTPUTS)))
    sys.exit(0 if good == len(OUTPUTS) and not export.problems.errors else 1)


main()
