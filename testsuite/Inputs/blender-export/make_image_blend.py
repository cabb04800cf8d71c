"""make_image_blend.py: a .blend with three Image Texture materials, for the exporter's images.

    .venv/bin/python make_image_blend.py OUT.blend [refused]  # the .blend, and OUT.blend's folder
                                                            # gets nonColor.png (external)
    .venv/bin/python make_image_blend.py --reference [SPP]   # Cycles' block means ->
                                                            # cycles-image-texture.json

Three planes seen from above (64x48 pixels, emission only, no lights), each an Emission of an
Image Texture's Color (seeded random pixels, so the file is the same every time):
- "Packed": an 8-bit sRGB PNG, packed into the .blend; UV through Mapping (scale 2.5, moved),
  Linear, Repeat;
- "External": an 8-bit Non-Color PNG beside the .blend (an absolute path); Texture Coordinate
  Object, Closest, Clip (the plane reaches past the image: black there);
- "Float": a float image packed as OpenEXR, Linear Rec.709, values up to 2; the unlinked Vector
  (the UV map), Cubic, Extend (Extend shows in the half texel along the edges).
"""
import os
import random
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "cycles-image-texture.json")


def pixels(seed, w, h, high=1.0, quantize=True):
    rng = random.Random(seed)
    out = []
    for _ in range(w * h):
        if quantize:
            out += [rng.randrange(256) / 255.0 for _ in range(3)] + [1.0]
        else:
            out += [round(rng.uniform(0.0, high), 4) for _ in range(3)] + [1.0]
    return out


def image_material(bpy, name, image, interpolation, extension, coords, scale=None):
    material = bpy.data.materials.new(name)
    tree = material.node_tree
    tree.nodes.clear()
    tex = tree.nodes.new("ShaderNodeTexImage")
    tex.name = "Image"
    tex.image, tex.interpolation, tex.extension = image, interpolation, extension
    emission = tree.nodes.new("ShaderNodeEmission")
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(tex.outputs["Color"], emission.inputs["Color"])
    tree.links.new(emission.outputs["Emission"], out.inputs["Surface"])
    if coords is not None:
        texco = tree.nodes.new("ShaderNodeTexCoord")
        source = texco.outputs[coords]
        if scale is not None:
            mapping = tree.nodes.new("ShaderNodeMapping")
            mapping.inputs["Scale"].default_value = scale
            mapping.inputs["Location"].default_value = (0.13, -0.21, 0.0)
            tree.links.new(source, mapping.inputs["Vector"])
            source = mapping.outputs["Vector"]
        tree.links.new(source, tex.inputs["Vector"])
    return material


def plane(bpy, scene, name, x0, x1, y0, y1, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(x0, y0, 0), (x1, y0, 0), (x1, y1, 0), (x0, y1, 0)], [], [(0, 1, 2, 3)])
    uv = mesh.uv_layers.new(name="UV")
    for loop, coord in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        uv.data[loop].uv = coord
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)


def make(out, refused=False):
    import bpy
    from texcc_tools.testing.make_blend import new_scene
    scene = new_scene(64, 48, 16, max_bounces=2, color=(0.0, 0.0, 0.0, 1.0))
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.data.lens = 35.0
    cam.location = (0.0, 0.0, 4.0)
    scene.collection.objects.link(cam)
    scene.camera = cam

    folder = os.path.dirname(os.path.abspath(out))
    packed = bpy.data.images.new("Packed", 6, 5, alpha=True)
    packed.pixels.foreach_set(pixels("packed", 6, 5))
    packed.filepath_raw = os.path.join(folder, "packed-source.png")
    packed.file_format = "PNG"
    packed.save()
    packed.pack()

    external = bpy.data.images.new("External", 5, 4, alpha=True)
    external.colorspace_settings.name = "Non-Color"  # first: it regenerates the pixels
    external.pixels.foreach_set(pixels("external", 5, 4))
    external.filepath_raw = os.path.join(folder, "nonColor.png")
    external.file_format = "PNG"
    external.save()

    floats = bpy.data.images.new("Float", 4, 4, alpha=True, float_buffer=True)
    floats.colorspace_settings.name = "Linear Rec.709"
    floats.pixels.foreach_set(pixels("float", 4, 4, 2.0, quantize=False))
    floats.filepath_raw = os.path.join(folder, "float-source.exr")
    floats.file_format = "OPEN_EXR"
    floats.save()
    floats.pack()
    floats.colorspace_settings.name = "Linear Rec.709"  # saving it made it sRGB

    # The view at z = 0 is 4.114 x 3.086 (35 mm lens, 36 mm sensor, 4 above): the planes fill it,
    # their edges on the 8x8-pixel blocks' (0.514 apart), so that every block is one material's.
    block = 4.0 * 36.0 / 35.0 / 8.0
    x, y = [block * (k - 4) for k in range(9)], (-3 * block, 3 * block)
    plane(bpy, scene, "PackedPlane", x[0], x[3], *y,
          image_material(bpy, "Packed", packed, "Linear", "REPEAT", "UV", (2.5, 2.5, 1.0)))
    plane(bpy, scene, "ExternalPlane", x[3], x[5], *y,
          image_material(bpy, "External", external, "Closest", "CLIP", "Object"))
    plane(bpy, scene, "FloatPlane", x[5], x[8], *y,
          image_material(bpy, "Float", floats, "Cubic", "EXTEND", None))
    if refused:
        # What the exporter refuses, one problem each (all reported at once): no image, a
        # missing file, an unsupported colour space, a channel-packed alpha, Box projection.
        gone = bpy.data.images.new("Gone", 2, 2)
        gone.source, gone.filepath = "FILE", os.path.join(folder, "does-not-exist.png")
        aces = bpy.data.images.new("Aces", 2, 2)
        aces.colorspace_settings.name = "ACEScg"
        packed_alpha = bpy.data.images.new("ChannelPacked", 2, 2)
        packed_alpha.alpha_mode = "CHANNEL_PACKED"
        material = bpy.data.materials["Packed"]
        tree = material.node_tree
        last = tree.nodes["Emission"].inputs["Color"]
        for name, image, interpolation, projection in (
                ("NoImage", None, "Linear", "FLAT"), ("GoneImage", gone, "Linear", "FLAT"),
                ("AcesImage", aces, "Linear", "FLAT"), ("Channels", packed_alpha, "Linear", "FLAT"),
                ("Box", packed, "Linear", "BOX")):
            tex = tree.nodes.new("ShaderNodeTexImage")
            tex.name, tex.image, tex.interpolation, tex.projection = \
                name, image, interpolation, projection
            mix = tree.nodes.new("ShaderNodeMix")
            mix.data_type = "RGBA"
            tree.links.new(tex.outputs["Color"], mix.inputs["A"])
            tree.links.new(mix.outputs["Result"], last)
            last = mix.inputs["B"]
        tree.links.new(tree.nodes["Image"].outputs["Color"], last)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(out))


def reference(spp):
    """Cycles' block means (8x8 pixels; the planes' edges marked) into REFERENCE."""
    from texcc_tools.testing.cycles_render import write_reference
    blend = os.path.join(tempfile.mkdtemp(), "image.blend")
    write_reference(__file__, blend, [], spp, REFERENCE, (8, 6), 0.01, edges=True)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--reference"]:
        reference(int(sys.argv[2]) if len(sys.argv) > 2 else 1024)
    elif sys.argv[1:2] == ["--render"]:
        from texcc_tools.testing.cycles_render import render_file
        render_file(sys.argv[2], int(sys.argv[3]), transparent=True)
    else:
        make(sys.argv[1], sys.argv[2:3] == ["refused"])
