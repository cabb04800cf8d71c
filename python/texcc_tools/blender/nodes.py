"""blender_nodes.py: which library function and which arguments each Blender node becomes.

The one table of the Blender exporter (scripts/blender_export.py, docs/blender.md): per Blender
node type, the textures/blender/ function of each output socket and what feeds each of its
parameters; the shaders the exporter translates; the library's signatures, read from its .cl
files, against which the table is checked when the exporter starts.
"""

import os
import re
import struct

from texcc_tools.paths import ROOT, TEXTURES

LIBRARY = os.path.join(TEXTURES, "blender")

# --- The library's signatures ---------------------------------------------------------------

_SIGNATURE = re.compile(r"^(float[234]?) (bl\w+)\(([^)]*)\)\s*\{", re.M)


def library_signatures():
    """{function: (file, return type, [(type, name)])}, read from textures/blender/*.cl."""
    signatures = {}
    for name in sorted(os.listdir(LIBRARY)):
        if not name.endswith(".cl"):
            continue
        with open(os.path.join(LIBRARY, name)) as f:
            text = f.read()
        for m in _SIGNATURE.finditer(text):
            params = []
            for p in m.group(3).split(","):
                words = p.split()
                if words:
                    params.append((" ".join(words[:-1]).replace(" *", "*"), words[-1].lstrip("*")))
            signatures[m.group(2)] = (name, m.group(1), params)
    return signatures


# --- The node table -------------------------------------------------------------------------
# Per Blender node type: `fn` maps an output socket's identifier to a library function (a
# callable of the node when a setting picks the variant); `sockets` maps a function parameter to
# the input socket (identifier) that feeds it, or a callable of the node returning one; `props`
# maps a parameter to a callable of the node returning its constant (settings, ramps, curve
# tables); `unlinked_attr` maps a parameter to the attribute that feeds it while its socket is
# unlinked (a hidden-value Normal is the shading normal). A
# parameter the function takes and the table does not name is an error in the table itself
# (checked against the library's signatures when the exporter starts).

MATH_OPS = ["ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "SINE", "COSINE", "TANGENT", "ARCSINE",
            "ARCCOSINE", "ARCTANGENT", "POWER", "LOGARITHM", "MINIMUM", "MAXIMUM", "ROUND",
            "LESS_THAN", "GREATER_THAN", "MODULO", "ABSOLUTE", "ARCTAN2", "FLOOR", "CEIL",
            "FRACT", "SQRT", "INVERSE_SQRT", "SIGN", "EXPONENT", "RADIANS", "DEGREES", "SINH",
            "COSH", "TANH", "TRUNC", "SNAP", "WRAP", "COMPARE", "MULTIPLY_ADD", "PINGPONG",
            "SMOOTH_MIN", "SMOOTH_MAX", "FLOORED_MODULO"]
VECTOR_MATH_OPS = ["ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "CROSS_PRODUCT", "PROJECT", "REFLECT",
                   "DOT_PRODUCT", "DISTANCE", "LENGTH", "SCALE", "NORMALIZE", "SNAP", "FLOOR",
                   "CEIL", "MODULO", "FRACTION", "ABSOLUTE", "MINIMUM", "MAXIMUM", "WRAP", "SINE",
                   "COSINE", "TANGENT", "REFRACT", "FACEFORWARD", "MULTIPLY_ADD", "POWER", "SIGN"]
BLEND_TYPES = ["MIX", "DARKEN", "MULTIPLY", "BURN", "LIGHTEN", "SCREEN", "DODGE", "ADD",
               "OVERLAY", "SOFT_LIGHT", "LINEAR_LIGHT", "DIFFERENCE", "EXCLUSION", "SUBTRACT",
               "DIVIDE", "HUE", "SATURATION", "COLOR", "VALUE"]
NOISE_TYPES = ["MULTIFRACTAL", "FBM", "HYBRID_MULTIFRACTAL", "RIDGED_MULTIFRACTAL",
               "HETERO_TERRAIN"]
VORONOI_FEATURES = ["F1", "F2", "SMOOTH_F1", "DISTANCE_TO_EDGE", "N_SPHERE_RADIUS"]
VORONOI_METRICS = ["EUCLIDEAN", "MANHATTAN", "CHEBYCHEV", "MINKOWSKI"]
RAMP_MODES = ["LINEAR", "EASE", "B_SPLINE", "CARDINAL", "CONSTANT"]
MAP_RANGE_TYPES = ["LINEAR", "STEPPED", "SMOOTHSTEP", "SMOOTHERSTEP"]
GRADIENT_TYPES = ["LINEAR", "QUADRATIC", "EASING", "DIAGONAL", "RADIAL", "QUADRATIC_SPHERE",
                  "SPHERICAL"]
COLOR_MODES = ["RGB", "HSV", "HSL"]
HUE_INTERPOLATIONS = ["NEAR", "FAR", "CW", "CCW"]
# Blender samples a curve mapping into a table of CURVE_TABLE_SIZE entries for Cycles (its
# RAMP_TABLE_SIZE + 1); textures/blender/curves.cl looks the input up in it.
CURVE_TABLE_SIZE = 257
# Image Texture settings texrender's tex2DFiltered has, in its numbering (Smart is Cubic: Cycles'
# SVM gives the same values, image-srgb-smart-repeat).
IMAGE_INTERPOLATIONS = ["Linear", "Closest", "Cubic"]
IMAGE_EXTENSIONS = ["REPEAT", "EXTEND", "CLIP", "MIRROR"]
IMAGE_COLORSPACES = ["sRGB", "Linear Rec.709", "Non-Color"]


def _index(table, prop):
    return lambda node: table.index(getattr(node, prop))


def _flag(prop):
    return lambda node: 1 if getattr(node, prop) else 0


def _dims(node, prop):
    return getattr(node, prop)[0]  # "3D" -> "3"


def _same(names):
    """Parameters fed by the socket of the same name, capitalised (scale <- Scale)."""
    return {n: n[0].upper() + n[1:] for n in names}


NOISE_SOCKETS = dict(_same(["scale", "detail", "roughness", "lacunarity", "offset", "gain",
                            "distortion"]), vector="Vector", w="W")
VORONOI_SOCKETS = dict(_same(["scale", "detail", "roughness", "lacunarity", "smoothness",
                              "exponent", "randomness"]), vector="Vector", w="W")


def _voronoi_fn(output):
    return lambda node: "blVoronoi%sD%s" % (_dims(node, "voronoi_dimensions"), output)


def _mix_fn(node):
    if node.data_type == "FLOAT":
        return "blMixFloat"
    if node.data_type == "VECTOR":
        return "blMixVector" if node.factor_mode == "UNIFORM" else "blMixVectorNonUniform"
    return "blMixColor"


def _mix_socket(kind):
    def pick(node):
        if kind == "Factor":
            return "Factor_Vector" if node.data_type == "VECTOR" and \
                node.factor_mode == "NON_UNIFORM" else "Factor_Float"
        return kind + {"FLOAT": "_Float", "VECTOR": "_Vector", "RGBA": "_Color"}[node.data_type]
    return pick


def _ramp_colors(node):
    return [list(e.color) for e in node.color_ramp.elements]


def _f32(x):
    """x rounded to a float32, as Blender's C code computes."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def curve_range(node, count):
    """(minX, maxX) of a curve node's table: the smallest first and largest last point x over
    its first `count` curves (Cycles' curvemapping_minmax: 1 Float, 3 Vector, 4 RGB with C)."""
    mapping = node.mapping
    mapping.update()  # sorts the points and rebuilds Blender's own tables, as Cycles' sync does
    curves = list(mapping.curves)[:count]
    return (_f32(min(c.points[0].location[0] for c in curves)),
            _f32(max(c.points[-1].location[0] for c in curves)))


def curve_table(node, count):
    """The table Blender gives Cycles for a Float (count 1), Vector (3) or RGB (4) Curves node:
    entry i at x = minX + i / 256 * (maxX - minX) (float32 arithmetic, as Blender's), each
    channel through its curve; RGB's channels after the combined curve C (curves[3]). Vector and
    RGB rows are float4 (w 0): textures/blender/curves.cl reads __global const float4* rows."""
    lo, hi = curve_range(node, count)
    mapping = node.mapping
    mapping.initialize()
    curves = list(mapping.curves)
    span = _f32(hi - lo)
    size = CURVE_TABLE_SIZE - 1
    table = []
    for i in range(CURVE_TABLE_SIZE):
        x = _f32(lo + _f32(_f32(i / size) * span))
        if count == 1:
            table.append(mapping.evaluate(curves[0], x))
            continue
        if count == 4:
            x = mapping.evaluate(curves[3], x)
        table.append([mapping.evaluate(curves[k], x) for k in range(3)] + [0.0])  # float4 rows
    return table


def _curve_props(count):
    return {"table": lambda n: curve_table(n, count), "size": lambda n: CURVE_TABLE_SIZE,
            "minX": lambda n: curve_range(n, count)[0], "maxX": lambda n: curve_range(n, count)[1],
            "extrapolate": lambda n: 1 if n.mapping.extend == "EXTRAPOLATED" else 0}


def _ramp_fn(output):
    return lambda node: ("blColorRamp%s" if node.color_ramp.color_mode == "RGB" else
                         "blColorRampHue%s") % output


def _map_range_socket(name):
    return lambda node: name if node.data_type == "FLOAT" else \
        name.replace(" ", "_") + "_FLOAT3"


NODES = {
    "ShaderNodeTexNoise": dict(
        fn={"Fac": lambda n: "blNoise%sDFac" % _dims(n, "noise_dimensions"),
            "Color": lambda n: "blNoise%sDColor" % _dims(n, "noise_dimensions")},
        sockets=NOISE_SOCKETS, texture=True,
        props={"type": _index(NOISE_TYPES, "noise_type"), "normalize": _flag("normalize")}),
    "ShaderNodeTexVoronoi": dict(
        fn={o: _voronoi_fn(o) for o in ("Distance", "Color", "Position", "W", "Radius")},
        sockets=VORONOI_SOCKETS, texture=True,
        props={"feature": _index(VORONOI_FEATURES, "feature"),
               "metric": _index(VORONOI_METRICS, "distance"), "normalize": _flag("normalize")}),
    "ShaderNodeTexWave": dict(
        fn={"Color": "blWaveColor", "Fac": "blWaveFac"}, texture=True,
        sockets=dict(_same(["scale", "distortion", "detail"]), vector="Vector",
                     detailScale="Detail Scale", detailRoughness="Detail Roughness",
                     phaseOffset="Phase Offset"),
        props={"waveType": lambda n: ["BANDS", "RINGS"].index(n.wave_type),
               "direction": lambda n: (["X", "Y", "Z", "DIAGONAL"].index(n.bands_direction)
                                       if n.wave_type == "BANDS" else
                                       ["X", "Y", "Z", "SPHERICAL"].index(n.rings_direction)),
               "profile": _index(["SIN", "SAW", "TRI"], "wave_profile")}),
    "ShaderNodeTexGradient": dict(
        fn={"Color": "blGradientColor", "Fac": "blGradientFac"}, texture=True,
        sockets={"vector": "Vector"}, props={"gradientType": _index(GRADIENT_TYPES,
                                                                    "gradient_type")}),
    "ShaderNodeTexChecker": dict(
        fn={"Color": "blCheckerColor", "Fac": "blCheckerFac"}, texture=True,
        sockets={"vector": "Vector", "color1": "Color1", "color2": "Color2", "scale": "Scale"}),
    "ShaderNodeTexMagic": dict(
        fn={"Color": "blMagicColor", "Fac": "blMagicFac"}, texture=True,
        sockets=dict(_same(["scale", "distortion"]), vector="Vector"),
        props={"depth": lambda n: n.turbulence_depth}),
    "ShaderNodeTexWhiteNoise": dict(
        fn={"Value": lambda n: "blWhiteNoise%sDValue" % _dims(n, "noise_dimensions"),
            "Color": lambda n: "blWhiteNoise%sDColor" % _dims(n, "noise_dimensions")},
        texture=True, sockets={"vector": "Vector", "w": "W"}),
    "ShaderNodeTexBrick": dict(
        fn={"Color": "blBrickColor", "Fac": "blBrickFac"}, texture=True,
        sockets={"vector": "Vector", "color1": "Color1", "color2": "Color2", "mortar": "Mortar",
                 "scale": "Scale", "mortarSize": "Mortar Size", "mortarSmooth": "Mortar Smooth",
                 "bias": "Bias", "brickWidth": "Brick Width", "rowHeight": "Row Height"},
        props={"offsetAmount": lambda n: n.offset, "offsetFrequency": lambda n: n.offset_frequency,
               "squashAmount": lambda n: n.squash,
               "squashFrequency": lambda n: n.squash_frequency}),
    # The image itself (the sam2D parameter) is bound by the exporter (Export.image_binding);
    # an unlinked Vector is the UV map, as Cycles' Image Texture reads it.
    "ShaderNodeTexImage": dict(
        fn={"Color": "blImageColor", "Alpha": "blImageAlpha"}, texture="uv",
        sockets={"vector": "Vector"},
        props={"interpolation": lambda n: IMAGE_INTERPOLATIONS.index(
            "Cubic" if n.interpolation == "Smart" else n.interpolation),  # Cycles' SVM: the same
               "extension": _index(IMAGE_EXTENSIONS, "extension"),
               "alphaLinked": lambda n: 1 if n.outputs["Alpha"].is_linked else 0}),
    # RGB colour mode: blColorRampColor/Alpha; HSV and HSL: blColorRampHueColor/Alpha.
    "ShaderNodeValToRGB": dict(
        fn={"Color": _ramp_fn("Color"), "Alpha": _ramp_fn("Alpha")}, sockets={"fac": "Fac"},
        variants=["blColorRampColor", "blColorRampAlpha", "blColorRampHueColor",
                  "blColorRampHueAlpha"],
        props={"colors": _ramp_colors,
               "positions": lambda n: [e.position for e in n.color_ramp.elements],
               "count": lambda n: len(n.color_ramp.elements),
               "interpolation": lambda n: RAMP_MODES.index(n.color_ramp.interpolation),
               "colorMode": lambda n: COLOR_MODES.index(n.color_ramp.color_mode),
               "hueInterpolation": lambda n: HUE_INTERPOLATIONS.index(
                   n.color_ramp.hue_interpolation)}),
    # The curves: the table Blender samples for Cycles (curve_table), looked up as Cycles does.
    "ShaderNodeFloatCurve": dict(
        fn={"Value": "blFloatCurve"}, sockets={"factor": "Factor", "value": "Value"},
        props=_curve_props(1)),
    "ShaderNodeRGBCurve": dict(
        fn={"Color": "blRgbCurves"}, sockets={"fac": "Fac", "color": "Color"},
        props=_curve_props(4)),
    "ShaderNodeVectorCurve": dict(
        fn={"Vector": "blVectorCurves"}, sockets={"fac": "Fac", "vector": "Vector"},
        props=_curve_props(3)),
    # Fresnel and Layer Weight: an unlinked Normal is the shading normal (attribute Normal).
    "ShaderNodeFresnel": dict(
        fn={"Fac": "blFresnel"}, sockets={"ior": "IOR", "normal": "Normal"},
        unlinked_attr={"normal": "Normal"}),
    "ShaderNodeLayerWeight": dict(
        fn={"Fresnel": "blLayerWeightFresnel", "Facing": "blLayerWeightFacing"},
        sockets={"blend": "Blend", "normal": "Normal"}, unlinked_attr={"normal": "Normal"}),
    "ShaderNodeMath": dict(
        fn={"Value": "blMath"}, sockets={"a": "Value", "b": "Value_001", "c": "Value_002"},
        props={"operation": _index(MATH_OPS, "operation"), "useClamp": _flag("use_clamp")}),
    "ShaderNodeVectorMath": dict(
        fn={"Vector": "blVectorMath", "Value": "blVectorMathValue"},
        sockets={"a": "Vector", "b": "Vector_001", "c": "Vector_002", "scale": "Scale"},
        props={"operation": _index(VECTOR_MATH_OPS, "operation")}),
    "ShaderNodeMapRange": dict(
        fn={"Result": "blMapRange", "Vector": "blMapRangeVector"},
        sockets={"value": "Value", "vector": "Vector", "fromMin": _map_range_socket("From Min"),
                 "fromMax": _map_range_socket("From Max"), "toMin": _map_range_socket("To Min"),
                 "toMax": _map_range_socket("To Max"), "steps": _map_range_socket("Steps")},
        props={"interpolation": _index(MAP_RANGE_TYPES, "interpolation_type"),
               "useClamp": _flag("clamp")}),
    "ShaderNodeClamp": dict(
        fn={"Result": "blClamp"}, sockets={"value": "Value", "minimum": "Min", "maximum": "Max"},
        props={"clampType": _index(["MINMAX", "RANGE"], "clamp_type")}),
    "ShaderNodeMix": dict(
        fn={"Result_Float": _mix_fn, "Result_Vector": _mix_fn, "Result_Color": _mix_fn},
        sockets={"factor": _mix_socket("Factor"), "a": _mix_socket("A"), "b": _mix_socket("B")},
        props={"blendType": _index(BLEND_TYPES, "blend_type"),
               "clampFactor": _flag("clamp_factor"), "clampResult": _flag("clamp_result")}),
    "ShaderNodeMapping": dict(
        fn={"Vector": "blMapping"},
        sockets={"vector": "Vector", "location": "Location", "rotation": "Rotation",
                 "scale": "Scale"},
        props={"mappingType": _index(["POINT", "TEXTURE", "VECTOR", "NORMAL"], "vector_type")}),
    "ShaderNodeCombineXYZ": dict(fn={"Vector": "blCombineXYZ"}, sockets=_same(["x", "y", "z"])),
    "ShaderNodeSeparateXYZ": dict(
        fn={"X": "blSeparateXYZX", "Y": "blSeparateXYZY", "Z": "blSeparateXYZZ"},
        sockets={"vector": "Vector"}),
    "ShaderNodeInvert": dict(fn={"Color": "blInvertColor"},
                             sockets={"fac": "Fac", "color": "Color"}),
    "ShaderNodeGamma": dict(fn={"Color": "blGamma"}, sockets={"color": "Color",
                                                             "gamma": "Gamma"}),
    "ShaderNodeBrightContrast": dict(
        fn={"Color": "blBrightContrast"},
        sockets={"color": "Color", "bright": "Bright", "contrast": "Contrast"}),
    "ShaderNodeHueSaturation": dict(
        fn={"Color": "blHueSaturationValue"},
        sockets=dict(_same(["hue", "saturation", "value", "fac", "color"]))),
    "ShaderNodeRGBToBW": dict(fn={"Val": "blRgbToBw"}, sockets={"color": "Color"}),
    "ShaderNodeSeparateColor": dict(
        fn={"Red": "blSeparateColorR", "Green": "blSeparateColorG", "Blue": "blSeparateColorB"},
        sockets={"color": "Color"}, props={"mode": _index(COLOR_MODES, "mode")}),
    "ShaderNodeCombineColor": dict(
        fn={"Color": "blCombineColor"}, sockets={"r": "Red", "g": "Green", "b": "Blue"},
        props={"mode": _index(COLOR_MODES, "mode")}),
    "ShaderNodeTexCoord": dict(
        fn={"Generated": "blTexCoordGenerated", "Object": "blTexCoordObject",
            "UV": "blTexCoordUV", "Normal": "blTexCoordNormal"},
        object_props=True),
    "ShaderNodeNewGeometry": dict(
        fn={"Position": "blGeometryPosition", "Normal": "blGeometryNormal",
            "True Normal": "blGeometryTrueNormal", "Tangent": "blGeometryTangent",
            "Incoming": "blGeometryIncoming"}),
    "ShaderNodeAmbientOcclusion": dict(
        fn={"AO": "blAmbientOcclusionAO", "Color": "blAmbientOcclusionColor"},
        sockets={"color": "Color"}),
}

# Object Info: each output's function takes the object's value (object_info, below).
OBJECT_INFO_OUTPUTS = {"Location": ("blObjectInfoLocation", "location"),
                       "Color": ("blObjectInfoColor", "objectColor"),
                       "Alpha": ("blObjectInfoAlpha", "objectAlpha"),
                       "Object Index": ("blObjectInfoObjectIndex", "objectIndex"),
                       "Material Index": ("blObjectInfoMaterialIndex", "materialIndex"),
                       "Random": ("blObjectInfoRandom", "objectRandom")}
NODES["ShaderNodeObjectInfo"] = dict(fn={o: fn for o, (fn, _) in OBJECT_INFO_OUTPUTS.items()},
                                     object_info=True)
# Normal Map in Tangent Space over the render UV map's tangents (textures/blender/normal_map.cl;
# the exporter writes the mesh's MikkTSpace tangents, blender_tangents.py); blender_materials
# refuses the other spaces and UV maps.
NODES["ShaderNodeNormalMap"] = dict(fn={"Normal": "blNormalMap"},
                                    sockets={"color": "Color", "strength": "Strength"},
                                    object_props=True)
# Attribute: the UV map texrender exports (TexCoord0) only; blender_materials refuses the rest.
NODES["ShaderNodeAttribute"] = dict(fn={"Vector": "blAttributeUV", "Color": "blAttributeUV",
                                        "Fac": "blAttributeUVFac", "Alpha": "blAttributeUVAlpha"})

_MASK = 0xFFFFFFFF


def _rot(x, k):
    return ((x << k) | (x >> (32 - k))) & _MASK


def cycles_hash_uint2(kx, ky):
    """Cycles' hash of two uints (util/hash.h: Bob Jenkins' lookup3 final mix)."""
    a = b = c = (0xDEADBEEF + (2 << 2) + 13) & _MASK
    a, b = (a + kx) & _MASK, (b + ky) & _MASK
    for x, y, z, k in ((2, 1, 0, 14), (0, 2, 1, 11), (1, 0, 2, 25), (2, 1, 0, 16),
                       (0, 2, 1, 4), (1, 0, 2, 14), (2, 1, 0, 24)):
        v = [a, b, c]
        v[x] = ((v[x] ^ v[y]) - _rot(v[y], k)) & _MASK
        a, b, c = v
    return c


def cycles_hash_string(text):
    """Cycles' hash_string: i * 37 + each byte of the UTF-8 name, as an unsigned number (what
    Cycles 5.0.1 gives 'Würfel.001'; a signed char would not)."""
    i = 0
    for byte in text.encode("utf-8"):
        i = (i * 37 + byte) & _MASK
    return i


def object_random(name):
    """Object Info's Random of an object that is not an instance: Cycles' random_id
    hash_uint2(hash_string(name), 0), times 1 / 0xFFFFFFFF in float32."""
    rid = cycles_hash_uint2(cycles_hash_string(name), 0)
    return _f32(_f32(float(rid)) * _f32(1.0 / 0xFFFFFFFF))


def object_info(obj, material):
    """Object Info's values for `obj` (None: Blender's defaults) with `material`."""
    if obj is None:
        return {"location": [0.0, 0.0, 0.0], "objectColor": [1.0, 1.0, 1.0],
                "objectAlpha": 1.0, "objectIndex": 0.0,
                "materialIndex": float(material.pass_index) if material else 0.0,
                "objectRandom": 0.0}
    original = getattr(obj, "original", obj)
    return {"location": [float(v) for v in obj.matrix_world.translation],
            "objectColor": [float(v) for v in obj.color[:3]], "objectAlpha": float(obj.color[3]),
            "objectIndex": float(original.pass_index),
            "materialIndex": float(material.pass_index) if material else 0.0,
            "objectRandom": object_random(original.name)}


def instancers(obj):
    """Names of the objects that instance `obj` (collection instances holding it, a parent
    that instances its children on vertices or faces, particle systems rendering it): Cycles
    gives each instance its own location and random number."""
    import bpy
    original = getattr(obj, "original", obj)
    found = []
    if original.parent is not None and original.parent.instance_type in ("VERTS", "FACES"):
        found.append(original.parent.name)
    for other in bpy.data.objects:
        if not other.users_scene:  # in no scene: instances nothing that renders
            continue
        coll = other.instance_collection if other.instance_type == "COLLECTION" else None
        if coll is not None and original.name in coll.all_objects:
            found.append(other.name)
        for system in getattr(other, "particle_systems", []):
            settings = system.settings
            if (settings.render_type == "OBJECT" and settings.instance_object == original) or \
                    (settings.render_type == "COLLECTION" and settings.instance_collection and
                     original.name in settings.instance_collection.all_objects):
                found.append(other.name)
    return found


# Shader nodes: what each becomes in graph.json's material tree (docs/graph.md's BSDFs).
SHADERS = {
    "ShaderNodeBsdfDiffuse": "diffuse", "ShaderNodeBsdfAnisotropic": "glossy",
    "ShaderNodeEmission": "emission", "ShaderNodeMixShader": "blend",
    "ShaderNodeBsdfPrincipled": "principled",
}
# Principled BSDF inputs the renderer has (socket -> graph input); every other input must stay
# unlinked at its default.
PRINCIPLED_INPUTS = {"Base Color": "baseColor", "Metallic": "metallic", "Roughness": "roughness",
                     "Specular IOR Level": "specular", "Emission Color": "emissionColor",
                     "Emission Strength": "emissionStrength"}
PRINCIPLED_IGNORED = {"Weight"}
# Cycles' surface for a mesh without a material (and --lenient's fallback for a shader).
DEFAULT_SURFACE = {"bsdf": "diffuse", "color": [0.8, 0.8, 0.8]}
PASS_THROUGH = {"NodeReroute"}


def check_table(signatures):
    """Every function the table names exists, and the table feeds each of its parameters."""
    for idname, spec in NODES.items():
        names = set(spec.get("variants", []))  # the functions a callable `fn` picks from
        for fn in spec["fn"].values():
            if isinstance(fn, str):
                names.add(fn)
        for name in names:
            if name not in signatures:
                raise SystemExit("blender_export: internal: %s names unknown function %s"
                                 % (idname, name))
            for ptype, param in signatures[name][2]:
                if ptype == "sam2D":  # the node's image (Export.image_binding)
                    continue
                known = set(spec.get("sockets", {})) | set(spec.get("props", {}))
                if spec.get("object_props"):
                    known |= {"bboxMin", "bboxMax", "axisX", "axisY", "axisZ"}
                if spec.get("object_info"):
                    known |= {p for _, p in OBJECT_INFO_OUTPUTS.values()}
                if param not in known:
                    raise SystemExit("blender_export: internal: %s: %s(%s) is not fed"
                                     % (idname, name, param))


def supported_nodes_text():
    """Blender's names of the nodes the exporter translates ("Noise Texture", ...)."""
    import bpy
    names = set()
    for idname in list(NODES) + list(SHADERS) + ["ShaderNodeBump", "ShaderNodeRGB",
                                                  "ShaderNodeValue", "NodeReroute"]:
        kind = getattr(bpy.types, idname, None)
        names.add(kind.bl_rna.name if kind is not None else idname)
    return ", ".join(sorted(names))
