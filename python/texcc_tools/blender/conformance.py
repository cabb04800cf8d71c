"""blender_conformance.py: golden values of Blender's shader nodes, computed by Cycles itself.

For every variant of textures/blender/ (a node with fixed settings, one or more outputs), this
script builds the node tree in Cycles (bpy, pinned below), feeds the node from the shading
point's Position (directly, or one coordinate of it through Separate XYZ), bakes each output
through an Emission shader into a float image over a tilted plane, and writes
testsuite/Inputs/blender/<variant>.json: the node's settings, the texcc function and arguments
of each output, and the baked values (little-endian float32, base64).

The positions where Cycles evaluated the node are not assumed: they are baked too (the
Geometry node's Position through the same Emission path) and written once to
testsuite/Inputs/blender/points.txt. The tests evaluate texcc at exactly those points.

    scripts/blender_conformance.py [--only NAME ...] [--size N]

On first use it installs bpy==5.0.1 into .venv/ (about 370 MB; not needed by the tests) and
re-runs itself with .venv's Python.
"""

import argparse
import json
import os
import sys
import time

from texcc_tools.blender.bake import AXIS_U, AXIS_V, ORIGIN, bake, build_variant, encode, setup_scene
from texcc_tools.blender.nodes import MATH_OPS, VECTOR_MATH_OPS
from texcc_tools.bpy_env import BPY_VERSION, ensure_bpy
from texcc_tools.paths import INPUTS

OUT = os.path.join(INPUTS, "blender")



# --- Variants -------------------------------------------------------------------------------
# A variant: name; the Blender node (bl_idname, properties, unlinked input values, and which
# inputs are fed from the position: "P" the vector, "P.x"/"P.y"/"P.z" one coordinate); the
# texcc library file; its outputs, each (Blender socket, texcc function, channels); and the
# texcc arguments (the same values; "P" and "P.x" etc. become graph references).

VARIANTS = []


def variant(name, node, props, inputs, feeds, source, outputs, args, setup=None, describe=None,
            image=None, exporter_args=()):
    """setup(node) configures what properties cannot (a ramp's stops); describe records it.
    image: the node's image, made in Blender (make_image) and written into the fixture.
    exporter_args: texcc arguments the exporter's own table (blender_nodes.NODES props)
    computes from the node once set up (a curve's table), so the fixture checks that code too.
    An argument "INCOMING" is the bake's incoming direction (baked, as the points are)."""
    VARIANTS.append(dict(name=name, node=node, props=props, inputs=inputs, feeds=feeds,
                         source=source, outputs=outputs, args=args,
                         exporter_args=list(exporter_args)))
    if setup:
        VARIANTS[-1]["setup"] = setup
        VARIANTS[-1]["describe"] = describe
    if image:
        VARIANTS[-1]["image"] = image


NOISE_TYPES = {"MULTIFRACTAL": 0, "FBM": 1, "HYBRID_MULTIFRACTAL": 2, "RIDGED_MULTIFRACTAL": 3,
               "HETERO_TERRAIN": 4}


def noise_variant(name, dims, ntype, normalize=True, scale=1.5, detail=3.0, roughness=0.5,
                  lacunarity=2.0, offset=0.0, gain=1.0, distortion=0.0, w=0.0):
    inputs = {"Scale": scale, "Detail": detail, "Roughness": roughness,
              "Lacunarity": lacunarity, "Offset": offset, "Gain": gain,
              "Distortion": distortion}
    args, feeds = {"vector": "P"}, {"Vector": "P"}
    if dims == 4:
        inputs["W"] = w
        args["w"] = w
    if dims == 1:  # the W input only, fed from the position's x
        args, feeds = {"w": "P.x"}, {"W": "P.x"}
    args.update({"scale": scale, "detail": detail, "roughness": roughness,
                 "lacunarity": lacunarity, "offset": offset, "gain": gain,
                 "distortion": distortion, "type": NOISE_TYPES[ntype],
                 "normalize": 1 if normalize else 0})
    variant(name, "ShaderNodeTexNoise",
            {"noise_dimensions": "%dD" % dims, "noise_type": ntype, "normalize": normalize},
            inputs, feeds, "noise.cl",
            [("Factor", "blNoise%dDFac" % dims, 1), ("Color", "blNoise%dDColor" % dims, 3)], args)


noise_variant("noise3d-fbm", 3, "FBM")
noise_variant("noise3d-fbm-fractional", 3, "FBM", detail=2.6, roughness=0.6, lacunarity=2.3)
noise_variant("noise3d-fbm-raw", 3, "FBM", normalize=False, detail=4.0)
noise_variant("noise3d-fbm-distortion", 3, "FBM", distortion=0.7)
noise_variant("noise3d-multifractal", 3, "MULTIFRACTAL", detail=2.5)
noise_variant("noise3d-hybrid", 3, "HYBRID_MULTIFRACTAL", detail=3.5, offset=0.5, gain=1.3)
noise_variant("noise3d-ridged", 3, "RIDGED_MULTIFRACTAL", detail=3.0, offset=1.0, gain=2.0)
noise_variant("noise3d-hetero", 3, "HETERO_TERRAIN", detail=2.5, offset=0.4)
noise_variant("noise3d-fbm-detail8", 3, "FBM", detail=8.0, scale=3.0)
noise_variant("noise2d-fbm", 2, "FBM", detail=2.5, distortion=0.3)
noise_variant("noise2d-ridged", 2, "RIDGED_MULTIFRACTAL", offset=1.0, gain=2.0)
noise_variant("noise1d-fbm", 1, "FBM", detail=3.5, distortion=0.4)
noise_variant("noise1d-hybrid", 1, "HYBRID_MULTIFRACTAL", detail=2.0, offset=0.6, gain=1.2)
noise_variant("noise4d-fbm", 4, "FBM", detail=2.5, w=0.37, distortion=0.2)
noise_variant("noise4d-hetero", 4, "HETERO_TERRAIN", detail=2.0, offset=0.3, w=-1.2)

VORONOI_FEATURES = {"F1": 0, "F2": 1, "SMOOTH_F1": 2, "DISTANCE_TO_EDGE": 3, "N_SPHERE_RADIUS": 4}
VORONOI_METRICS = {"EUCLIDEAN": 0, "MANHATTAN": 1, "CHEBYCHEV": 2, "MINKOWSKI": 3}


def voronoi_variant(name, dims, feature, metric="EUCLIDEAN", normalize=False, scale=2.5,
                    detail=0.0, roughness=0.5, lacunarity=2.0, smoothness=1.0, exponent=0.5,
                    randomness=1.0):
    inputs = {"Scale": scale, "Detail": detail, "Roughness": roughness,
              "Lacunarity": lacunarity, "Smoothness": smoothness, "Exponent": exponent,
              "Randomness": randomness}
    args = {"vector": "P", "scale": scale, "detail": detail, "roughness": roughness,
            "lacunarity": lacunarity, "smoothness": smoothness, "exponent": exponent,
            "randomness": randomness, "feature": VORONOI_FEATURES[feature],
            "metric": VORONOI_METRICS[metric], "normalize": 1 if normalize else 0}
    fn = "blVoronoi%dD" % dims
    feeds = {"Vector": "P"}
    if dims == 4:  # W fed from the position's y
        feeds["W"] = args["w"] = "P.y"
    if dims == 1:  # W only, fed from the position's x; a line has no metric (texcc takes none)
        feeds = {"W": "P.x"}
        del args["vector"], args["metric"], args["exponent"]
        args = dict({"w": "P.x"}, **args)
    if feature == "N_SPHERE_RADIUS":
        outputs = [("Radius", fn + "Radius", 1)]
    elif feature == "DISTANCE_TO_EDGE":
        outputs = [("Distance", fn + "Distance", 1)]
    elif dims == 1:
        outputs = [("Distance", fn + "Distance", 1), ("Color", fn + "Color", 3),
                   ("W", fn + "W", 1)]
    else:
        outputs = [("Distance", fn + "Distance", 1), ("Color", fn + "Color", 3),
                   ("Position", fn + "Position", 3)] + ([("W", fn + "W", 1)] if dims == 4 else [])
    variant(name, "ShaderNodeTexVoronoi",
            {"voronoi_dimensions": "%dD" % dims, "feature": feature, "distance": metric,
             "normalize": normalize}, inputs, feeds, "voronoi.cl", outputs, args)


voronoi_variant("voronoi3d-f1", 3, "F1")
voronoi_variant("voronoi3d-f1-manhattan", 3, "F1", "MANHATTAN")
voronoi_variant("voronoi3d-f1-chebychev", 3, "F1", "CHEBYCHEV")
voronoi_variant("voronoi3d-f1-minkowski", 3, "F1", "MINKOWSKI", exponent=1.5)
voronoi_variant("voronoi3d-f1-randomness", 3, "F1", randomness=0.6, normalize=True)
voronoi_variant("voronoi3d-f1-detail", 3, "F1", detail=2.5, roughness=0.6, normalize=True)
voronoi_variant("voronoi3d-f2", 3, "F2", normalize=True)
voronoi_variant("voronoi3d-smooth-f1", 3, "SMOOTH_F1", smoothness=0.6)
voronoi_variant("voronoi3d-edge", 3, "DISTANCE_TO_EDGE")
voronoi_variant("voronoi3d-edge-detail", 3, "DISTANCE_TO_EDGE", detail=1.5, normalize=True)
voronoi_variant("voronoi3d-nsphere", 3, "N_SPHERE_RADIUS")
voronoi_variant("voronoi2d-f1", 2, "F1", scale=3.0)
voronoi_variant("voronoi2d-f2-manhattan", 2, "F2", "MANHATTAN", scale=3.0)
voronoi_variant("voronoi2d-smooth-f1", 2, "SMOOTH_F1", smoothness=0.8, scale=3.0)
voronoi_variant("voronoi2d-edge", 2, "DISTANCE_TO_EDGE", scale=3.0)
voronoi_variant("voronoi2d-nsphere", 2, "N_SPHERE_RADIUS", scale=3.0)
voronoi_variant("voronoi4d-f1", 4, "F1", scale=1.5)
voronoi_variant("voronoi4d-f2-chebychev", 4, "F2", "CHEBYCHEV", scale=1.5, normalize=True)
voronoi_variant("voronoi4d-smooth-f1", 4, "SMOOTH_F1", scale=1.5, smoothness=0.5)
voronoi_variant("voronoi4d-edge", 4, "DISTANCE_TO_EDGE", scale=1.5)
voronoi_variant("voronoi4d-nsphere", 4, "N_SPHERE_RADIUS", scale=1.5)
voronoi_variant("voronoi1d-f1", 1, "F1", scale=2.0)
voronoi_variant("voronoi1d-f1-detail", 1, "F1", scale=2.0, detail=2.5, roughness=0.6,
                randomness=0.7, normalize=True)
voronoi_variant("voronoi1d-f2", 1, "F2", scale=2.0, normalize=True)
voronoi_variant("voronoi1d-smooth-f1", 1, "SMOOTH_F1", scale=2.0, smoothness=0.7)
voronoi_variant("voronoi1d-edge", 1, "DISTANCE_TO_EDGE", scale=2.0, detail=1.5, normalize=True)
voronoi_variant("voronoi1d-nsphere", 1, "N_SPHERE_RADIUS", scale=2.0, randomness=0.8)

# Cycles' NodeMathType order: textures/blender/math.cl's operation numbers.
# (MATH_OPS: scripts/blender_nodes.py, shared with the exporter.)

for number, op in enumerate(MATH_OPS):
    variant("math-" + op.lower().replace("_", "-"), "ShaderNodeMath",
            {"operation": op, "use_clamp": False}, {},
            {"Value": "P.x", "Value_001": "P.y", "Value_002": "P.z"}, "math.cl",
            [("Value", "blMath", 1)],
            {"a": "P.x", "b": "P.y", "c": "P.z", "operation": number, "useClamp": 0})
for op in ("MULTIPLY", "SINE"):
    variant("math-%s-clamp" % op.lower(), "ShaderNodeMath", {"operation": op, "use_clamp": True},
            {}, {"Value": "P.x", "Value_001": "P.y", "Value_002": "P.z"}, "math.cl",
            [("Value", "blMath", 1)],
            {"a": "P.x", "b": "P.y", "c": "P.z", "operation": MATH_OPS.index(op), "useClamp": 1})

MAP_RANGE_TYPES = ["LINEAR", "STEPPED", "SMOOTHSTEP", "SMOOTHERSTEP"]


def map_range_variant(name, interpolation, clamp, from_min=0.2, from_max=1.9, to_min=-0.5,
                      to_max=2.0, steps=3.0):
    variant(name, "ShaderNodeMapRange",
            {"data_type": "FLOAT", "interpolation_type": interpolation, "clamp": clamp},
            {"From Min": from_min, "From Max": from_max, "To Min": to_min, "To Max": to_max,
             "Steps": steps}, {"Value": "P.x"}, "math.cl", [("Result", "blMapRange", 1)],
            {"value": "P.x", "fromMin": from_min, "fromMax": from_max, "toMin": to_min,
             "toMax": to_max, "steps": steps,
             "interpolation": MAP_RANGE_TYPES.index(interpolation), "useClamp": int(clamp)})


map_range_variant("maprange-linear", "LINEAR", False)
map_range_variant("maprange-linear-clamp", "LINEAR", True)
map_range_variant("maprange-stepped-clamp", "STEPPED", True)
map_range_variant("maprange-smoothstep", "SMOOTHSTEP", False)
map_range_variant("maprange-smootherstep", "SMOOTHERSTEP", False)
map_range_variant("maprange-smoothstep-inverted", "SMOOTHSTEP", False, from_min=1.9,
                  from_max=0.2)

for name, ctype, lo, hi in (("clamp-minmax", "MINMAX", 0.1, 1.2),
                            ("clamp-range-inverted", "RANGE", 1.2, 0.1)):
    variant(name, "ShaderNodeClamp", {"clamp_type": ctype}, {"Min": lo, "Max": hi},
            {"Value": "P.x"}, "math.cl", [("Result", "blClamp", 1)],
            {"value": "P.x", "minimum": lo, "maximum": hi,
             "clampType": 0 if ctype == "MINMAX" else 1})

variant("combine-xyz", "ShaderNodeCombineXYZ", {}, {}, {"X": "P.y", "Y": "P.z", "Z": "P.x"},
        "converter.cl", [("Vector", "blCombineXYZ", 3)], {"x": "P.y", "y": "P.z", "z": "P.x"})
variant("geometry-position", "ShaderNodeNewGeometry", {}, {}, {}, "input.cl",
        [("Position", "blGeometryPosition", 3)], {})
# Texture Coordinate at the plane's points (texcc-eval sets ObjectPos to the point; the plane's
# object transform is the identity). Generated takes the mesh's bounding box, as the exporter
# passes it. UV and Normal read TexCoord0 and Normal, which texcc-eval does not set from the
# points: they have no fixture.
_CORNERS = [[ORIGIN[k] + i * AXIS_U[k] + j * AXIS_V[k] for k in range(3)]
            for i in (0, 1) for j in (0, 1)]
variant("texcoord-object", "ShaderNodeTexCoord", {}, {}, {}, "input.cl",
        [("Object", "blTexCoordObject", 3)], {})
variant("texcoord-generated", "ShaderNodeTexCoord", {}, {}, {}, "input.cl",
        [("Generated", "blTexCoordGenerated", 3)],
        {"bboxMin": [min(c[k] for c in _CORNERS) for k in range(3)],
         "bboxMax": [max(c[k] for c in _CORNERS) for k in range(3)]})

RAMP_STOPS = [(0.15, (0.9, 0.2, 0.1, 1.0)), (0.4, (0.1, 0.8, 0.3, 0.5)),
              (0.65, (0.2, 0.3, 0.9, 0.8)), (0.9, (1.0, 1.0, 0.2, 0.2))]
RAMP_MODES = ["LINEAR", "EASE", "B_SPLINE", "CARDINAL", "CONSTANT"]


def ramp_setup(mode):
    def setup(node):
        ramp = node.color_ramp
        ramp.color_mode = "RGB"
        ramp.interpolation = mode
        while len(ramp.elements) < len(RAMP_STOPS):
            ramp.elements.new(0.5)
        for element, (pos, color) in zip(ramp.elements, RAMP_STOPS):
            element.position = pos
            element.color = color
    return setup


for mode in RAMP_MODES:
    variant("colorramp-" + mode.lower().replace("_", "-"), "ShaderNodeValToRGB", {}, {},
            {"Fac": "P.x*0.3+0.35"}, "ramp.cl",
            [("Color", "blColorRampColor", 3), ("Alpha", "blColorRampAlpha", 1)],
            {"fac": "P.x*0.3+0.35", "colors": [list(c) for _, c in RAMP_STOPS],
             "positions": [p for p, _ in RAMP_STOPS], "count": len(RAMP_STOPS),
             "interpolation": RAMP_MODES.index(mode)},
            setup=ramp_setup(mode),
            describe={"interpolation": mode, "stops": [[p] + list(c) for p, c in RAMP_STOPS]})

# textures/blender/mix.cl's blend numbers: Blender's menu order.
BLEND_TYPES = ["MIX", "DARKEN", "MULTIPLY", "BURN", "LIGHTEN", "SCREEN", "DODGE", "ADD",
               "OVERLAY", "SOFT_LIGHT", "LINEAR_LIGHT", "DIFFERENCE", "EXCLUSION", "SUBTRACT",
               "DIVIDE", "HUE", "SATURATION", "COLOR", "VALUE"]
MIX_FACTOR = "P.z*0.4+0.45"
MIX_B_COLOR = (0.8, 0.3, 0.55, 1.0)

for number, blend in enumerate(BLEND_TYPES):
    variant("mix-color-" + blend.lower().replace("_", "-"), "ShaderNodeMix",
            {"data_type": "RGBA", "blend_type": blend, "clamp_factor": True,
             "clamp_result": False}, {"B_Color": MIX_B_COLOR},
            {"Factor_Float": MIX_FACTOR, "A_Color": "P"}, "mix.cl",
            [("Result_Color", "blMixColor", 3)],
            {"factor": MIX_FACTOR, "a": "P", "b": list(MIX_B_COLOR[:3]), "blendType": number,
             "clampFactor": 1, "clampResult": 0})
variant("mix-color-multiply-unclamped-clamp-result", "ShaderNodeMix",
        {"data_type": "RGBA", "blend_type": "MULTIPLY", "clamp_factor": False,
         "clamp_result": True}, {"B_Color": MIX_B_COLOR},
        {"Factor_Float": MIX_FACTOR, "A_Color": "P"}, "mix.cl", [("Result_Color", "blMixColor", 3)],
        {"factor": MIX_FACTOR, "a": "P", "b": list(MIX_B_COLOR[:3]), "blendType": 2,
         "clampFactor": 0, "clampResult": 1})
for clamp in (True, False):
    suffix = "" if clamp else "-unclamped"
    variant("mix-float" + suffix, "ShaderNodeMix", {"data_type": "FLOAT", "clamp_factor": clamp},
            {}, {"Factor_Float": MIX_FACTOR, "A_Float": "P.x", "B_Float": "P.y"}, "mix.cl",
            [("Result_Float", "blMixFloat", 1)],
            {"factor": MIX_FACTOR, "a": "P.x", "b": "P.y", "clampFactor": int(clamp)})
variant("mix-vector", "ShaderNodeMix",
        {"data_type": "VECTOR", "factor_mode": "UNIFORM", "clamp_factor": True},
        {"B_Vector": (0.5, -1.0, 2.0)}, {"Factor_Float": MIX_FACTOR, "A_Vector": "P"}, "mix.cl",
        [("Result_Vector", "blMixVector", 3)],
        {"factor": MIX_FACTOR, "a": "P", "b": [0.5, -1.0, 2.0], "clampFactor": 1})
variant("mix-vector-non-uniform", "ShaderNodeMix",
        {"data_type": "VECTOR", "factor_mode": "NON_UNIFORM", "clamp_factor": True},
        {"B_Vector": (0.5, -1.0, 2.0), "A_Vector": (0.25, 0.75, -0.5)},
        {"Factor_Vector": "P"}, "mix.cl", [("Result_Vector", "blMixVectorNonUniform", 3)],
        {"factor": "P", "a": [0.25, 0.75, -0.5], "b": [0.5, -1.0, 2.0], "clampFactor": 1})

# Cycles' NodeVectorMathType order: textures/blender/vector_math.cl's operation numbers.
# (VECTOR_MATH_OPS: scripts/blender_nodes.py, shared with the exporter.)
VM_B = (0.7, -1.3, 0.45)
VM_C = (-0.6, 0.9, 1.4)
VM_SCALE = 0.8

for number, op in enumerate(VECTOR_MATH_OPS):
    value = op in ("DOT_PRODUCT", "DISTANCE", "LENGTH")
    variant("vectormath-" + op.lower().replace("_", "-"), "ShaderNodeVectorMath",
            {"operation": op}, {"Vector_001": VM_B, "Vector_002": VM_C, "Scale": VM_SCALE},
            {"Vector": "P"}, "vector_math.cl",
            [("Value", "blVectorMathValue", 1)] if value else [("Vector", "blVectorMath", 3)],
            {"a": "P", "b": list(VM_B), "c": list(VM_C), "scale": VM_SCALE, "operation": number})

GRADIENT_TYPES = ["LINEAR", "QUADRATIC", "EASING", "DIAGONAL", "RADIAL", "QUADRATIC_SPHERE",
                  "SPHERICAL"]
for number, gtype in enumerate(GRADIENT_TYPES):
    variant("gradient-" + gtype.lower().replace("_", "-"), "ShaderNodeTexGradient",
            {"gradient_type": gtype}, {}, {"Vector": "P"}, "textures.cl",
            [("Fac", "blGradientFac", 1)] + ([("Color", "blGradientColor", 3)] if number == 0
                                             else []),
            {"vector": "P", "gradientType": number})

CHECKER_1, CHECKER_2 = (0.9, 0.1, 0.2, 1.0), (0.1, 0.7, 0.4, 1.0)
variant("checker", "ShaderNodeTexChecker", {}, {"Color1": CHECKER_1, "Color2": CHECKER_2,
                                                "Scale": 2.0},
        {"Vector": "P"}, "textures.cl",
        [("Fac", "blCheckerFac", 1, ["color1", "color2"]), ("Color", "blCheckerColor", 3)],
        {"vector": "P", "color1": list(CHECKER_1[:3]), "color2": list(CHECKER_2[:3]),
         "scale": 2.0})
for depth, distortion, scale in ((2, 1.3, 1.5), (7, 0.8, 0.9)):
    variant("magic-depth%d" % depth, "ShaderNodeTexMagic", {"turbulence_depth": depth},
            {"Scale": scale, "Distortion": distortion}, {"Vector": "P"}, "textures.cl",
            [("Fac", "blMagicFac", 1), ("Color", "blMagicColor", 3)],
            {"vector": "P", "scale": scale, "distortion": distortion, "depth": depth})
variant("whitenoise3d", "ShaderNodeTexWhiteNoise", {"noise_dimensions": "3D"}, {},
        {"Vector": "P"}, "textures.cl",
        [("Value", "blWhiteNoise3DValue", 1), ("Color", "blWhiteNoise3DColor", 3)],
        {"vector": "P"})
variant("whitenoise1d", "ShaderNodeTexWhiteNoise", {"noise_dimensions": "1D"}, {},
        {"W": "P.x"}, "textures.cl",
        [("Value", "blWhiteNoise1DValue", 1), ("Color", "blWhiteNoise1DColor", 3)], {"w": "P.x"})
variant("whitenoise2d", "ShaderNodeTexWhiteNoise", {"noise_dimensions": "2D"}, {},
        {"Vector": "P"}, "textures.cl",
        [("Value", "blWhiteNoise2DValue", 1), ("Color", "blWhiteNoise2DColor", 3)],
        {"vector": "P"})
variant("whitenoise4d", "ShaderNodeTexWhiteNoise", {"noise_dimensions": "4D"}, {},
        {"Vector": "P", "W": "P.y"}, "textures.cl",
        [("Value", "blWhiteNoise4DValue", 1), ("Color", "blWhiteNoise4DColor", 3)],
        {"vector": "P", "w": "P.y"})

WAVE_PROFILES = ["SIN", "SAW", "TRI"]


def wave_variant(name, wtype, direction, profile, scale=1.5, distortion=0.0, detail=2.0,
                 detail_scale=1.0, roughness=0.5, phase=0.0, color=False):
    dirs = ["X", "Y", "Z", "DIAGONAL" if wtype == "BANDS" else "SPHERICAL"]
    props = {"wave_type": wtype, "wave_profile": profile}
    props["bands_direction" if wtype == "BANDS" else "rings_direction"] = direction
    variant(name, "ShaderNodeTexWave", props,
            {"Scale": scale, "Distortion": distortion, "Detail": detail,
             "Detail Scale": detail_scale, "Detail Roughness": roughness, "Phase Offset": phase},
            {"Vector": "P"}, "noise.cl",
            [("Fac", "blWaveFac", 1)] + ([("Color", "blWaveColor", 3)] if color else []),
            {"vector": "P", "scale": scale, "distortion": distortion, "detail": detail,
             "detailScale": detail_scale, "detailRoughness": roughness, "phaseOffset": phase,
             "waveType": 0 if wtype == "BANDS" else 1, "direction": dirs.index(direction),
             "profile": WAVE_PROFILES.index(profile)})


wave_variant("wave-bands-x-sin", "BANDS", "X", "SIN", color=True)
wave_variant("wave-bands-diagonal-saw-distorted", "BANDS", "DIAGONAL", "SAW", distortion=3.0,
             detail=2.5, detail_scale=1.7, phase=0.4)
wave_variant("wave-rings-spherical-tri", "RINGS", "SPHERICAL", "TRI", scale=0.6)
wave_variant("wave-rings-z-sin-distorted", "RINGS", "Z", "SIN", scale=0.8, distortion=2.0)

COLOR_IN = "P*0.25+0.35"  # colours in about [0, 1.2]
variant("invert", "ShaderNodeInvert", {}, {}, {"Fac": MIX_FACTOR, "Color": COLOR_IN},
        "color.cl", [("Color", "blInvertColor", 3)], {"fac": MIX_FACTOR, "color": COLOR_IN})
variant("gamma", "ShaderNodeGamma", {}, {"Gamma": 2.2}, {"Color": COLOR_IN}, "color.cl",
        [("Color", "blGamma", 3)], {"color": COLOR_IN, "gamma": 2.2})
variant("bright-contrast", "ShaderNodeBrightContrast", {}, {"Bright": 0.1, "Contrast": 0.4},
        {"Color": COLOR_IN}, "color.cl", [("Color", "blBrightContrast", 3)],
        {"color": COLOR_IN, "bright": 0.1, "contrast": 0.4})
variant("hue-saturation-value", "ShaderNodeHueSaturation", {},
        {"Hue": 0.3, "Saturation": 1.4, "Value": 0.9}, {"Fac": MIX_FACTOR, "Color": COLOR_IN},
        "color.cl", [("Color", "blHueSaturationValue", 3)],
        {"hue": 0.3, "saturation": 1.4, "value": 0.9, "fac": MIX_FACTOR, "color": COLOR_IN})
variant("rgb-to-bw", "ShaderNodeRGBToBW", {}, {}, {"Color": COLOR_IN}, "color.cl",
        [("Val", "blRgbToBw", 1)], {"color": COLOR_IN})
for number, mode in enumerate(["RGB", "HSV", "HSL"]):
    variant("separate-color-" + mode.lower(), "ShaderNodeSeparateColor", {"mode": mode}, {},
            {"Color": COLOR_IN}, "color.cl",
            [("Red", "blSeparateColorR", 1), ("Green", "blSeparateColorG", 1),
             ("Blue", "blSeparateColorB", 1)], {"color": COLOR_IN, "mode": number})
    variant("combine-color-" + mode.lower(), "ShaderNodeCombineColor", {"mode": mode}, {},
            {"Red": "P.x*0.25+0.35", "Green": "P.y*0.25+0.2", "Blue": "P.z*0.3+0.4"}, "color.cl",
            [("Color", "blCombineColor", 3)],
            {"r": "P.x*0.25+0.35", "g": "P.y*0.25+0.2", "b": "P.z*0.3+0.4", "mode": number})

MAP_LOC, MAP_ROT, MAP_SCALE = (0.3, -0.2, 0.5), (0.4, -0.7, 1.1), (1.5, 0.8, -1.2)
for number, mtype in enumerate(["POINT", "TEXTURE", "VECTOR", "NORMAL"]):
    variant("mapping-" + mtype.lower(), "ShaderNodeMapping", {"vector_type": mtype},
            {"Location": MAP_LOC, "Rotation": MAP_ROT, "Scale": MAP_SCALE}, {"Vector": "P"},
            "vector_math.cl", [("Vector", "blMapping", 3)],
            {"vector": "P", "location": list(MAP_LOC), "rotation": list(MAP_ROT),
             "scale": list(MAP_SCALE), "mappingType": number})

for interpolation, clamp in (("LINEAR", True), ("STEPPED", False), ("SMOOTHSTEP", False),
                             ("SMOOTHERSTEP", False)):
    fmin, fmax, tmin, tmax, steps = (0.2, -0.5, 0.0), (1.9, 3.0, 1.2), (-0.5, 0.0, 2.0), \
        (2.0, 1.0, -1.0), (3.0, 4.0, 2.0)
    variant("vector-maprange-" + interpolation.lower(), "ShaderNodeMapRange",
            {"data_type": "FLOAT_VECTOR", "interpolation_type": interpolation, "clamp": clamp},
            {"From_Min_FLOAT3": fmin, "From_Max_FLOAT3": fmax, "To_Min_FLOAT3": tmin,
             "To_Max_FLOAT3": tmax, "Steps_FLOAT3": steps}, {"Vector": "P"}, "vector_math.cl",
            [("Vector", "blMapRangeVector", 3)],
            {"vector": "P", "fromMin": list(fmin), "fromMax": list(fmax), "toMin": list(tmin),
             "toMax": list(tmax), "steps": list(steps),
             "interpolation": MAP_RANGE_TYPES.index(interpolation), "useClamp": int(clamp)})

BRICK_COLORS = {"Color1": (0.8, 0.3, 0.2, 1.0), "Color2": (0.4, 0.2, 0.1, 1.0),
                "Mortar": (0.7, 0.7, 0.65, 1.0)}
for name, freq, squash, smooth in (("brick", 2, 1.0, 0.1), ("brick-squashed-sharp", 3, 0.6, 0.0)):
    inputs = dict(BRICK_COLORS, **{"Scale": 2.0, "Mortar Size": 0.03, "Mortar Smooth": smooth,
                                    "Bias": 0.1, "Brick Width": 0.5, "Row Height": 0.25})
    variant(name, "ShaderNodeTexBrick",
            {"offset": 0.5, "offset_frequency": freq, "squash": squash, "squash_frequency": 2},
            inputs, {"Vector": "P"}, "textures.cl",
            [("Color", "blBrickColor", 3), ("Fac", "blBrickFac", 1, ["color1", "color2", "mortar"])],
            {"vector": "P", "color1": list(BRICK_COLORS["Color1"][:3]),
             "color2": list(BRICK_COLORS["Color2"][:3]), "mortar": list(BRICK_COLORS["Mortar"][:3]),
             "scale": 2.0, "mortarSize": 0.03, "mortarSmooth": smooth, "bias": 0.1,
             "brickWidth": 0.5, "rowHeight": 0.25, "offsetAmount": 0.5, "offsetFrequency": freq,
             "squashAmount": squash, "squashFrequency": 2})


# Image Texture (textures/blender/image.cl): a generated 6x5 image (not square, not a power of
# two, so that a swapped axis shows) in three kinds, bytes read as sRGB, bytes as Non-Color and
# floats (0..2) as Linear Rec.709, each with every interpolation and extension. The plane's x and
# y (the lookup's u and v) run over about four periods, negative ones included. One more: bytes
# with alpha below 1 (the colour comes out associated, as Cycles gives it when Alpha is unused).
IMAGE_KINDS = {"srgb": (False, "sRGB", False), "noncolor": (False, "Non-Color", False),
               "linear": (True, "Linear Rec.709", False), "srgb-alpha": (False, "sRGB", True),
               "srgb16": (False, "sRGB", False)}
IMAGE_INTERPOLATIONS = ["Linear", "Closest", "Cubic"]
IMAGE_EXTENSIONS = ["REPEAT", "EXTEND", "CLIP", "MIRROR"]


def image_spec(kind):
    import random
    is_float, colorspace, alpha = IMAGE_KINDS[kind]
    rng = random.Random("texcc-" + kind)
    w, h = 6, 5
    pixels = []
    if kind == "srgb16":  # a 16-bit PNG file, which Blender reads into a linear float buffer
        for _ in range(w * h):
            pixels += [rng.randrange(65536) / 65535.0 for _ in range(3)] + [1.0]
        return {"kind": kind, "width": w, "height": h, "float": False, "bits": 16,
                "colorspace": colorspace, "pixels": pixels}
    for _ in range(w * h):
        if is_float:
            pixels += [round(rng.uniform(0.0, 2.0), 4) for _ in range(3)] + [1.0]
        else:
            pixels += [rng.randrange(256) / 255.0 for _ in range(3)]
            pixels.append(rng.randrange(256) / 255.0 if alpha else 1.0)
    return {"kind": kind, "width": w, "height": h, "float": is_float, "colorspace": colorspace,
            "pixels": pixels}


for kind in IMAGE_KINDS:
    for interpolation in IMAGE_INTERPOLATIONS:
        for extension in IMAGE_EXTENSIONS:
            if kind == "srgb-alpha" and (interpolation != "Linear" or extension != "REPEAT"):
                continue
            if kind == "srgb16" and (interpolation, extension) not in (("Linear", "REPEAT"),
                                                                       ("Cubic", "CLIP")):
                continue
            iargs = {"image": "IMAGE", "vector": "P",
                     "interpolation": IMAGE_INTERPOLATIONS.index(interpolation),
                     "extension": IMAGE_EXTENSIONS.index(extension), "alphaLinked": 0}
            variant("image-%s-%s-%s" % (kind, interpolation.lower(), extension.lower()),
                    "ShaderNodeTexImage", {"interpolation": interpolation, "extension": extension},
                    {}, {"Vector": "P"}, "image.cl",
                    [("Color", "blImageColor", 3), ("Alpha", "blImageAlpha", 1, ["alphaLinked"])],
                    iargs, image=image_spec(kind))
# Smart: Cycles' SVM gives Cubic's values (the exporter writes interpolation 2).
variant("image-srgb-smart-repeat", "ShaderNodeTexImage",
        {"interpolation": "Smart", "extension": "REPEAT"}, {}, {"Vector": "P"}, "image.cl",
        [("Color", "blImageColor", 3)],
        {"image": "IMAGE", "vector": "P", "interpolation": 2, "extension": 0, "alphaLinked": 0},
        image=image_spec("srgb"))
# The same with the Alpha output in use (Cycles then divides the colour by the alpha): the
# bake's Emission Strength is (Alpha > -1), always 1, which Cycles cannot fold away.
variant("image-srgb-alpha-linear-repeat-straight", "ShaderNodeTexImage",
        {"interpolation": "Linear", "extension": "REPEAT"}, {}, {"Vector": "P", "alpha": "linked"},
        "image.cl", [("Color", "blImageColor", 3)],
        {"image": "IMAGE", "vector": "P", "interpolation": 0, "extension": 0, "alphaLinked": 1},
        image=image_spec("srgb-alpha"))


# Color Ramp in HSV and HSL colour modes (ramp.cl blColorRampHue*): the same four stops, each
# hue interpolation; Blender mixes linearly between stops there whatever the interpolation says,
# which only decides whether the table lookup interpolates (Constant: not).
HUE_MODES = ["NEAR", "FAR", "CW", "CCW"]


def ramp_hue_setup(color_mode, hue, interpolation):
    def setup(node):
        ramp_setup(interpolation)(node)
        node.color_ramp.color_mode = color_mode
        node.color_ramp.hue_interpolation = hue
    return setup


for color_mode, hue, interpolation in [("HSV", h, "LINEAR") for h in HUE_MODES] + \
        [("HSL", h, "LINEAR") for h in HUE_MODES] + [("HSV", "NEAR", "CONSTANT"),
                                                      ("HSL", "FAR", "EASE")]:
    name = "colorramp-%s-%s" % (color_mode.lower(), hue.lower())
    if interpolation != "LINEAR":
        name += "-" + interpolation.lower()
    variant(name, "ShaderNodeValToRGB", {}, {}, {"Fac": "P.x*0.3+0.35"}, "ramp.cl",
            [("Color", "blColorRampHueColor", 3), ("Alpha", "blColorRampHueAlpha", 1)],
            {"fac": "P.x*0.3+0.35", "colors": [list(c) for _, c in RAMP_STOPS],
             "positions": [p for p, _ in RAMP_STOPS], "count": len(RAMP_STOPS),
             "interpolation": RAMP_MODES.index(interpolation),
             "colorMode": ["RGB", "HSV", "HSL"].index(color_mode),
             "hueInterpolation": HUE_MODES.index(hue)},
            setup=ramp_hue_setup(color_mode, hue, interpolation),
            describe={"interpolation": interpolation, "color_mode": color_mode,
                      "hue_interpolation": hue,
                      "stops": [[p] + list(c) for p, c in RAMP_STOPS]})


# Float, RGB and Vector Curves (curves.cl): curves with Auto, Auto Clamped and Vector handles,
# inputs running past the table's range on both sides (Extend Extrapolated and Horizontal). The
# table, its range and the extension are what the exporter computes (exporter_args).
CURVE_ARGS = ["table", "size", "minX", "maxX", "extrapolate"]


def set_curve_mapping(node, curves, extend, clip=True):
    """Gives a curve node's mapping the points of `curves` (per curve of the mapping, its points
    (x, y, handle type)), its extension and clipping (the fixtures' setup and check_table.py)."""
    mapping = node.mapping
    mapping.use_clip = clip
    mapping.extend = extend
    for curve, points in zip(mapping.curves, curves):
        while len(curve.points) < len(points):
            curve.points.new(0.5, 0.5)
        for point, (x, y, handle) in zip(curve.points, points):
            point.location = (x, y)
            point.handle_type = handle
    mapping.update()


def curve_setup(curves, extend, clip=True):
    """curves: per curve of the mapping, its points (x, y, handle type)."""
    return lambda node: set_curve_mapping(node, curves, extend, clip)


FLOAT_CURVE = [[(0.0, 0.1, "AUTO"), (0.3, 0.65, "AUTO"), (0.6, 0.2, "VECTOR"),
                (1.0, 0.9, "AUTO_CLAMPED")]]
FLOAT_CURVE_WIDE = [[(-1.0, 0.5, "AUTO"), (0.5, -0.4, "AUTO"), (2.0, 1.7, "AUTO")]]
for name, curves, extend, clip, feed in (
        ("floatcurve", FLOAT_CURVE, "EXTRAPOLATED", True, "P.x*0.4+0.5"),
        ("floatcurve-horizontal", FLOAT_CURVE, "HORIZONTAL", True, "P.x*0.5+0.4"),
        ("floatcurve-wide", FLOAT_CURVE_WIDE, "EXTRAPOLATED", False, "P.x*1.0+0.2")):
    variant(name, "ShaderNodeFloatCurve", {}, {"Factor": 0.85}, {"Value": feed}, "curves.cl",
            [("Value", "blFloatCurve", 1)], {"factor": 0.85, "value": feed},
            setup=curve_setup(curves, extend, clip),
            describe={"extend": extend, "use_clip": clip, "curves": curves},
            exporter_args=CURVE_ARGS)

RGB_CURVES = [[(0.0, 0.05, "AUTO"), (0.4, 0.55, "AUTO"), (1.0, 0.95, "AUTO")],  # R
              [(0.0, 0.0, "AUTO"), (1.0, 1.0, "AUTO")],  # G: identity
              [(0.0, 0.2, "VECTOR"), (0.5, 0.3, "VECTOR"), (1.0, 1.0, "AUTO_CLAMPED")],  # B
              [(0.0, 0.0, "AUTO"), (0.35, 0.5, "AUTO"), (1.0, 1.0, "AUTO")]]  # C (combined)
VECTOR_CURVES = [[(-1.0, -0.8, "AUTO"), (0.0, 0.3, "AUTO"), (1.0, 0.9, "AUTO")],
                 [(-1.0, 1.0, "VECTOR"), (1.0, -1.0, "VECTOR")],
                 [(-1.0, -1.0, "AUTO"), (-0.2, 0.4, "AUTO_CLAMPED"), (0.6, -0.1, "AUTO"),
                  (1.0, 1.0, "AUTO")]]
for name, node, fn, socket, param, curves, extend, feed, fac in (
        ("rgbcurves", "ShaderNodeRGBCurve", "blRgbCurves", "Color", "color", RGB_CURVES,
         "EXTRAPOLATED", COLOR_IN, 0.9),
        ("rgbcurves-horizontal", "ShaderNodeRGBCurve", "blRgbCurves", "Color", "color",
         RGB_CURVES, "HORIZONTAL", COLOR_IN, 1.0),
        ("vectorcurves", "ShaderNodeVectorCurve", "blVectorCurves", "Vector", "vector",
         VECTOR_CURVES, "EXTRAPOLATED", "P*0.5+-0.3", 0.75),
        ("vectorcurves-horizontal", "ShaderNodeVectorCurve", "blVectorCurves", "Vector",
         "vector", VECTOR_CURVES, "HORIZONTAL", "P*0.5+-0.3", 1.0)):
    variant(name, node, {}, {"Fac": fac}, {socket: feed}, "curves.cl", [(socket, fn, 3)],
            {"fac": fac, param: feed}, setup=curve_setup(curves, extend),
            describe={"extend": extend, "curves": curves}, exporter_args=CURVE_ARGS)


# Fresnel and Layer Weight (input.cl): the incoming direction is the bake's (fixed: the plane's
# normal), so the fixtures compare the *Incoming functions that blFresnel and blLayerWeight*
# call with ViewDir. The Normal input is fed one coordinate of the position (a float into a
# vector socket: (v, v, v) in both renderers; an affine map of the whole position would keep
# its dot product with the plane's normal constant), so that the cosine runs from -0.3 to 0.93.
NORMAL_FEED = "P.x*0.3+0.1"
for name, ior in (("fresnel", 1.45), ("fresnel-below-one", 0.7)):
    variant(name, "ShaderNodeFresnel", {}, {"IOR": ior}, {"Normal": NORMAL_FEED}, "input.cl",
            [("Fac", "blFresnelIncoming", 1)],
            {"ior": ior, "normal": NORMAL_FEED, "incoming": "INCOMING"})
for blend in (0.5, 0.2, 0.85):
    variant("layerweight-%g" % blend, "ShaderNodeLayerWeight", {}, {"Blend": blend},
            {"Normal": NORMAL_FEED}, "input.cl",
            [("Fresnel", "blLayerWeightFresnelIncoming", 1),
             ("Facing", "blLayerWeightFacingIncoming", 1)],
            {"blend": blend, "normal": NORMAL_FEED, "incoming": "INCOMING"})


# Normal Map in Tangent Space (textures/blender/normal_map.cl): blNormalMapFrame, which
# blNormalMap calls with the hit's Normal, Tangent, TangentSign and Backfacing, with the bake
# plane's frame as arguments: the normal of AXIS_U x AXIS_V, the MikkTSpace tangent of its UVs
# (dP/du = AXIS_U, normalized) and the sign +1 (its UVs are not mirrored), a front face. The
# Color is the position (values beyond 0..1 too); Strength below, at and above 1.
def _unit(v):
    n = sum(c * c for c in v) ** 0.5
    return [c / n for c in v]


PLANE_NORMAL = _unit([AXIS_U[1] * AXIS_V[2] - AXIS_U[2] * AXIS_V[1],
                      AXIS_U[2] * AXIS_V[0] - AXIS_U[0] * AXIS_V[2],
                      AXIS_U[0] * AXIS_V[1] - AXIS_U[1] * AXIS_V[0]])
PLANE_TANGENT = _unit(list(AXIS_U))
for strength in (0.0, 0.5, 1.0, 2.0):
    variant("normalmap-strength-%g" % strength, "ShaderNodeNormalMap", {"space": "TANGENT"},
            {"Strength": strength}, {"Color": "P"}, "normal_map.cl",
            [("Normal", "blNormalMapFrame", 3)],
            {"color": "P", "strength": strength, "normal": PLANE_NORMAL,
             "tangent": PLANE_TANGENT, "tangentSign": 1.0, "backfacing": 0.0,
             "axisX": [1.0, 0.0, 0.0], "axisY": [0.0, 1.0, 0.0], "axisZ": [0.0, 0.0, 1.0]})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", nargs="*", help="variant names or prefixes (default: all)")
    ap.add_argument("--size", type=int, default=48, help="texels per side (points: size^2)")
    args = ap.parse_args()
    ensure_bpy("blender_conformance")
    import bpy
    import numpy as np
    start = time.time()
    os.makedirs(OUT, exist_ok=True)
    material, image = setup_scene(args.size)
    points = bake(material, image, lambda tree, position: position)
    # The baked Position is where Cycles shaded; it must lie on the plane near each texel centre.
    n = args.size
    centres = np.array([[ORIGIN[k] + (i + 0.5) / n * AXIS_U[k] + (j + 0.5) / n * AXIS_V[k]
                         for k in range(3)] for j in range(n) for i in range(n)])
    drift = float(np.abs(points - centres).max())
    if drift > 0.01:
        sys.exit("blender_conformance: baked positions are %g from the texel centres" % drift)
    with open(os.path.join(OUT, "points.txt"), "w") as f:
        f.write("".join("%.9g %.9g %.9g\n" % tuple(float(c) for c in p) for p in points))
    chosen = [v for v in VARIANTS
              if not args.only or any(v["name"].startswith(o) for o in args.only)]
    # The incoming direction Cycles shades with in a bake: one direction (the plane's normal).
    incoming = bake(material, image, lambda tree, position: tree.nodes.new(
        "ShaderNodeNewGeometry").outputs["Incoming"])
    if float(np.abs(incoming - incoming[0]).max()) > 1e-6:
        sys.exit("blender_conformance: the baked incoming direction varies over the plane")
    for v in chosen:
        for key, value in v["args"].items():
            if value == "INCOMING":
                v["args"][key] = [float(c) for c in incoming[0]]
    for v in chosen:
        outputs = []
        for socket, fn, channels, *drop in v["outputs"]:
            values = bake(material, image, build_variant(v, socket))[:, :channels]
            outputs.append({"socket": socket, "fn": fn, "channels": channels,
                            "values": encode(values)})
            if drop:  # arguments of the node this output's function does not take
                outputs[-1]["drop"] = drop[0]
        fixture = {"variant": v["name"], "blender": BPY_VERSION,
                   "node": {"type": v["node"], "properties": v["props"], "inputs": v["inputs"],
                            "fed_from_position": v["feeds"], "setup": v.get("describe")},
                   "source": v["source"], "args": v["args"], "points": "points.txt",
                   "outputs": outputs}
        if "image" in v:
            # The image as Blender holds it (rows bottom first) and the colour space it was
            # read in: compare.py gives texcc-eval the texels texrender's loader makes of it.
            spec = v["image"]
            fixture["image"] = {"width": spec["width"], "height": spec["height"],
                                "float": spec["float"], "colorspace": spec["colorspace"],
                                "pixels": encode(spec["stored"])}
            if "bits" in spec:
                fixture["image"]["bits"] = spec["bits"]
        with open(os.path.join(OUT, v["name"] + ".json"), "w") as f:
            json.dump(fixture, f, indent=1)
            f.write("\n")
    print("blender_conformance: %d variants, %d points each, bpy %s, %.1f s (position drift "
          "from texel centres %.3g)" % (len(chosen), n * n, bpy.app.version_string,
                                         time.time() - start, drift))

