#!/usr/bin/env python3
"""blender_export.py: a Blender scene as texcc's graph.json, texrender's scene.json and OBJ meshes.

    scripts/blender_export.py FILE.blend -o OUTDIR [--scene NAME] [--camera NAME] [--frame N]
                              [--lenient]
    blender -b FILE.blend --python scripts/blender_export.py -- -o OUTDIR [...]

Then `texcc --graph OUTDIR/graph.json -o T && texrender OUTDIR/scene.json --textures T -o img.exr`
renders the scene. Each material's node tree goes through the Blender-conformant library
(textures/blender/, one texture function per node output); NODES in blender_nodes.py is the one
table of which function and which arguments a Blender node becomes. World coordinates stay Blender's (Z up):
texrender has no preferred up axis except the camera's, which is the Blender camera's +Y. So
WorldPos, Normal and ObjectPos read by the textures are Cycles' Position, Normal and Object.

Anything the exporter cannot translate is an error naming the material, the node and what is
supported (exit 1, nothing written: OUTDIR appears only complete); --lenient makes it a warning and
uses the documented fallback (docs/blender.md). Run as a plain script it needs the bpy wheel,
installed into .venv/ on first use (as scripts/blender_conformance.py does).
"""

import argparse
import contextlib
import math
import os
import re
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class ExportError(Exception):
    """One problem, one line: what and where."""


class Problems:
    """Strict: a problem is an error. Lenient: a warning, and the caller's fallback is used."""

    def __init__(self, lenient):
        self.lenient = lenient

    def refuse(self, message, fallback_text):
        if not self.lenient:
            raise ExportError(message)
        sys.stderr.write("blender_export: warning: %s; %s\n" % (message, fallback_text))


# The node table and the library signatures (one owner: blender_nodes.py).
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bpy_env import ensure_bpy  # noqa: E402
from blender_nodes import (  # noqa: E402
    DEFAULT_SURFACE, LIBRARY, MATH_OPS, NODES, PASS_THROUGH, PRINCIPLED_IGNORED, PRINCIPLED_INPUTS,
    SHADERS, VECTOR_MATH_OPS, check_table, library_signatures, supported_nodes_text)


# --- Material translation -------------------------------------------------------------------

def luminance(rgb):
    """Cycles' colour-to-float conversion (linear Rec.709 luminance, Blender's default)."""
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def sanitize_id(text):
    return "".join(c if c.isprintable() else "?" for c in text).replace("*/", "*|")


class Source:
    """What feeds a socket: an output `out` of `node` inside the node groups `path` (outermost
    first); node None: an unlinked socket `out` across a group boundary, whose value counts."""

    def __init__(self, node, out, path):
        self.node, self.out, self.path = node, out, path


class MaterialTranslator:
    """One material's node tree, on one object (Generated and Normal coordinates read the
    object's bounds and axes), into graph nodes (appended to `nodes`) and a BSDF tree. Node
    groups are inlined: a node inside groups is named by the path, 'Group/Node'."""

    def __init__(self, export, material, name, obj, nodes):
        self.export, self.material, self.name, self.obj = export, material, name, obj
        self.nodes, self.done, self.done_fn, self.stack, self.ids = nodes, {}, {}, [], set()
        self.path = []
        self.where = "material '%s'" % material.name

    def qual(self, node):
        """The node's name, with the groups it sits in."""
        return "/".join([g.name for g in self.path] + [node.name])

    @contextlib.contextmanager
    def inside(self, path):
        outer, self.path = self.path, path
        try:
            yield
        finally:
            self.path = outer

    def node_where(self, node):
        return "%s: node '%s' (%s)" % (self.where, self.qual(node), node.bl_idname)

    def refuse(self, message, fallback_text):
        self.export.problems.refuse(message, fallback_text)

    def add_node(self, key, fn, args):
        node_id = sanitize_id("%s/%s" % (self.name, key))
        if node_id not in self.ids:
            self.ids.add(node_id)
            self.nodes.append({"id": node_id, "fn": fn, "args": args})
            self.export.functions.add(fn)
        return node_id

    # A value is ("const", number or list) or ("node", id, "float" | "float3").
    def link_source(self, socket):
        """The Source feeding `socket` (in the current groups), through reroutes and into and
        out of node groups; None if unlinked."""
        path, crossed = list(self.path), False
        while True:
            links = [l for l in socket.links if not l.is_muted]
            if not links:
                return Source(None, socket, path) if crossed else None
            node, out = links[0].from_node, links[0].from_socket
            if node.bl_idname in PASS_THROUGH:
                socket = node.inputs[0]
            elif node.bl_idname == "NodeGroupInput" and path:
                group = path.pop()
                socket = next(s for s in group.inputs if s.identifier == out.identifier)
                crossed = True
            elif node.bl_idname == "ShaderNodeGroup" and not node.mute and node.node_tree:
                outputs = [n for n in node.node_tree.nodes if n.bl_idname == "NodeGroupOutput"]
                active = [n for n in outputs if n.is_active_output] or outputs
                inner = [s for s in active[0].inputs if s.identifier == out.identifier] \
                    if active else []
                if not inner:
                    return Source(node, out, path)
                path.append(node)
                socket, crossed = inner[0], True
            else:
                return Source(node, out, path)

    def socket_value(self, node, socket, want):
        """The value of an input socket, as `want` ("float" or "float3")."""
        source = self.link_source(socket)
        if source is None:
            return self.socket_value_unlinked(socket)
        if source.node is None:  # an unlinked socket of a group: its value
            return self.convert(self.socket_value_unlinked(source.out), source.out.type, want,
                                None, None)
        with self.inside(source.path):
            value = self.output_value(source.node, source.out, node, socket)
            if value is None:  # --lenient fallback: the socket's own value
                return self.socket_value_unlinked(socket)
            return self.convert(value, source.out.type, want, source.node, source.out)

    def socket_value_unlinked(self, socket):
        value = socket.default_value
        if isinstance(value, (int, float)):
            return ("const", float(value))
        return ("const", [float(v) for v in value][:3])

    def convert(self, value, from_type, want, from_node, out):
        """Blender's implicit socket conversions: colour -> float is luminance, vector -> float
        the average; float -> colour or vector is a broadcast (the graph does that itself)."""
        if want != "float":
            return value
        if value[0] == "const":
            v = value[1]
            if isinstance(v, float):
                return value
            return ("const", luminance(v) if from_type == "RGBA" else sum(v) / 3.0)
        if value[2] == "float":
            return value
        key = "%s.%s>float" % (self.qual(from_node), out.identifier)
        if from_type == "RGBA":
            return ("node", self.add_node(key, "blRgbToBw", {"color": {"node": value[1]}}),
                    "float")
        third = 1.0 / 3.0
        return ("node", self.add_node(key, "blVectorMathValue", {
            "a": {"node": value[1]}, "b": [third, third, third], "c": [0.0, 0.0, 0.0],
            "scale": 1.0, "operation": VECTOR_MATH_OPS.index("DOT_PRODUCT")}), "float")

    def output_value(self, node, out, user, user_socket):
        """The value of `node`'s output socket `out`; None for a --lenient fallback."""
        if node.mute:
            self.refuse("%s is muted; muted nodes are not supported" % self.node_where(node),
                        "using input '%s''s own value" % user_socket.name)
            return None
        if node.bl_idname == "ShaderNodeValue":
            return ("const", float(out.default_value))
        if node.bl_idname == "ShaderNodeRGB":
            return ("const", [float(v) for v in out.default_value][:3])
        spec = NODES.get(node.bl_idname)
        if spec is None:
            self.refuse("%s is not supported (it feeds '%s' of '%s'); supported nodes: %s"
                        % (self.node_where(node), user_socket.name, user.name,
                           supported_nodes_text()),
                        "using input '%s''s own value" % user_socket.name)
            return None
        fn = spec["fn"].get(out.identifier)
        if fn is None:
            self.refuse("%s: output '%s' is not supported; supported outputs: %s"
                        % (self.node_where(node), out.name, ", ".join(spec["fn"])),
                        "using input '%s''s own value" % user_socket.name)
            return None
        key = (self.qual(node), out.identifier)
        if key in self.done:
            return ("node", self.done[key], self.export.signatures[self.done_fn[key]][1])
        self.enter(node)
        fn = fn(node) if callable(fn) else fn
        args = self.node_args(node, spec, fn)
        self.stack.pop()
        node_id = self.add_node("%s.%s" % (self.qual(node), out.identifier), fn, args)
        self.done[key] = node_id
        self.done_fn[key] = fn
        return ("node", node_id, self.export.signatures[fn][1])

    def enter(self, node):
        """Pushes `node` on the path being translated; a node already on it is a loop."""
        name = self.qual(node)
        if name in self.stack:
            raise ExportError("%s: node loop: %s" % (self.where, " -> ".join(
                "'%s'" % n for n in self.stack[self.stack.index(name):] + [name])))
        self.stack.append(name)

    def node_args(self, node, spec, fn):
        self.node_checks(node)
        args = {}
        for ptype, param in self.export.signatures[fn][2]:
            if param in spec.get("props", {}):
                args[param] = spec["props"][param](node)
                continue
            if spec.get("object_props") and param in ("bboxMin", "bboxMax", "axisX", "axisY",
                                                       "axisZ"):
                args[param] = self.export.object_constants(self.obj)[param]
                continue
            ident = spec["sockets"][param]
            ident = ident(node) if callable(ident) else ident
            socket = next(s for s in node.inputs if s.identifier == ident)
            if spec.get("texture") and param == "vector" and self.link_source(socket) is None:
                # Cycles: an unlinked Vector of a texture node is the Generated coordinates.
                value = ("node", self.add_node("Generated", "blTexCoordGenerated", dict(
                    (k, self.export.object_constants(self.obj)[k])
                    for k in ("bboxMin", "bboxMax"))), "float3")
            else:
                value = self.socket_value(node, socket, "float" if ptype == "float" else "float3")
            args[param] = {"node": value[1]} if value[0] == "node" else value[1]
        if node.bl_idname == "ShaderNodeAmbientOcclusion":
            self.export.note_ao(self, node)
        return args

    def node_checks(self, node):
        if node.bl_idname == "ShaderNodeValToRGB" and node.color_ramp.color_mode != "RGB":
            self.refuse("%s: colour mode '%s' is not supported; supported: RGB"
                        % (self.node_where(node), node.color_ramp.color_mode),
                        "interpolating in RGB")
        if node.bl_idname == "ShaderNodeTexCoord" and node.object is not None:
            self.refuse("%s: 'From' another object ('%s') is not supported"
                        % (self.node_where(node), node.object.name),
                        "using this object's own coordinates")

    # --- Shaders ---
    def shader(self, socket, where_text):
        source = self.link_source(socket)
        if source is None or source.node is None:
            return None
        node = source.node
        with self.inside(source.path):
            kind = SHADERS.get(node.bl_idname)
            if kind is None or node.mute:
                self.refuse("%s is not supported as a shader; supported shaders: Diffuse BSDF, "
                            "Glossy BSDF, Emission, Mix Shader, Principled BSDF"
                            % self.node_where(node), "using a grey diffuse (0.8)")
                return dict(DEFAULT_SURFACE)
            self.enter(node)
            bsdf = getattr(self, "shader_" + kind)(node)
            self.stack.pop()
            return bsdf

    def input(self, node, ident, want):
        socket = next(s for s in node.inputs if s.identifier == ident)
        value = self.socket_value(node, socket, want)
        return {"node": value[1]} if value[0] == "node" else value[1]

    def normal_input(self, node, bsdf, ident="Normal"):
        socket = next(s for s in node.inputs if s.identifier == ident)
        source = self.link_source(socket)
        if source is None:
            return
        if source.node is None or source.node.bl_idname != "ShaderNodeBump":
            fed = source.node or source.out.node
            self.refuse("%s: input '%s' is fed by '%s' (%s); supported: a Bump node"
                        % (self.node_where(node), socket.name, fed.name, fed.bl_idname),
                        "using the surface's normal")
            return
        with self.inside(source.path):
            bsdf["normal"] = {"node": self.bump(source.node)}

    def bump(self, node):
        key = (self.qual(node), "Normal")
        if key in self.done:
            return self.done[key]
        self.enter(node)
        distance = self.input(node, "Distance", "float")
        if node.invert:  # Cycles negates the distance (into the surface instead of out)
            distance = -distance if not isinstance(distance, dict) else {"node": self.add_node(
                "%s.Distance>inverted" % self.qual(node), "blMath",
                {"a": distance, "b": -1.0, "c": 0.0, "operation": MATH_OPS.index("MULTIPLY"),
                 "useClamp": 0})}
        args = {"height": self.input(node, "Height", "float"),
                "strength": self.input(node, "Strength", "float"),
                "distance": distance, "normal": {"attr": "Normal"}}
        inner = self.link_source(next(s for s in node.inputs if s.identifier == "Normal"))
        if inner is not None and inner.node is not None and \
                inner.node.bl_idname == "ShaderNodeBump":
            with self.inside(inner.path):
                args["normal"] = {"node": self.bump(inner.node)}
        elif inner is not None:
            fed = inner.node or inner.out.node
            self.refuse("%s: input 'Normal' is fed by '%s' (%s); supported: a Bump node"
                        % (self.node_where(node), fed.name, fed.bl_idname),
                        "using the surface's normal")
        self.stack.pop()
        node_id = sanitize_id("%s/%s.Normal" % (self.name, self.qual(node)))
        self.nodes.append({"id": node_id, "fn": "bump", "args": args})
        self.done[key] = node_id
        return node_id

    def shader_diffuse(self, node):
        rough = next(s for s in node.inputs if s.identifier == "Roughness")
        if self.link_source(rough) is not None or rough.default_value != 0.0:
            self.refuse("%s: Roughness (Oren-Nayar) is not supported; supported: 0, unlinked"
                        % self.node_where(node), "using Lambert (roughness 0)")
        bsdf = {"bsdf": "diffuse", "color": self.input(node, "Color", "float3")}
        self.normal_input(node, bsdf)
        return bsdf

    def shader_glossy(self, node):
        aniso = next(s for s in node.inputs if s.identifier == "Anisotropy")
        if self.link_source(aniso) is not None or aniso.default_value != 0.0:
            self.refuse("%s: Anisotropy is not supported; supported: 0, unlinked"
                        % self.node_where(node), "using an isotropic GGX")
        if node.distribution not in ("GGX", "MULTI_GGX"):
            self.refuse("%s: distribution '%s' is not supported; supported: GGX"
                        % (self.node_where(node), node.distribution), "using GGX")
        bsdf = {"bsdf": "glossy", "color": self.input(node, "Color", "float3"),
                "roughness": self.input(node, "Roughness", "float")}
        self.normal_input(node, bsdf)
        return bsdf

    def shader_emission(self, node):
        return {"bsdf": "emission", "color": self.input(node, "Color", "float3"),
                "strength": self.input(node, "Strength", "float")}

    def shader_blend(self, node):
        a = self.shader(node.inputs[1], "Shader") or {"bsdf": "diffuse", "color": [0, 0, 0]}
        b = self.shader(node.inputs[2], "Shader") or {"bsdf": "diffuse", "color": [0, 0, 0]}
        return {"bsdf": "blend", "mask": self.input(node, "Fac", "float"), "a": a, "b": b}

    def shader_principled(self, node):
        defaults = self.export.principled_defaults()
        for socket in node.inputs:
            if socket.identifier in PRINCIPLED_INPUTS or socket.identifier in PRINCIPLED_IGNORED:
                continue
            value = getattr(socket, "default_value", None)
            changed = value is not None and _differs(value, defaults.get(socket.identifier))
            if socket.identifier == "Normal":
                continue
            if self.link_source(socket) is not None or changed:
                self.refuse("%s: input '%s' is %s; supported: %s (the others at their "
                            "defaults, unlinked)" % (self.node_where(node), socket.name,
                                                     "linked" if not changed else "changed",
                                                     ", ".join(PRINCIPLED_INPUTS)),
                            "using its default")
        bsdf = {"bsdf": "principled"}
        for ident, name in PRINCIPLED_INPUTS.items():
            want = "float3" if "Color" in ident else "float"
            bsdf[name] = self.input(node, ident, want)
        self.normal_input(node, bsdf)
        return bsdf


def _differs(a, b):
    if b is None:
        return False
    if isinstance(a, (int, float)):
        return abs(float(a) - float(b)) > 1e-6
    return any(abs(float(x) - float(y)) > 1e-6 for x, y in zip(a, b))


# --- The scene ------------------------------------------------------------------------------

def rows(matrix):
    return [[float(matrix[r][c]) for c in range(4)] for r in range(4)]


def file_name(text):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", text) or "_"


class Export:
    def __init__(self, bpy, options):
        self.bpy, self.options = bpy, options
        self.problems = Problems(options.lenient)
        self.signatures = library_signatures()
        check_table(self.signatures)
        self.functions = set()
        self.graph_nodes, self.materials, self.material_names = [], {}, {}
        self.ao = None
        self.files = set()
        self._principled = None
        self._constants = {}

    # Settings that only an object gives (Generated's bounds, Normal's axes).
    def object_constants(self, obj):
        if obj is None:
            box = {"bboxMin": [-1.0, -1.0, -1.0], "bboxMax": [1.0, 1.0, 1.0]}
            axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        else:
            loc, size = obj.data.texspace_location, obj.data.texspace_size
            box = {"bboxMin": [float(loc[k] - size[k]) for k in range(3)],
                   "bboxMax": [float(loc[k] + size[k]) for k in range(3)]}
            m = obj.matrix_world
            axes = [[float(m[r][c]) for r in range(3)] for c in range(3)]
        return dict(box, axisX=axes[0], axisY=axes[1], axisZ=axes[2])

    def principled_defaults(self):
        if self._principled is None:
            tree = self.bpy.data.node_groups.new("blender_export_defaults", "ShaderNodeTree")
            node = tree.nodes.new("ShaderNodeBsdfPrincipled")
            self._principled = {}
            for s in node.inputs:
                value = getattr(s, "default_value", None)
                if value is not None:
                    self._principled[s.identifier] = value if isinstance(value, (int, float)) \
                        else tuple(value)
            self.bpy.data.node_groups.remove(tree)
        return self._principled

    def note_ao(self, translator, node):
        distance = next(s for s in node.inputs if s.identifier == "Distance")
        if translator.link_source(distance) is not None:
            raise ExportError("%s: a linked Distance is not supported; supported: a constant "
                              "(it is the scene's render.aoDistance)"
                              % translator.node_where(node))
        if node.inside or node.only_local:
            translator.refuse("%s: 'Inside' and 'Only Local' are not supported"
                              % translator.node_where(node), "tracing outside, all objects")
        setting = (int(node.samples), float(distance.default_value))
        if self.ao is not None and self.ao[0] != setting:
            raise ExportError("%s: Ambient Occlusion with %d samples, distance %g, but %s has %d "
                              "samples, distance %g; texrender has one AO setting per scene"
                              % (translator.node_where(node), setting[0], setting[1],
                                 self.ao[1], self.ao[0][0], self.ao[0][1]))
        self.ao = (setting, "%s node '%s'" % (translator.where, node.name))

    # --- Materials ---
    def surface_output(self, material):
        tree = material.node_tree
        outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"
                   and n.target in ("ALL", "CYCLES")]
        active = [n for n in outputs if n.is_active_output] or outputs
        return active[0] if active else None

    def material(self, material, obj):
        """(graph material name, emission or None) for `material` on `obj`, translating it on
        first use. A material whose translation depends on the object (Generated bounds, Normal
        axes) and differs between objects gets one graph material per object, 'NAME@OBJECT'."""
        if material is None:
            self.materials.setdefault("__default", {"bsdf": dict(DEFAULT_SURFACE),
                                                    "emission": None, "nodes": []})
            return "__default", None
        base = sanitize_id(material.name)
        candidates = self.material_names.setdefault(material.name, [])
        result = self.translate(material, base, obj)
        for name in candidates:
            if self.materials[name]["bsdf"] == result["bsdf"] and \
                    self.materials[name]["nodes"] == result["nodes"]:
                return name, result["emission"]
        name = base
        if candidates:
            name = sanitize_id("%s@%s" % (material.name, obj.name))
            result = self.translate(material, name, obj)
        candidates.append(name)
        self.materials[name] = result
        self.graph_nodes.extend(result["nodes"])
        return name, result["emission"]

    def translate(self, material, name, obj):
        nodes = []
        translator = MaterialTranslator(self, material, name, obj, nodes)
        output = self.surface_output(material) if material.node_tree else None
        if output is None:
            bsdf = {"bsdf": "diffuse", "color": [float(c) for c in material.diffuse_color[:3]]}
        else:
            for ident in ("Volume", "Displacement"):
                socket = next((s for s in output.inputs if s.identifier == ident), None)
                if socket is not None and translator.link_source(socket) is not None:
                    translator.refuse("material '%s': the %s output is linked; supported: "
                                      "Surface" % (material.name, ident), "ignoring it")
            surface = next(s for s in output.inputs if s.identifier == "Surface")
            bsdf = translator.shader(surface, "Surface") or {"bsdf": "diffuse",
                                                               "color": [0.0, 0.0, 0.0]}
        emission = None
        if bsdf["bsdf"] == "emission" and not isinstance(bsdf["color"], dict) \
                and not isinstance(bsdf["strength"], dict):
            # A constant Emission is an area light: the mesh emits, the surface is black.
            color = bsdf["color"] if isinstance(bsdf["color"], list) else [bsdf["color"]] * 3
            emission = [to_f32(c * bsdf["strength"]) for c in color]  # as Cycles multiplies
            bsdf = {"bsdf": "diffuse", "color": [0.0, 0.0, 0.0]}
        return {"bsdf": bsdf, "emission": emission, "nodes": nodes}

    # --- Geometry ---
    def unique_file(self, stem, ext):
        """Object names that differ only in characters a file name cannot keep stay apart."""
        name, n = stem + ext, 1
        while name.lower() in self.files:
            n += 1
            name = "%s-%d%s" % (stem, n, ext)
        self.files.add(name.lower())
        return name

    def write_mesh(self, obj_eval, directory):
        """The evaluated mesh in object space, triangulated, one OBJ per material slot used:
        [(file, slot index)]."""
        import numpy as np
        mesh = obj_eval.to_mesh()
        try:
            mesh.calc_loop_triangles()
            ntri = len(mesh.loop_triangles)
            if ntri == 0:
                return []
            co = np.empty(len(mesh.vertices) * 3, np.float32)
            mesh.vertices.foreach_get("co", co)
            co = co.reshape(-1, 3)
            tv = np.empty(ntri * 3, np.int64)
            mesh.loop_triangles.foreach_get("vertices", tv)
            tl = np.empty(ntri * 3, np.int64)
            mesh.loop_triangles.foreach_get("loops", tl)
            mi = np.empty(ntri, np.int64)
            mesh.loop_triangles.foreach_get("material_index", mi)
            normals = np.empty(len(mesh.loops) * 3, np.float32)
            mesh.corner_normals.foreach_get("vector", normals)
            normals = normals.reshape(-1, 3)
            uv = None
            # Cycles' default UV map (Texture Coordinate's UV) is the one active for rendering.
            layer = next((l for l in mesh.uv_layers if l.active_render), mesh.uv_layers.active)
            if layer is not None:
                uv = np.empty(len(mesh.loops) * 2, np.float32)
                layer.data.foreach_get("uv", uv)
                uv = uv.reshape(-1, 2)
            tv, tl = tv.reshape(-1, 3), tl.reshape(-1, 3)
            files = []
            for slot in sorted(set(mi.tolist())):
                pick = mi == slot
                corners = tl[pick].reshape(-1)
                # Each position, normal and UV once (smooth meshes share them between corners).
                verts, vidx = np.unique(tv[pick].reshape(-1), return_inverse=True)
                vn, nidx = np.unique(normals[corners], axis=0, return_inverse=True)
                columns = [vidx.reshape(-1) + 1]
                if uv is not None:
                    vt, tidx = np.unique(uv[corners], axis=0, return_inverse=True)
                    columns.append(tidx.reshape(-1) + 1)
                columns.append(nidx.reshape(-1) + 1)
                corner = np.stack(columns, axis=1).reshape(-1, 3 * len(columns)).tolist()
                face = "f " + " ".join(["/".join(["%d"] * 3) if uv is not None
                                        else "%d//%d"] * 3) + "\n"
                name = self.unique_file("%s.%d" % (file_name(obj_eval.name), slot), ".obj")
                with open(os.path.join(directory, name), "w") as f:
                    f.write("# %s, material slot %d (blender_export.py)\n" % (obj_eval.name,
                                                                            slot))
                    f.write("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in co[verts].tolist()))
                    f.write("".join("vn %.7g %.7g %.7g\n" % tuple(n) for n in vn.tolist()))
                    if uv is not None:
                        f.write("".join("vt %.7g %.7g\n" % tuple(t) for t in vt.tolist()))
                    f.write("".join(face % tuple(c) for c in corner))
                files.append((name, slot))
            return files
        finally:
            obj_eval.to_mesh_clear()

    # --- Camera, lights, world ---
    def camera(self, scene, depsgraph):
        cam = scene.camera
        if self.options.camera:
            cam = scene.objects.get(self.options.camera)
            if cam is None or cam.type != "CAMERA":
                raise ExportError("scene '%s': no camera named '%s'; cameras: %s" % (
                    scene.name, self.options.camera, ", ".join(
                        sorted(o.name for o in scene.objects if o.type == "CAMERA")) or "none"))
        if cam is None:
            raise ExportError("scene '%s': no camera (set the scene's camera or pass --camera "
                              "NAME)" % scene.name)
        data = cam.data
        where = "camera '%s'" % cam.name
        if data.type != "PERSP":
            raise ExportError("%s: type '%s' is not supported; supported: PERSP (perspective)"
                              % (where, data.type))
        if data.shift_x != 0 or data.shift_y != 0:
            self.problems.refuse("%s: lens shift is not supported" % where, "ignoring the shift")
        r = scene.render
        width = int(r.resolution_x * r.resolution_percentage / 100)
        height = int(r.resolution_y * r.resolution_percentage / 100)
        if r.pixel_aspect_x != r.pixel_aspect_y:
            self.problems.refuse("%s: non-square pixels are not supported" % where,
                                 "using square pixels")
        fit = data.sensor_fit
        if fit == "AUTO":
            axis, sensor = ("x" if width >= height else "y"), data.sensor_width
        elif fit == "HORIZONTAL":
            axis, sensor = "x", data.sensor_width
        else:
            axis, sensor = "y", data.sensor_height
        fov = math.degrees(2.0 * math.atan(sensor / (2.0 * data.lens)))
        m = cam.evaluated_get(depsgraph).matrix_world
        pos = [float(m[k][3]) for k in range(3)]
        forward = [-float(m[k][2]) for k in range(3)]
        up = [float(m[k][1]) for k in range(3)]
        norm = math.sqrt(sum(v * v for v in forward))
        return ({"position": pos, "target": [pos[k] + forward[k] / norm for k in range(3)],
                 "up": up, "fov": fov, "fovAxis": axis}, {"width": width, "height": height})

    def sun(self, obj):
        light = obj.data
        where = "light '%s'" % obj.name
        # Settings texrender's sun has no counterpart for, each at Blender's default or refused.
        for attr, default, fallback in (("use_temperature", False, "using its Color"),
                                        ("use_nodes", False, "using its Color and Strength"),
                                        ("use_shadow", True, "casting shadows"),
                                        ("diffuse_factor", 1.0, "using 1"),
                                        ("specular_factor", 1.0, "using 1")):
            if getattr(light, attr, default) != default:
                self.problems.refuse("%s: '%s' is %s; supported: %s" % (
                    where, attr, getattr(light, attr), default), fallback)
        # Strength x 2^Exposure is what Cycles uses (Exposure is 0 by default).
        strength = float(light.energy) * 2.0 ** float(getattr(light, "exposure", 0.0))
        radius = max(float(light.angle) / 2.0, math.radians(0.01))
        if light.angle / 2.0 < radius:
            sys.stderr.write("blender_export: note: sun '%s': angle %g deg is below texrender's "
                             "smallest disc; using a radius of 0.01 deg\n"
                             % (obj.name, math.degrees(light.angle)))
        # Blender's strength is the irradiance (W/m^2) facing the sun; texrender's sun is a disc
        # of uniform radiance R over a cone of half-angle r: irradiance R * 2 pi (1 - cos r).
        scale = strength / (2.0 * math.pi * (1.0 - math.cos(radius)))
        m = obj.matrix_world
        direction = [float(m[k][2]) for k in range(3)]  # the sun shines along its -Z
        return {"type": "sun", "direction": direction,
                "radiance": [float(c) * scale for c in light.color],
                "angularRadius": math.degrees(radius)}

    def world(self, scene):
        world = scene.world
        if world is None:
            return None
        where = "world '%s'" % world.name
        color = [float(c) for c in world.color]
        tree = world.node_tree
        if tree is not None:
            outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputWorld"
                       and n.target in ("ALL", "CYCLES")]
            active = [n for n in outputs if n.is_active_output] or outputs
            if not active:
                return None
            links = [l for l in active[0].inputs["Surface"].links if not l.is_muted]
            if not links:
                return None
            node = links[0].from_node
            supported = "supported: a Background node with an unlinked Color and Strength"
            if node.bl_idname != "ShaderNodeBackground":
                self.problems.refuse("%s: node '%s' (%s) is not supported; %s" % (
                    where, node.name, node.bl_idname, supported), "using the world's colour")
            else:
                for s in node.inputs:
                    if s.identifier in ("Color", "Strength") and s.links:
                        self.problems.refuse(
                            "%s: node '%s' (%s): input '%s' is linked (%s); %s" % (
                                where, node.name, node.bl_idname, s.name,
                                s.links[0].from_node.bl_idname, supported),
                            "using its unlinked value")
                strength = float(node.inputs["Strength"].default_value)
                color = [float(c) * strength for c in node.inputs["Color"].default_value[:3]]
        if max(color) <= 0.0:
            return None
        return {"type": "sky", "radiance": color}

    # --- The whole scene ---
    @staticmethod
    def use_render_settings(scene):
        """The bpy module evaluates the viewport's depsgraph; Cycles renders with the render
        settings. The file is never saved, so the viewport takes them: each object's and
        modifier's render visibility, and subdivision's render levels."""
        for obj in scene.objects:
            obj.hide_viewport = obj.hide_render
            for modifier in obj.modifiers:
                modifier.show_viewport = modifier.show_render
                if hasattr(modifier, "render_levels") and hasattr(modifier, "levels"):
                    modifier.levels = modifier.render_levels

    def run(self, scene, staging, final_dir):
        self.use_render_settings(scene)
        view_layer = next((v for v in scene.view_layers if v.use), scene.view_layers[0])
        # A scene other than the context's has no depsgraph until one is asked for in its context.
        with self.bpy.context.temp_override(scene=scene, view_layer=view_layer):
            if self.options.frame is not None:
                scene.frame_set(self.options.frame)
            depsgraph = self.bpy.context.evaluated_depsgraph_get()
        camera, film = self.camera(scene, depsgraph)
        lights, meshes, written = [], [], {}
        sky = self.world(scene)
        if sky:
            lights.append(sky)
        mesh_dir = os.path.join(staging, "meshes")
        os.makedirs(mesh_dir)
        geometry = {"MESH", "CURVE", "SURFACE", "FONT", "META"}
        for inst in depsgraph.object_instances:
            obj = inst.object
            if obj.type == "LIGHT":
                if obj.data.type == "SUN":
                    lights.append(self.sun(obj))
                else:
                    self.problems.refuse("light '%s': type '%s' is not supported; supported: "
                                         "SUN (area lights: meshes with an Emission material)"
                                         % (obj.name, obj.data.type), "leaving it out")
                continue
            if obj.type not in geometry:
                continue
            key = obj.original.name
            if key not in written:
                written[key] = self.write_mesh(obj, mesh_dir)
            slots = obj.material_slots
            for name, slot in written[key]:
                material = slots[slot].material if slot < len(slots) else None
                graph_name, emission = self.material(material, obj)
                entry = {"obj": "meshes/" + name, "material": graph_name,
                         "transform": {"matrix": rows(inst.matrix_world)}}
                if emission is not None and max(emission) > 0.0:
                    entry["emission"] = emission
                meshes.append(entry)
        if not meshes:
            raise ExportError("scene '%s': nothing to render: no visible mesh with faces"
                              % scene.name)
        render = {}
        if scene.render.engine == "CYCLES":
            # Cycles' bounce b is texrender's (Mitsuba's) depth b + 2: depth 2 is direct light.
            render["spp"] = int(scene.cycles.samples)
            render["maxDepth"] = int(scene.cycles.max_bounces) + 2
        if self.ao is not None:
            render["aoSamples"], render["aoDistance"] = self.ao[0]
        scene_json = {"texrender": 1, "camera": camera, "film": film, "lights": lights,
                      "meshes": meshes}
        if render:
            scene_json["render"] = render
        self.write_json(os.path.join(staging, "scene.json"), scene_json)
        self.write_json(os.path.join(staging, "graph.json"), self.graph_json(final_dir))

    def graph_json(self, final_dir):
        files = sorted(set(self.signatures[f][0] for f in self.functions
                           if f in self.signatures))
        sources = []
        for name in files:
            path = os.path.join(LIBRARY, name)
            try:
                sources.append(os.path.relpath(path, final_dir).replace(os.sep, "/"))
            except ValueError:  # another drive
                sources.append(path)
        materials = {}
        for name, m in self.materials.items():
            materials[name] = m["bsdf"]
        return {"texcc": 1, "sources": sources, "nodes": self.graph_nodes,
                "materials": materials}

    @staticmethod
    def write_json(path, value):
        import json
        with open(path, "w") as f:
            text = json.dumps(short_floats(value), indent=1)
            # Arrays of numbers on one line each.
            text = re.sub(r"\[\s+([-+0-9.eE,\s]+?)\s+\]", lambda m: "[%s]" % ", ".join(
                x.strip() for x in m.group(1).split(",")), text)
            f.write(text + "\n")


def to_f32(value):
    import struct
    return struct.unpack("<f", struct.pack("<f", value))[0]


def short_floats(value):
    """Blender's values are float32: write each as the shortest decimal that reads back as the
    same float32 (0.6, not 0.6000000238418579)."""
    import struct
    if isinstance(value, float):
        single = struct.unpack("<f", struct.pack("<f", value))[0] if abs(value) < 3e38 else value
        if single != value:
            return value  # a double the exporter computed (fov, radiance): keep it
        for digits in range(6, 10):
            text = float("%.*g" % (digits, value))
            if struct.unpack("<f", struct.pack("<f", text))[0] == single:
                return text
        return value
    if isinstance(value, list):
        return [short_floats(v) for v in value]
    if isinstance(value, dict):
        return {k: short_floats(v) for k, v in value.items()}
    return value


# --- Driver ---------------------------------------------------------------------------------

def parse_args(argv, inside_blender):
    ap = argparse.ArgumentParser(prog="blender_export.py",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("blend", nargs=None if not inside_blender else "?",
                    help="the .blend file (inside Blender: the file Blender opened)")
    ap.add_argument("-o", dest="outdir", required=True, help="output folder (replaced whole)")
    ap.add_argument("--scene", help="scene name (default: the file's active scene)")
    ap.add_argument("--camera", help="camera object (default: the scene's camera)")
    ap.add_argument("--frame", type=int, help="frame to export (default: the current frame)")
    ap.add_argument("--lenient", action="store_true",
                    help="untranslatable nodes, inputs and lights are warnings with a fallback")
    return ap.parse_args(argv)


def check_blend(path):
    if not os.path.isfile(path):
        raise ExportError("%s: no such file" % path)
    with open(path, "rb") as f:
        head = f.read(7)
    # Uncompressed .blend files start with "BLENDER"; compressed ones are zstd or gzip streams.
    if not (head.startswith(b"BLENDER") or head.startswith(b"\x28\xb5\x2f\xfd")
            or head.startswith(b"\x1f\x8b")):
        raise ExportError("%s: not a .blend file (it does not start with 'BLENDER')" % path)


def replace_dir(staging, final_dir):
    """Moves the finished export into place; an older OUTDIR goes only once the new one is in."""
    old = None
    if os.path.lexists(final_dir):
        old = tempfile.mkdtemp(prefix=".old-", dir=os.path.dirname(final_dir))
        os.rename(final_dir, os.path.join(old, "x"))
    os.rename(staging, final_dir)
    if old:
        shutil.rmtree(old)


def main():
    # Inside Blender (`blender -b FILE --python blender_export.py -- ARGS`) bpy is loaded already
    # and our arguments follow "--".
    inside_blender = "bpy" in sys.modules and "--" in sys.argv
    argv = sys.argv[sys.argv.index("--") + 1:] if inside_blender else sys.argv[1:]
    options = parse_args(argv, inside_blender)
    final_dir = os.path.abspath(options.outdir)
    parent = os.path.dirname(final_dir)
    staging = None
    try:
        if options.blend or not inside_blender:
            check_blend(options.blend)
        if not os.path.isdir(parent):
            raise ExportError("%s: the folder does not exist" % parent)
        if not inside_blender:
            ensure_bpy("blender_export", exact=False)
        import bpy
        if options.blend and os.path.abspath(options.blend) != os.path.abspath(
                bpy.data.filepath or ""):
            try:
                bpy.ops.wm.open_mainfile(filepath=os.path.abspath(options.blend))
            except RuntimeError as e:
                raise ExportError("%s: Blender cannot read it: %s" % (
                    options.blend, str(e).strip().splitlines()[-1]))
        scene = bpy.context.scene
        if options.scene:
            scene = bpy.data.scenes.get(options.scene)
            if scene is None:
                raise ExportError("no scene named '%s'; scenes: %s" % (
                    options.scene, ", ".join(s.name for s in bpy.data.scenes)))
        staging = tempfile.mkdtemp(prefix=".%s.tmp-" % os.path.basename(final_dir), dir=parent)
        export = Export(bpy, options)
        export.run(scene, staging, final_dir)
        replace_dir(staging, final_dir)
        staging = None
        print("blender_export: %s: %d meshes, %d materials, %d graph nodes -> %s" % (
            options.blend or bpy.data.filepath, len(os.listdir(os.path.join(final_dir, "meshes"))),
            len(export.materials), len(export.graph_nodes), options.outdir))
    except ExportError as e:
        sys.stderr.write("blender_export: error: %s\n" % e)
        sys.exit(1)
    finally:
        if staging and os.path.isdir(staging):
            shutil.rmtree(staging)


if __name__ == "__main__":
    main()
