"""check_table.py: the exporter's node table against the Blender conformance fixtures.

    check_table.py FIXTURE_DIR

Each fixture (testsuite/Inputs/blender/<variant>.json, made by scripts/blender_conformance.py)
names a Blender node with its settings and, per output, the library function and the arguments
that reproduce Cycles' values. This builds that node with bpy, feeds the same inputs from the
Geometry node's Position, translates each output with the exporter, and checks the function and
every argument that is not fed from the position (settings, constants, ramps, curve tables) equal
the fixture's. A fixture's *Incoming function (Fresnel, Layer Weight: the bake's incoming
direction as an argument) is the exporter's function of the same name without it (ViewDir). Prints one line per mismatch, then "N outputs of M variants: K mismatches".
"""
import argparse
import glob
import json
import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
from texcc_tools.blender import export as blender_export
from texcc_tools.blender.conformance import set_curve_mapping

OBJECT_ARGS = {"bboxMin", "bboxMax", "axisX", "axisY", "axisZ"}  # the object's, not the node's


def socket_named(sockets, key):
    for s in sockets:
        if s.identifier == key:
            return s
    return next(s for s in sockets if s.name == key and s.enabled)


def build(tree, node_spec, image=None):
    tree.nodes.clear()
    node = tree.nodes.new(node_spec["type"])
    for key, value in node_spec["inputs"].items():
        socket_named(node.inputs, key).default_value = value
    for key, value in node_spec["properties"].items():
        setattr(node, key, value)
    setup = node_spec.get("setup")
    if setup and "stops" in setup:  # a Color Ramp's stops and modes
        ramp = node.color_ramp
        ramp.interpolation = setup["interpolation"]
        ramp.color_mode = setup.get("color_mode", "RGB")
        ramp.hue_interpolation = setup.get("hue_interpolation", "NEAR")
        while len(ramp.elements) < len(setup["stops"]):
            ramp.elements.new(0.5)
        for element, stop in zip(ramp.elements, setup["stops"]):
            element.position = stop[0]
            element.color = stop[1:]
    if setup and "curves" in setup:  # a curve mapping's points, handles and extension
        set_curve_mapping(node, setup["curves"], setup["extend"], setup.get("use_clip", True))
    position = tree.nodes.new("ShaderNodeNewGeometry").outputs["Position"]
    emission = tree.nodes.new("ShaderNodeEmission")
    for key in node_spec["fed_from_position"]:
        if key == "alpha":  # the Alpha output in use (blender_conformance.py)
            above = tree.nodes.new("ShaderNodeMath")
            tree.links.new(node.outputs["Alpha"], above.inputs[0])
            tree.links.new(above.outputs[0], emission.inputs["Strength"])
            continue
        tree.links.new(position, socket_named(node.inputs, key))
    if image is not None:  # an Image Texture fixture's image (its pixels do not matter here)
        name = "fixture-%s-%dx%d" % (image["colorspace"], image["width"], image["height"])
        node.image = bpy.data.images.get(name) or bpy.data.images.new(
            name, image["width"], image["height"], float_buffer=image["float"])
        node.image.colorspace_settings.name = image["colorspace"]
    return node, emission


def same(a, b):
    if isinstance(a, list) or isinstance(b, list):
        return isinstance(a, list) and isinstance(b, list) and len(a) == len(b) and \
            all(same(x, y) for x, y in zip(a, b))
    return abs(float(a) - float(b)) <= 1e-6 * max(1.0, abs(float(b)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fixtures")
    args = ap.parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    options = argparse.Namespace(lenient=False)
    export = blender_export.Export(bpy, options)
    material = bpy.data.materials.new("probe")
    outputs = variants = bad = 0
    for path in sorted(glob.glob(os.path.join(args.fixtures, "*.json"))):
        with open(path) as f:
            fixture = json.load(f)
        if "node" not in fixture:
            continue
        variants += 1
        for output in fixture["outputs"]:
            outputs += 1
            node, emission = build(material.node_tree, fixture["node"], fixture.get("image"))
            nodes = []
            tr = blender_export.MaterialTranslator(export, material, "m", None, nodes)
            out = socket_named(node.outputs, output["socket"])
            value = tr.output_value(node, out, emission, emission.inputs["Color"])
            got = next(n for n in nodes if n["id"] == value[1])
            where = "%s %s" % (fixture["variant"], output["socket"])
            fn, drop = output["fn"], set(output.get("drop", []))
            if fn.endswith("Incoming"):  # the fixture's incoming direction is ViewDir's
                fn, drop = fn[:-len("Incoming")], drop | {"incoming"}
            if fn == "blNormalMapFrame":  # the fixture's frame is the hit's attributes'
                fn, drop = "blNormalMap", drop | {"normal", "tangent", "tangentSign",
                                                  "backfacing"}
            if got["fn"] != fn:
                print("%s: function %s, fixture %s" % (where, got["fn"], output["fn"]))
                bad += 1
                continue
            want = {k: v for k, v in fixture["args"].items() if k not in drop}
            if set(want) != set(got["args"]):
                print("%s: arguments %s, fixture %s" % (where, sorted(got["args"]), sorted(want)))
                bad += 1
                continue
            for key, expected in want.items():
                if key in OBJECT_ARGS or (isinstance(expected, str) and expected.startswith("P")):
                    continue
                if expected == "IMAGE":  # the fixture's image: bound by the exporter
                    if not (isinstance(got["args"][key], dict) and "image" in got["args"][key]):
                        print("%s: %s = %s, fixture an image" % (where, key, got["args"][key]))
                        bad += 1
                    continue
                if not same(got["args"][key], expected):
                    print("%s: %s = %s, fixture %s" % (where, key, got["args"][key], expected))
                    bad += 1
    print("%d outputs of %d variants: %d mismatches" % (outputs, variants, bad))
    sys.exit(1 if bad else 0)


main()
