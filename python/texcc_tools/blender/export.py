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
import math
import os
import re
import shutil
import sys
import tempfile

from texcc_tools.atomic import AtomicWriteError, atomic_open, make_dir, new_dir_mode
from texcc_tools.blender.lights import LightsExport
from texcc_tools.blender.materials import (
    ExportError, MaterialTranslator, Problems, ProblemsFound, finite, sanitize_id)
from texcc_tools.blender.nodes import (
    DEFAULT_SURFACE, IMAGE_COLORSPACES, LIBRARY, check_table, library_signatures)
from texcc_tools.blender.settings import check_render_settings
from texcc_tools.blender.tangents import mikk_tangents, uses_normal_map
from texcc_tools.bpy_env import ensure_bpy
from texcc_tools.paths import ROOT


# --- The scene ------------------------------------------------------------------------------

def rows(matrix):
    return [[float(matrix[r][c]) for c in range(4)] for r in range(4)]


def file_name(text):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", text) or "_"


class Export(LightsExport):
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
        self._images = {}  # Blender image name (or None: missing) -> graph.json image binding
        self._constants = {}
        self._socket_defaults = {}
        # graph.json ids: {id: owner} and {owner: id}; names that sanitise alike get a suffix.
        self._ids = {"material": ({}, {}), "node": ({}, {}), "image": ({}, {})}
        self.renamed = []  # (kind, name as in Blender, id), for the export's log

    def unique_id(self, kind, owner, name, label=None):
        """The graph.json id of `owner` (a material, or a node of a material): `name` with the
        characters graph.json cannot hold replaced, and '~2', '~3' ... added when another owner
        has that id already (7 materials named alike were 4 merged ones, silently)."""
        by_id, by_owner = self._ids[kind]
        if owner in by_owner:
            return by_owner[owner]
        base = sanitize_id(name)
        ident, n = base, 1
        while ident in by_id:
            n += 1
            ident = "%s~%d" % (base, n)
        by_id[ident], by_owner[owner] = owner, ident
        if ident != name:
            self.renamed.append((label or "%s '%s'" % (kind, printable(name)), ident))
        return ident

    def material_id(self, material, obj=None):
        if obj is None:
            return self.unique_id("material", (material.name,), material.name)
        return self.unique_id("material", (material.name, obj.name),
                              "%s@%s" % (material.name, obj.name),
                              "material '%s' on object '%s'" % (printable(material.name),
                                                                printable(obj.name)))

    def node_id(self, material_id, key, owner=None):
        label = None
        if isinstance(owner, tuple) and isinstance(owner[0], tuple):  # (node path, output...)
            label = "node %s of material '%s', output '%s'%s" % (
                " > ".join("'%s'" % printable(n) for n in owner[0]), material_id, owner[1],
                "".join(" %s" % extra for extra in owner[2:]))
        return self.unique_id("node", (material_id, owner or key), "%s/%s" % (material_id, key),
                              label)

    def socket_default(self, socket):
        """Blender's default of `socket` for its node type (a new node's), as a float or a
        list; zeros where there is none (a group's socket)."""
        node = socket.node
        key = (node.bl_idname, socket.is_output, socket.identifier)
        if key not in self._socket_defaults:
            value = None
            tree = self.bpy.data.node_groups.new("blender_export_defaults", "ShaderNodeTree")
            try:
                fresh = tree.nodes.new(node.bl_idname)
                sockets = fresh.outputs if socket.is_output else fresh.inputs
                match = next((s for s in sockets if s.identifier == socket.identifier), None)
                value = getattr(match, "default_value", None)
            except RuntimeError:  # a node type that cannot be created alone
                pass
            finally:
                self.bpy.data.node_groups.remove(tree)
            current = socket.default_value
            if value is None or not finite(_numbers(value)):
                value = 0.0 if isinstance(current, (int, float)) else [0.0] * len(current)
            self._socket_defaults[key] = _numbers(value)
        return self._socket_defaults[key]

    def check_finite(self, where, what, value, fallback):
        """False (and a problem, with `fallback` in lenient mode) if `value` has a NaN or an
        infinity: graph.json and scene.json are strict JSON."""
        if finite(value):
            return True
        self.problems.refuse("%s: %s has a NaN or infinite value; supported: finite values"
                             % (where, what), fallback)
        return False

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
        setting = (int(node.samples),
                   translator.checked(distance, "input", float(distance.default_value)))
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
            name = self.unique_id("material", ("__default",), "__default")
            self.materials.setdefault(name, {"bsdf": dict(DEFAULT_SURFACE), "emission": None,
                                             "nodes": []})
            return name, None
        base = self.material_id(material)
        candidates = self.material_names.setdefault(material.name, [])
        result = self.translate(material, base, obj)
        for name in candidates:
            if self.materials[name]["bsdf"] == result["bsdf"] and \
                    self.materials[name]["nodes"] == result["nodes"]:
                return name, result["emission"]
        name = base
        if candidates:
            name = self.material_id(material, obj)
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
    def image_binding(self, translator, node):
        """The graph.json image name of an Image Texture node's image (graph.md "Images"): an
        external file by its absolute path; a packed one, and one that only lives in the .blend
        (generated, or painted and unsaved), written into OUTDIR/images/ at the end (write_images);
        with its colour space. A problem's fallback is Cycles' missing-image magenta."""
        image, where = node.image, translator.node_where(node)
        missing = "using Cycles' missing-image magenta"
        if image is None:
            translator.refuse("%s has no image" % where, missing)
            return self._image_entry(None)
        if image.name in self._images:
            return self._images[image.name]["name"]
        what = "%s: image '%s'" % (where, printable(image.name))
        problems, path, colorspace = self.image_problems(image)
        for problem in problems:
            translator.refuse("%s: %s" % (what, problem), missing)
        if problems:
            return self._image_entry(None)
        return self._image_entry(image, path, colorspace)

    def image_problems(self, image):
        """What texrender cannot read of a Blender image as Cycles does (each a sentence), its
        file's absolute path (None: packed, or living only in the .blend) and its colour
        space. The Image Texture node's and the world's Environment Texture's images."""
        problems = []
        if image.source not in ("FILE", "GENERATED"):
            problems.append("source '%s' is not supported; supported: a single image (FILE, "
                            "GENERATED or packed)" % image.source)
        colorspace = image.colorspace_settings.name
        if colorspace not in IMAGE_COLORSPACES:
            problems.append("colour space '%s' is not supported; supported: %s"
                            % (colorspace, ", ".join(IMAGE_COLORSPACES)))
        if image.alpha_mode != "STRAIGHT" and colorspace != "Non-Color":
            problems.append("alpha mode '%s' is not supported; supported: STRAIGHT (texrender "
                            "associates alpha as Cycles does for straight images)" % image.alpha_mode)
        path = None
        if not problems and image.packed_file is None and image.source == "FILE" and \
                not image.is_dirty:
            path = os.path.normpath(self.bpy.path.abspath(image.filepath, library=image.library))
            if not os.path.isfile(path):
                problems.append("its file '%s' does not exist (pack it, or fix the path)"
                                % printable(path))
        return problems, path, colorspace

    def _image_entry(self, image, path=None, colorspace=None):
        key = None if image is None else image.name
        if key not in self._images:
            name = self.unique_id("image", (key,), "missing" if image is None else key)
            self._images[key] = {"name": name, "image": image, "path": path,
                                 "colorspace": colorspace}
        return self._images[key]["name"]

    def write_images(self, staging, final_dir):
        """Writes what write_images has to (packed files as packed, byte for byte; images that
        live only in the .blend through Blender's own writer, PNG for 8-bit and OpenEXR for
        float buffers, the pixels as Blender holds them; the missing image as a 1x1 magenta
        PNG) into OUTDIR/images/ and returns graph.json's "images"."""
        images = {}
        for entry in self._images.values():
            binding = {"path": self.image_file(entry, staging, final_dir)}
            if entry["colorspace"] is not None:
                binding["colorspace"] = entry["colorspace"]
            images[entry["name"]] = binding
        return images

    def image_file(self, entry, staging, final_dir):
        """The path by which OUTDIR's files name an image entry ({"image", "name", "path"}):
        an external file's absolute path; else the file written into OUTDIR/images/ (as
        write_images says) relative to OUTDIR."""
        image, name = entry["image"], entry["name"]
        if entry["path"] is not None:
            return entry["path"]
        image_dir = os.path.join(staging, "images")
        if not os.path.isdir(image_dir):
            make_dir(image_dir, os.path.join(final_dir, "images"))
        if image is None:
            ext = ".png"
        elif image.packed_file is not None:
            ext = os.path.splitext(image.filepath)[1].lower() or \
                {"OPEN_EXR": ".exr", "JPEG": ".jpg", "HDR": ".hdr"}.get(
                    image.file_format, ".png")
        else:
            ext = ".exr" if image.is_float else ".png"
        file = self.unique_file("images/" + file_name(name), ext)
        target = os.path.join(staging, file)
        if image is None:
            with atomic_open(target, "wb", os.path.join(final_dir, file)) as f:
                f.write(magenta_png())
        elif image.packed_file is not None:
            with atomic_open(target, "wb", os.path.join(final_dir, file)) as f:
                f.write(bytes(image.packed_file.data))
        else:
            image.file_format = "OPEN_EXR" if ext == ".exr" else "PNG"
            image.save(filepath=target)
        return file

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
            tv, tl = tv.reshape(-1, 3), tl.reshape(-1, 3)
            # One normal per triangle corner. A flat-shaded face's corner normals are its
            # polygon's normal, but Cycles shades each of its triangles with the triangle's own
            # normal (Ng; a non-planar quad's two triangles differ), and so does the AO node's
            # hemisphere (issue 22): flat triangles get their geometric normal.
            corner_normals = normals.reshape(-1, 3)[tl]
            smooth = np.empty(ntri, bool)
            mesh.loop_triangles.foreach_get("use_smooth", smooth)
            p = co.astype(np.float64)[tv]
            ng = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
            length = np.linalg.norm(ng, axis=1)
            flat = ~smooth & (length > 0)
            corner_normals[flat] = (ng[flat] / length[flat, None])[:, None, :]
            uv = None
            # Cycles' default UV map (Texture Coordinate's UV) is the one active for rendering.
            layer = next((l for l in mesh.uv_layers if l.active_render), mesh.uv_layers.active)
            if layer is not None:
                uv = np.empty(len(mesh.loops) * 2, np.float32)
                layer.data.foreach_get("uv", uv)
                uv = uv.reshape(-1, 2)
            # A Normal Map node needs the UV tangents as Cycles has them (blender_tangents.py):
            # written as vtan, one per vn (docs/scene.md "Tangents").
            tangents = None
            if any(uses_normal_map(s.material) for s in obj_eval.material_slots):
                if uv is None:
                    self.problems.refuse(
                        "object '%s': a Normal Map node shades it, but the mesh has no UV map; "
                        "supported: a mesh with a UV map (the Normal Map's tangents are the UV "
                        "map's)" % obj_eval.name, "using tangents of no UV map (arbitrary)")
                else:
                    tangents = mikk_tangents(co, tv, uv[tl], corner_normals)
            files = []
            for slot in sorted(set(mi.tolist())):
                pick = mi == slot
                corners = tl[pick].reshape(-1)
                # Each position, normal and UV once (smooth meshes share them between corners).
                verts, vidx = np.unique(tv[pick].reshape(-1), return_inverse=True)
                if tangents is None:
                    vn, nidx = np.unique(corner_normals[pick].reshape(-1, 3), axis=0,
                                         return_inverse=True)
                else:  # each distinct (normal, tangent, sign) its own vn and vtan
                    both = np.concatenate([corner_normals[pick], tangents[pick]], axis=2)
                    vn, nidx = np.unique(both.reshape(-1, 7), axis=0, return_inverse=True)
                columns = [vidx.reshape(-1) + 1]
                if uv is not None:
                    vt, tidx = np.unique(uv[corners], axis=0, return_inverse=True)
                    columns.append(tidx.reshape(-1) + 1)
                columns.append(nidx.reshape(-1) + 1)
                corner = np.stack(columns, axis=1).reshape(-1, 3 * len(columns)).tolist()
                face = "f " + " ".join(["/".join(["%d"] * 3) if uv is not None
                                        else "%d//%d"] * 3) + "\n"
                name = self.unique_file("%s.%d" % (file_name(obj_eval.name), slot), ".obj")
                with atomic_open(os.path.join(directory, name), "w",
                                 os.path.join(self.final_dir, "meshes", name)) as f:
                    f.write("# %s, material slot %d (blender_export.py)\n" % (obj_eval.name,
                                                                            slot))
                    f.write("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in co[verts].tolist()))
                    f.write("".join("vn %.7g %.7g %.7g\n" % tuple(n[:3]) for n in vn.tolist()))
                    if tangents is not None:
                        f.write("".join("vtan %.7g %.7g %.7g %d\n" % (t[3], t[4], t[5], t[6])
                                        for t in vn.tolist()))
                    if uv is not None:
                        f.write("".join("vt %.7g %.7g\n" % tuple(t) for t in vt.tolist()))
                    f.write("".join(face % tuple(c) for c in corner))
                files.append((name, slot))
            return files
        finally:
            obj_eval.to_mesh_clear()

    # --- Camera, lights, world ---
    def object_visibility(self, obj):
        """Cycles' per-object ray visibility, holdout and shadow catcher: texrender's objects
        are seen by every ray, never held out, and catch no shadow on their own."""
        for attr, label in (("visible_camera", "Camera"), ("visible_diffuse", "Diffuse"),
                            ("visible_glossy", "Glossy"), ("visible_shadow", "Shadow"),
                            ("visible_transmission", "Transmission"),
                            ("visible_volume_scatter", "Volume Scatter")):
            if not getattr(obj, attr, True):
                self.problems.refuse("object '%s': Visibility > Ray Visibility > %s is off; "
                                     "supported: on (texrender's objects are visible to every "
                                     "ray)" % (obj.name, label), "visible to every ray")
        for attr, label in (("is_holdout", "Holdout"), ("is_shadow_catcher", "Shadow Catcher")):
            if getattr(obj, attr, False):
                self.problems.refuse("object '%s': Visibility > %s is on; supported: off"
                                     % (obj.name, label), "rendering it as an object")

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
        if data.dof.use_dof:
            self.problems.refuse("%s: Depth of Field is on; supported: off (texrender's camera "
                                 "is a pinhole)" % where, "rendering everything in focus")
        if not finite([pos, forward, up, fov]):
            raise ExportError("%s: its transform or lens has a NaN or infinite value" % where)
        norm = math.sqrt(sum(v * v for v in forward))
        return ({"position": pos, "target": [pos[k] + forward[k] / norm for k in range(3)],
                 "up": up, "fov": fov, "fovAxis": axis}, {"width": width, "height": height})

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
        self.final_dir = final_dir
        self.scene = scene
        view = check_render_settings(scene, self.problems.refuse)
        self.use_render_settings(scene)
        view_layer = next((v for v in scene.view_layers if v.use), scene.view_layers[0])
        # A scene other than the context's has no depsgraph until one is asked for in its context.
        with self.bpy.context.temp_override(scene=scene, view_layer=view_layer):
            if self.options.frame is not None:
                scene.frame_set(self.options.frame)
            depsgraph = self.bpy.context.evaluated_depsgraph_get()
        camera, film = self.camera(scene, depsgraph)
        if view:
            film["view"] = view
        lights, meshes, written = [], [], {}
        sky = self.world(scene, staging)
        if sky:
            lights.append(sky)
        mesh_dir = os.path.join(staging, "meshes")
        make_dir(mesh_dir, os.path.join(final_dir, "meshes"))
        geometry = {"MESH", "CURVE", "SURFACE", "FONT", "META"}
        for inst in depsgraph.object_instances:
            obj = inst.object
            if obj.type == "LIGHT":
                if obj.data.type == "SUN":
                    sun = self.sun(obj)
                    if sun is not None:
                        lights.append(sun)
                elif obj.data.type in ("POINT", "SPOT", "AREA"):
                    lamp = self.lamp(obj, inst.matrix_world)
                    if lamp is not None:
                        lights.append(lamp)
                else:
                    self.problems.refuse("light '%s': type '%s' is not supported; supported: "
                                         "SUN, POINT, SPOT, AREA" % (obj.name, obj.data.type),
                                         "leaving it out")
                continue
            if obj.type not in geometry:
                continue
            if not self.check_finite("object '%s'" % obj.name, "its transform",
                                     rows(inst.matrix_world), "leaving it out"):
                continue
            key = obj.original.name
            if key not in written:
                self.object_visibility(obj.original)
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
        if self.problems.errors:
            raise ProblemsFound()
        self.write_json(os.path.join(staging, "scene.json"), scene_json,
                        os.path.join(final_dir, "scene.json"))
        graph = self.graph_json(final_dir)
        if self._images:
            graph["images"] = self.write_images(staging, final_dir)
        self.write_json(os.path.join(staging, "graph.json"), graph,
                        os.path.join(final_dir, "graph.json"))

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
    def write_json(path, value, label):
        import json
        try:
            text = json.dumps(short_floats(value), indent=1, allow_nan=False)
        except ValueError:  # a value no check above caught: never write invalid JSON
            raise ExportError("%s: a value is NaN or infinite; nothing written" % label)
        with atomic_open(path, "w", label) as f:
            # Arrays of numbers on one line each.
            text = re.sub(r"\[\s+([-+0-9.eE,\s]+?)\s+\]", lambda m: "[%s]" % ", ".join(
                x.strip() for x in m.group(1).split(",")), text)
            f.write(text + "\n")


def _numbers(value):
    if isinstance(value, (int, float)):
        return float(value)
    return [float(v) for v in value]


def magenta_png():
    """A 1x1 opaque magenta PNG (Cycles' colour for a missing image)."""
    import struct
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + \
            struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0)) + \
        chunk(b"IDAT", zlib.compress(b"\x00\xff\x00\xff")) + chunk(b"IEND", b"")


def printable(text):
    """A Blender name as the log shows it: control characters escaped (\\x01)."""
    return "".join(c if c.isprintable() else "\\x%02x" % ord(c) if ord(c) < 256
                   else "\\u%04x" % ord(c) for c in text)


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
    staging = export = None
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
        try:
            staging = tempfile.mkdtemp(prefix=".%s.tmp-" % os.path.basename(final_dir),
                                       dir=parent)
            # mkdtemp's 0700 would become OUTDIR's mode: a folder's mode from the umask.
            os.chmod(staging, new_dir_mode())
        except OSError as e:
            raise ExportError("%s: cannot write: %s" % (final_dir, e.strerror))
        export = Export(bpy, options)
        export.run(scene, staging, final_dir)
        replace_dir(staging, final_dir)
        staging = None
        for label, ident in export.renamed:
            print("blender_export: %s is '%s' in graph.json" % (label, ident))
        print("blender_export: %s: %d meshes, %d materials, %d graph nodes -> %s" % (
            options.blend or bpy.data.filepath, len(os.listdir(os.path.join(final_dir, "meshes"))),
            len(export.materials), len(export.graph_nodes), options.outdir))
    except (ExportError, AtomicWriteError) as e:
        for problem in export.problems.errors if export else []:
            sys.stderr.write("blender_export: error: %s\n" % problem)
        if not isinstance(e, ProblemsFound):
            sys.stderr.write("blender_export: error: %s\n" % e)
        sys.exit(1)
    except OSError as e:  # moving the finished export into place
        sys.stderr.write("blender_export: error: %s: %s\n" % (e.filename or final_dir,
                                                             e.strerror or e))
        sys.exit(1)
    finally:
        if staging and os.path.isdir(staging):
            shutil.rmtree(staging)

