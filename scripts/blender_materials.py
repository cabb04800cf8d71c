"""blender_materials.py: a Blender material's node tree as texcc graph nodes and a BSDF
(MaterialTranslator), and the exporter's errors (ExportError, Problems). NODES in blender_nodes.py
is the table of which library function and which arguments each Blender node becomes; this module
walks the tree with it. Used by scripts/blender_export.py."""

import contextlib
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_nodes import (  # noqa: E402
    DEFAULT_SURFACE, MATH_OPS, NODES, PASS_THROUGH, PRINCIPLED_IGNORED, PRINCIPLED_INPUTS,
    SHADERS, VECTOR_MATH_OPS, supported_nodes_text)


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
