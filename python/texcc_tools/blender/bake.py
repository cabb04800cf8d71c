"""Baking for scripts/blender_conformance.py (texcc_tools.blender.conformance): the plane the
fixture points lie on, the Cycles scene that bakes a node variant's outputs over it, and the
fixture images and encodings."""
import base64
import os

from texcc_tools.blender.nodes import NODES

# The plane the points lie on: P(u, v) = ORIGIN + u * AXIS_U + v * AXIS_V, (u, v) in [0, 1]^2.
# Tilted, so that x, y and z all vary; it spans about four lattice cells per axis at scale 1.
ORIGIN = (-1.3, -0.7, 0.2)
AXIS_U = (4.0, 0.0, 1.0)
AXIS_V = (0.0, 4.0, -1.5)


# --- Baking ---------------------------------------------------------------------------------

def setup_scene(size):
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.render.bake.margin = 0
    mesh = bpy.data.meshes.new("plane")
    o, a, b = ORIGIN, AXIS_U, AXIS_V
    corners = [o, tuple(o[i] + a[i] for i in range(3)),
               tuple(o[i] + a[i] + b[i] for i in range(3)), tuple(o[i] + b[i] for i in range(3))]
    mesh.from_pydata(corners, [], [(0, 1, 2, 3)])
    uv = mesh.uv_layers.new(name="UV")
    for loop, coord in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        uv.data[loop].uv = coord
    obj = bpy.data.objects.new("plane", mesh)
    scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    material = bpy.data.materials.new("probe")
    material.use_nodes = True
    mesh.materials.append(material)
    image = bpy.data.images.new("bake", size, size, float_buffer=True, alpha=True)
    image.colorspace_settings.name = "Non-Color"
    return material, image


def bake(material, image, build):
    """Bakes Emission(color = build(tree, position_socket)) and returns the RGB per texel."""
    import bpy
    import numpy as np
    tree = material.node_tree
    tree.nodes.clear()
    geometry = tree.nodes.new("ShaderNodeNewGeometry")
    emission = tree.nodes.new("ShaderNodeEmission")
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(build(tree, geometry.outputs["Position"]), emission.inputs["Color"])
    tree.links.new(emission.outputs["Emission"], output.inputs["Surface"])
    target = tree.nodes.new("ShaderNodeTexImage")
    target.image = image
    tree.nodes.active = target
    bpy.ops.object.bake(type="EMIT")
    pixels = np.empty(len(image.pixels), np.float32)
    image.pixels.foreach_get(pixels)
    return pixels.reshape(-1, 4)[:, :3].copy()


def socket_named(sockets, key):
    """A socket by identifier (unique: "Value_001"), else by its displayed name."""
    for s in sockets:
        if s.identifier == key:
            return s
    for s in sockets:
        if s.name == key and s.enabled:
            return s
    raise KeyError(key)


def build_variant(v, socket):
    def build(tree, position):
        node = tree.nodes.new(v["node"])
        # Inputs first: a property may hide sockets (Noise's Offset under fBM).
        for key, value in v["inputs"].items():
            socket_named(node.inputs, key).default_value = value
        for key, value in v["props"].items():
            setattr(node, key, value)
        if "setup" in v:
            v["setup"](node)
        for param in v["exporter_args"]:
            v["args"][param] = NODES[v["node"]]["props"][param](node)
        if "image" in v:
            node.image = make_image(v["image"])
        separate = None
        for key, feed in v["feeds"].items():
            if key == "alpha":  # the Alpha output linked (Emission Strength = Alpha > -1)
                above = tree.nodes.new("ShaderNodeMath")
                above.operation = "GREATER_THAN"
                tree.links.new(node.outputs["Alpha"], above.inputs[0])
                above.inputs[1].default_value = -1.0
                emission = next(n for n in tree.nodes if n.bl_idname == "ShaderNodeEmission")
                tree.links.new(above.outputs[0], emission.inputs["Strength"])
                continue
            if feed == "P":
                tree.links.new(position, socket_named(node.inputs, key))
                continue
            if feed.startswith("P*"):
                # "P*S+O": the position through Vector Math Multiply Add (texcc: blVectorMath).
                scale, offset = (float(t) for t in feed[2:].split("+"))
                affine = tree.nodes.new("ShaderNodeVectorMath")
                affine.operation = "MULTIPLY_ADD"
                tree.links.new(position, affine.inputs[0])
                affine.inputs[1].default_value = (scale, scale, scale)
                affine.inputs[2].default_value = (offset, offset, offset)
                tree.links.new(affine.outputs[0], socket_named(node.inputs, key))
                continue
            if separate is None:
                separate = tree.nodes.new("ShaderNodeSeparateXYZ")
                tree.links.new(position, separate.inputs[0])
            source = separate.outputs[feed[2].upper()]
            if "*" in feed:
                # "P.x*S+O": one coordinate through Math Multiply Add (texcc: blMath, op 36).
                scale, offset = (float(t) for t in feed[4:].split("+"))
                affine = tree.nodes.new("ShaderNodeMath")
                affine.operation = "MULTIPLY_ADD"
                tree.links.new(source, affine.inputs[0])
                affine.inputs[1].default_value = scale
                affine.inputs[2].default_value = offset
                source = affine.outputs[0]
            tree.links.new(source, socket_named(node.inputs, key))
        return socket_named(node.outputs, socket)
    return build


def write_png16(path, w, h, pixels):
    """A 16-bit RGBA PNG of pixels (0..1, Blender's order: the bottom row first)."""
    import struct
    import zlib
    raw = b""
    for row in range(h - 1, -1, -1):
        raw += b"\x00" + b"".join(struct.pack(">H", round(v * 65535))
                                  for v in pixels[row * w * 4:(row + 1) * w * 4])

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + \
            struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 16, 6, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def make_image(spec):
    """The variant's image in Blender (once per variant): pixels as spec["pixels"] (Blender's
    order, the bottom row first); spec["stored"] becomes what Blender holds (bytes: k / 255)."""
    import bpy
    name = "image-" + spec["kind"]
    image = bpy.data.images.get(name)
    if image is None and spec.get("bits") == 16:
        import tempfile
        path = os.path.join(tempfile.mkdtemp(), name + ".png")
        write_png16(path, spec["width"], spec["height"], spec["pixels"])
        image = bpy.data.images.load(path)
        image.colorspace_settings.name = spec["colorspace"]
        spec["stored"] = spec["pixels"]  # the file's values (texrender reads the file)
        return image
    if spec.get("bits") == 16:
        return image
    if image is None:
        image = bpy.data.images.new(name, spec["width"], spec["height"], alpha=True,
                                    float_buffer=spec["float"])
        image.colorspace_settings.name = spec["colorspace"]
        image.alpha_mode = "STRAIGHT"
        image.pixels.foreach_set(spec["pixels"])
        image.update()
    stored = [0.0] * len(image.pixels)
    image.pixels.foreach_get(stored)
    spec["stored"] = stored
    return image


def encode(values):
    import numpy as np
    return base64.b64encode(np.ascontiguousarray(values, dtype="<f4").tobytes()).decode("ascii")
