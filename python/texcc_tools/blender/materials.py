"""blender_materials.py: a Blender material's node tree as texcc graph nodes and a BSDF
(MaterialTranslator), and the exporter's errors (ExportError, Problems). NODES in blender_nodes.py
is the table of which library function and which arguments each Blender node becomes; this module
walks the tree with it. Used by scripts/blender_export.py."""

import contextlib
import math
import sys

from texcc_tools.blender.nodes import (
    DEFAULT_SURFACE, MATH_OPS, NODES, PASS_THROUGH, PRINCIPLED_IGNORED,
    PRINCIPLED_INPUTS, SHADERS, VECTOR_MATH_OPS, instancers, object_info, supported_nodes_text)


class ExportError(Exception):
    """One problem, one line: what and where. Raised for a problem with no fallback (a node
    loop, no camera): the export stops there."""


class ProblemsFound(ExportError):
    """Raised once a strict export has found its problems (Problems.errors, printed one a
    line): nothing is written."""


class Problems:
    """A problem with a fallback. Lenient: a warning, and the caller's fallback is used.
    Strict: an error, collected, and the caller's fallback is used too so that the export goes
    on to find the next one: the export lists every problem of the file at once and writes
    nothing (Export.run raises at the end while `errors` is not empty)."""

    def __init__(self, lenient):
        self.lenient = lenient
        self.errors = []
        self.seen = set()

    def refuse(self, message, fallback_text):
        if (message, fallback_text) in self.seen:  # the same problem found again (a material
            return                                 # translated for a second object): once
        self.seen.add((message, fallback_text))
        if self.lenient:
            sys.stderr.write("blender_export: warning: %s; %s\n" % (message, fallback_text))
        else:
            self.errors.append("%s (--lenient makes this a warning: %s)" % (message,
                                                                            fallback_text))


# Mix Shaders nest BSDFs in graph.json; texcc reads JSON nested up to 256 levels.
MAX_SHADER_DEPTH = 100
OBJECT_PARAMS = ("bboxMin", "bboxMax", "axisX", "axisY", "axisZ")


def finite(value):
    """Whether every number in `value` (a number or nested lists) is finite."""
    if isinstance(value, (list, tuple)):
        return all(finite(v) for v in value)
    return not isinstance(value, float) or math.isfinite(value)


def replace_non_finite(value, default=0.0):
    if isinstance(value, (list, tuple)):
        return [replace_non_finite(v, default) for v in value]
    return default if isinstance(value, float) and not math.isfinite(value) else value


def number_text(value):
    if isinstance(value, (list, tuple)):
        return "(%s)" % ", ".join(number_text(v) for v in value)
    return "%g" % value


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
        self.shader_depth = 0
        self._correction_noted = False
        self._links = {}
        self.where = "material '%s'" % material.name

    def qual(self, node):
        """The node's name, with the groups it sits in (for messages and graph ids: a node
        named 'G/N' and node 'N' in group 'G' read alike; node_key tells them apart)."""
        return "/".join([g.name for g in self.path] + [node.name])

    def node_key(self, node):
        return tuple(g.name for g in self.path) + (node.name,)

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

    def add_node(self, key, fn, args, owner=None):
        """The graph node `key` (its id's text) of this material; `owner` (default `key`)
        identifies it: another owner whose id reads the same gets a suffixed one."""
        node_id = self.export.node_id(self.name, key, owner)
        if node_id not in self.ids:
            self.ids.add(node_id)
            self.nodes.append({"id": node_id, "fn": fn, "args": args})
            self.export.functions.add(fn)
        return node_id

    def links_to(self, socket):
        """The unmuted links into `socket`. bpy's socket.links scans every link of the tree
        (a 1,500-node chain took 13 s); each tree's links are indexed once per translation
        (the trees do not change during one)."""
        tree = socket.id_data
        index = self._links.get(tree.as_pointer())
        if index is None:
            index = self._links[tree.as_pointer()] = {}
            for link in tree.links:
                if not link.is_muted:
                    index.setdefault(link.to_socket.as_pointer(), []).append(link)
        return index.get(socket.as_pointer(), [])

    # A value is ("const", number or list) or ("node", id, "float" | "float3").
    def link_source(self, socket):
        """The Source feeding `socket` (in the current groups), through reroutes and into and
        out of node groups; None if unlinked."""
        path, crossed = list(self.path), False
        while True:
            links = self.links_to(socket)
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
            with self.inside(source.path):  # the group node's own path
                value = self.socket_value_unlinked(source.out)
            return self.convert(value, source.out.type, want, None, None)
        self.prepare(source)
        with self.inside(source.path):
            value = self.output_value(source.node, source.out, node, socket)
            if value is None:  # --lenient fallback: the socket's own value
                return self.socket_value_unlinked(socket)
            return self.convert(value, source.out.type, want, source.node, source.out)

    def socket_value_unlinked(self, socket):
        value = socket.default_value
        if isinstance(value, (int, float)):
            value = float(value)
        else:
            value = [float(v) for v in value][:3]
        return ("const", self.checked(socket, "input", value))

    def checked(self, socket, kind, value):
        """`value` of `socket` if finite; else a problem, and the socket's default (Blender's
        for this node type) as the fallback. graph.json is strict JSON: no NaN or Infinity."""
        if finite(value):
            return value
        default = self.export.socket_default(socket) if not socket.is_output else \
            (0.0 if isinstance(value, float) else [0.0] * len(value))
        if isinstance(value, list):
            default = list(default)[:len(value)]
        self.refuse("%s: %s '%s' is %s; supported: finite values" % (
            self.node_where(socket.node), kind, socket.name, number_text(value)),
            "using its default %s" % number_text(default))
        return default

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
        owner = (self.node_key(from_node), out.identifier, ">float")
        if from_type == "RGBA":
            return ("node", self.add_node(key, "blRgbToBw", {"color": {"node": value[1]}},
                                          owner), "float")
        third = 1.0 / 3.0
        return ("node", self.add_node(key, "blVectorMathValue", {
            "a": {"node": value[1]}, "b": [third, third, third], "c": [0.0, 0.0, 0.0],
            "scale": 1.0, "operation": VECTOR_MATH_OPS.index("DOT_PRODUCT")}, owner), "float")

    def output_value(self, node, out, user, user_socket):
        """The value of `node`'s output socket `out`; None for a --lenient fallback."""
        if node.mute:
            self.refuse("%s is muted; muted nodes are not supported" % self.node_where(node),
                        "using input '%s''s own value" % user_socket.name)
            return None
        if node.bl_idname == "ShaderNodeValue":
            return ("const", self.checked(out, "output", float(out.default_value)))
        if node.bl_idname == "ShaderNodeRGB":
            return ("const", self.checked(out, "output",
                                          [float(v) for v in out.default_value][:3]))
        spec = NODES.get(node.bl_idname)
        if node.bl_idname == "ShaderNodeBump":
            self.refuse("%s feeds '%s' of '%s'; supported: a Bump's Normal into a BSDF's, a "
                        "Fresnel's, a Layer Weight's or another Bump's Normal"
                        % (self.node_where(node), user_socket.name, user.name),
                        "using input '%s''s own value" % user_socket.name)
            return None
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
        key = (self.node_key(node), out.identifier)
        if key in self.done:
            return ("node", self.done[key], self.export.signatures[self.done_fn[key]][1])
        self.enter(node)
        fn = fn(node) if callable(fn) else fn
        args = self.node_args(node, spec, fn)
        self.stack.pop()
        node_id = self.add_node("%s.%s" % (self.qual(node), out.identifier), fn, args, key)
        self.done[key] = node_id
        self.done_fn[key] = fn
        return ("node", node_id, self.export.signatures[fn][1])

    def translatable(self, source):
        """(spec, function) of a Source that output_value translates into a graph node without
        a problem of its own; None for the rest (constants, muted, unsupported: leaves)."""
        node = source.node
        if node is None or node.mute:
            return None
        spec = NODES.get(node.bl_idname)
        fn = spec["fn"].get(source.out.identifier) if spec else None
        if fn is None:
            return None
        return spec, (fn(node) if callable(fn) else fn)

    def param_socket(self, node, spec, param):
        """The input socket feeding `param`; None for a setting or an object constant."""
        if param in spec.get("props", {}) or spec.get("object_info") or \
                (spec.get("object_props") and param in OBJECT_PARAMS):
            return None
        if param not in spec["sockets"]:  # an image (sam2D): bound, not fed
            return None
        ident = spec["sockets"][param]
        ident = ident(node) if callable(ident) else ident
        return next(s for s in node.inputs if s.identifier == ident)

    def prepare(self, first):
        """Translates every translatable node feeding the Source `first`, and `first`, inputs
        before their users, walking with an explicit stack: the recursive translation
        (output_value -> node_args -> socket_value) then finds each input translated and stays
        one level deep however long the chain (1,500 chained Math nodes were a RecursionError).
        A node reached again on the current path is a loop."""
        def entry(source):
            with self.inside(source.path):
                found = self.translatable(source)
                if found is None:
                    return None
                node_key = self.node_key(source.node)
                key = (node_key, source.out.identifier)
                if key in self.done:
                    return None
                spec, fn = found
                children = []
                for _, param in self.export.signatures[fn][2]:
                    socket = self.param_socket(source.node, spec, param)
                    child = self.link_source(socket) if socket is not None else None
                    if child is not None and child.node is not None:
                        children.append(child)
                return [source, key, node_key, children, 0]

        top = entry(first)
        if top is None:
            return
        stack, on_path = [top], [top[2]]
        while stack:
            item = stack[-1]
            source, key, node_key, children, k = item
            if k < len(children):
                item[4] += 1
                child = entry(children[k])
                if child is None:
                    continue
                if child[2] in on_path:
                    loop = on_path[on_path.index(child[2]):] + [child[2]]
                    raise ExportError("%s: node loop: %s" % (self.where, " -> ".join(
                        "'%s'" % "/".join(n) for n in loop)))
                stack.append(child)
                on_path.append(child[2])
                continue
            stack.pop()
            on_path.pop()
            if key not in self.done:
                with self.inside(source.path):
                    self.output_value(source.node, source.out, None, None)

    def enter(self, node):
        """Pushes `node` on the path being translated; a node already on it is a loop."""
        key = self.node_key(node)
        if key in self.stack:
            raise ExportError("%s: node loop: %s" % (self.where, " -> ".join(
                "'%s'" % "/".join(n) for n in self.stack[self.stack.index(key):] + [key])))
        self.stack.append(key)

    def node_args(self, node, spec, fn):
        self.node_checks(node)
        args = {}
        for ptype, param in self.export.signatures[fn][2]:
            if ptype == "sam2D":
                args[param] = {"image": self.export.image_binding(self, node)}
                continue
            if param in spec.get("props", {}):
                value = spec["props"][param](node)
                if not finite(value):
                    self.refuse("%s: setting '%s' is %s; supported: finite values"
                                % (self.node_where(node), param, number_text(value)),
                                "using 0 for its NaN and infinite numbers")
                    value = replace_non_finite(value)
                args[param] = value
                continue
            if spec.get("object_info"):
                args[param] = object_info(self.obj, self.material)[param]
                continue
            socket = self.param_socket(node, spec, param)
            if socket is None:
                args[param] = self.export.object_constants(self.obj)[param]
                continue
            if param in spec.get("unlinked_attr", {}):
                source = self.link_source(socket)
                if source is None:
                    args[param] = {"attr": spec["unlinked_attr"][param]}
                    continue
                if source.node is not None and source.node.bl_idname == "ShaderNodeBump" \
                        and not source.node.mute:  # a bumped normal (graph.md "Bump")
                    with self.inside(source.path):
                        args[param] = {"node": self.bump(source.node)}
                    continue
            if spec.get("texture") == "uv" and param == "vector" and \
                    self.link_source(socket) is None:
                # Cycles: an unlinked Vector of an Image Texture is the UV map.
                value = ("node", self.add_node("UV", "blTexCoordUV", {}), "float3")
            elif spec.get("texture") and param == "vector" and self.link_source(socket) is None:
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
        if node.bl_idname == "ShaderNodeTexImage":
            if node.projection != "FLAT":
                self.refuse("%s: projection '%s' is not supported; supported: FLAT"
                            % (self.node_where(node), node.projection), "using FLAT")
        if node.bl_idname == "ShaderNodeObjectInfo" and self.obj is not None:
            used = [o.name for o in node.outputs if o.name in ("Location", "Random")
                    and self.links_from(o)]
            found = instancers(self.obj) if used else []
            if found:
                self.refuse("%s: %s of object '%s', which '%s' instances; supported: objects "
                            "that are not instanced (Cycles gives each instance its own, the "
                            "exporter translates a material once per object)"
                            % (self.node_where(node), " and ".join(used), self.obj.name,
                               found[0]), "using the object's own")
        if node.bl_idname == "ShaderNodeAttribute":
            self.attribute_checks(node)
        if node.bl_idname == "ShaderNodeNormalMap":
            self.normal_map_checks(node)
        if node.bl_idname == "ShaderNodeTexCoord" and node.object is not None:
            self.refuse("%s: 'From' another object ('%s') is not supported"
                        % (self.node_where(node), node.object.name),
                        "using this object's own coordinates")

    def links_from(self, socket):
        tree = socket.id_data
        return [link for link in tree.links if link.from_socket == socket and not link.is_muted]

    def normal_map_checks(self, node):
        """The Normal Map node in Tangent Space over the render UV map: the tangents the
        exporter writes (blender_tangents.py) are that map's."""
        if node.space != "TANGENT":
            self.refuse("%s: Space '%s' is not supported; supported: TANGENT (texrender's "
                        "normal map is the tangent-space one)" % (self.node_where(node),
                                                                  node.space),
                        "using Tangent Space")
        if node.uv_map:
            mesh = getattr(self.obj, "data", None)
            layers = getattr(mesh, "uv_layers", None) or []
            render = next((l for l in layers if l.active_render), None) or \
                (layers.active if layers else None)
            if render is None or node.uv_map != render.name:
                self.refuse("%s: UV map '%s' is not supported; supported: the mesh's render UV "
                            "map%s (texrender's meshes carry its tangents only)"
                            % (self.node_where(node), node.uv_map,
                               " '%s'" % render.name if render is not None else ", which it lacks"),
                            "using the render UV map")

    def attribute_checks(self, node):
        """The Attribute node reads the UV map texrender exports (the render UV map, TexCoord0):
        texrender's meshes carry no other per-vertex attribute (colour attributes, other UV maps,
        generic attributes) and no object or view-layer attributes."""
        mesh = getattr(self.obj, "data", None)
        layers = getattr(mesh, "uv_layers", None) or []
        render = next((l for l in layers if l.active_render), None) or \
            (layers.active if layers else None)
        name = node.attribute_name
        if node.attribute_type == "GEOMETRY" and render is not None and name == render.name:
            return
        what = "attribute '%s'" % name
        if node.attribute_type != "GEOMETRY":
            what = "%s attribute '%s'" % (node.attribute_type.lower().replace("_", " "), name)
        elif mesh is not None and name in getattr(mesh, "color_attributes", {}):
            what = "colour attribute '%s'" % name
        elif any(l.name == name for l in layers):
            what = "UV map '%s' (not the one that renders)" % name
        self.refuse("%s: %s is not supported; supported: the mesh's render UV map%s "
                    "(texrender's meshes carry no other attribute)"
                    % (self.node_where(node), what,
                       " '%s'" % render.name if render is not None else ", which it lacks"),
                    "using the UV map")

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
            if self.shader_depth >= MAX_SHADER_DEPTH:
                raise ExportError("%s: shaders nested more than %d deep (Mix Shaders in Mix "
                                  "Shaders); graph.json nests BSDFs, and texcc reads JSON up to "
                                  "256 levels deep" % (self.node_where(node), MAX_SHADER_DEPTH))
            self.enter(node)
            self.shader_depth += 1
            bsdf = getattr(self, "shader_" + kind)(node)
            self.shader_depth -= 1
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
        if source.node is not None and source.node.bl_idname == "ShaderNodeNormalMap":
            # A library node (textures/blender/normal_map.cl) like any other.
            value = self.socket_value(node, socket, "float3")
            if value[0] == "node":
                bsdf["normal"] = {"node": value[1]}
            return
        if source.node is None or source.node.bl_idname != "ShaderNodeBump":
            fed = source.node or source.out.node
            self.refuse("%s: input '%s' is fed by '%s' (%s); supported: a Bump or Normal Map "
                        "node" % (self.node_where(node), socket.name, fed.name, fed.bl_idname),
                        "using the surface's normal")
            return
        with self.inside(source.path):
            bsdf["normal"] = {"node": self.bump(source.node)}

    def bump(self, node):
        """The graph id of `node`'s bump, and of the Bump nodes chained into its Normal, the
        innermost first (a loop, not recursion: a chain may be long)."""
        chain, path, names, fed = [], list(self.path), set(), None
        inner_id = None
        while True:
            with self.inside(path):
                key = (self.node_key(node), "Normal")
                if key in self.done:
                    inner_id = self.done[key]
                    break
                if key[0] in names or key[0] in self.stack:
                    raise ExportError("%s: node loop through the Normal inputs of Bump '%s'"
                                      % (self.where, self.qual(node)))
                names.add(key[0])
                chain.append((node, path))
                inner = self.link_source(next(s for s in node.inputs
                                              if s.identifier == "Normal"))
            if inner is not None and inner.node is not None and \
                    inner.node.bl_idname == "ShaderNodeBump":
                node, path = inner.node, inner.path
                continue
            if inner is not None:
                fed = inner.node or inner.out.node
            break
        for k, (node, path) in enumerate(reversed(chain)):
            with self.inside(path):
                inner_id = self.bump_one(node, inner_id, fed if k == 0 else None)
        return inner_id

    def bump_one(self, node, inner_id, fed):
        """One Bump node's graph node; `inner_id`: the Bump feeding its Normal, `fed`: the
        node that feeds it instead (refused: the surface's normal is used)."""
        self.enter(node)
        self.bump_checks(node)
        distance = self.input(node, "Distance", "float")
        if node.invert:  # Cycles negates the distance (into the surface instead of out)
            distance = -distance if not isinstance(distance, dict) else {"node": self.add_node(
                "%s.Distance>inverted" % self.qual(node), "blMath",
                {"a": distance, "b": -1.0, "c": 0.0, "operation": MATH_OPS.index("MULTIPLY"),
                 "useClamp": 0}, (self.node_key(node), "Distance>inverted"))}
        args = {"height": self.input(node, "Height", "float"),
                "strength": self.input(node, "Strength", "float"),
                "distance": distance, "normal": {"attr": "Normal"}}
        if inner_id is not None:
            args["normal"] = {"node": inner_id}
        elif fed is not None and fed.bl_idname == "ShaderNodeNormalMap":
            normal = self.input(node, "Normal", "float3")
            if isinstance(normal, dict):
                args["normal"] = normal
        elif fed is not None:
            self.refuse("%s: input 'Normal' is fed by '%s' (%s); supported: a Bump or Normal "
                        "Map node" % (self.node_where(node), fed.name, fed.bl_idname),
                        "using the surface's normal")
        self.stack.pop()
        key = (self.node_key(node), "Normal")
        node_id = self.export.node_id(self.name, "%s.Normal" % self.qual(node), key)
        self.nodes.append({"id": node_id, "fn": "bump", "args": args})
        self.done[key] = node_id
        return node_id

    def bump_checks(self, node):
        """What texrender's bump does not read: another Filter Width than Cycles' default 0.1
        (the offsets are 0.1 of the ray footprint, graph.md "The step"), and a material whose
        Bump Map Correction is off (texrender always shadows bumped diffuse as Cycles' on)."""
        width = next((s for s in node.inputs if s.identifier == "Filter Width"), None)
        if width is not None and (self.link_source(width) is not None
                                  or abs(float(width.default_value) - 0.1) > 1e-6):
            self.refuse("%s: Filter Width is %s; supported: 0.1 (Cycles' default), unlinked"
                        % (self.node_where(node), "linked" if self.link_source(width)
                           else "%g" % width.default_value), "using 0.1")
        correction = getattr(getattr(self.material, "cycles", None), "use_bump_map_correction",
                             True)
        if not correction and not self._correction_noted:
            self._correction_noted = True
            self.refuse("%s: Bump Map Correction (material settings) is off; supported: on "
                        "(texrender always shadows bumped diffuse as Cycles does with it on)"
                        % self.where, "rendering with it on")

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
        self.multiscatter_ggx(node)
        bsdf = {"bsdf": "glossy", "color": self.input(node, "Color", "float3"),
                "roughness": self.input(node, "Roughness", "float")}
        self.normal_input(node, bsdf)
        return bsdf

    def multiscatter_ggx(self, node):
        """texrender's GGX lobes are Cycles' Multiscatter GGX (Blender's default): the energy
        lost to single scattering is added back. Plain GGX (none added back) and the other
        distributions render differently: refused."""
        if node.distribution != "MULTI_GGX":
            self.refuse("%s: distribution '%s' is not supported; supported: Multiscatter GGX "
                        "(Blender's default)" % (self.node_where(node), node.distribution),
                        "using Multiscatter GGX")

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
        self.multiscatter_ggx(node)
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
