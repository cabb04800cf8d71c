"""make_world_blend.py: .blend files lit only by an HDR world (an Environment Texture), for
testsuite/blender-export/export-world*.test and bench/cycles.py --env (bpy; .venv).

    make_world_blend.py OUT.blend CASE
    make_world_blend.py --all OUTDIR            OUTDIR/CASE.blend for every case of CASES
    make_world_blend.py --reference [--spp N] [--cases A,B]

The scene (Blender's Z up): a grey diffuse floor (8 m square), a green-grey diffuse cube (1 m)
and a glossy sphere (GGX, roughness 0.25, radius 0.6, smooth), a camera at (0, -6, 1.6) looking
at (0, 0, 0.8) with the sky above the horizon in view, 64x48, Cycles with the settings texrender
reproduces (make_blend.py's reproducible(): Max Bounces 6, no light tree, no clamping, box
filter). The world's Background takes its Color from an Environment Texture of a float image
this script makes, 128x64 (hdr_map): a sky gradient (bright blue above, white at the horizon,
a brown ground below) and a small sun, 2x2 texels of radiance 600 at 35 degrees elevation,
written as an OpenEXR. CASES:
"env" (the image an external EXR file, the Vector unlinked, Strength 1), "env-rotated" (the
image packed, Strength 0.8, the Vector from a Texture Coordinate's Generated through a Mapping
node (Point) rotated (12, 0, 75) degrees: the sun moves into another part of the sky);
"refused" (for the error test: a Mirror Ball projection, Cubic interpolation, a Mapping node with
a Location, an image whose file does not exist, a linked Strength).

--reference renders each case with Cycles (CPU, N spp, default 4096; cycles_render.py) and
writes the 16x16-pixel block means into cycles-world-CASE.json (region_means.py --write).
"""
import math
import os


CASES = ("env", "env-rotated")
MAP_W, MAP_H = 128, 64


def hdr_map():
    """The sky (MAP_H x MAP_W x 3, row 0 the top, as an image file stores it): a gradient in
    elevation with a little variation along the azimuth, and the sun."""
    import numpy as np
    y, x = np.meshgrid((np.arange(MAP_H) + 0.5) / MAP_H, (np.arange(MAP_W) + 0.5) / MAP_W,
                       indexing="ij")
    elevation = (0.5 - y) * math.pi  # +pi/2 at the top row
    up = np.clip(np.sin(elevation), 0.0, 1.0)[..., None]
    sky = (1 - up) * np.array([1.2, 1.15, 1.1]) + up * np.array([0.25, 0.45, 0.9])
    sky = sky * (1.0 + 0.25 * np.cos(2 * math.pi * x))[..., None]
    ground = np.array([0.25, 0.18, 0.1]) * (1.0 + 0.5 * np.sin(2 * math.pi * x))[..., None]
    img = np.where(elevation[..., None] > 0, sky, ground)
    row = int(round((0.5 - math.radians(35.0) / math.pi) * MAP_H))  # 35 degrees up
    col = int(0.62 * MAP_W)
    img[row - 1:row + 1, col - 1:col + 1] = [600.0, 560.0, 500.0]
    return img.astype(np.float32)


def map_image(bpy, folder, name, pack):
    """The map as a Blender float image saved to FOLDER/NAME.exr (and packed when asked)."""
    import numpy as np
    img = bpy.data.images.new(name, MAP_W, MAP_H, alpha=True, float_buffer=True)
    rgba = np.concatenate([hdr_map(), np.ones((MAP_H, MAP_W, 1), np.float32)], axis=-1)
    img.pixels.foreach_set(rgba[::-1].ravel())  # Blender's row 0 is the bottom
    img.filepath_raw = os.path.join(folder, name + ".exr")
    img.file_format = "OPEN_EXR"
    img.save()
    if pack:
        img.pack()
    img.colorspace_settings.name = "Linear Rec.709"  # saving it made it sRGB
    return img


def sphere_mesh(radius, center, uvs=False):
    """A smooth UV sphere (48 x 24 segments); with `uvs`, its UV map "UVMap"."""
    import bmesh
    import bpy
    mesh = bpy.data.meshes.new("sphere")
    bm = bmesh.new()
    if uvs:
        bm.loops.layers.uv.new("UVMap")
    bmesh.ops.create_uvsphere(bm, u_segments=48, v_segments=24, radius=radius, calc_uvs=uvs)
    bmesh.ops.translate(bm, verts=bm.verts, vec=center)
    bm.to_mesh(mesh)
    bm.free()
    for poly in mesh.polygons:
        poly.use_smooth = True
    return mesh


def make(out, case):
    import bpy
    from texcc_tools.testing.make_blend import add_mesh, cube_mesh, new_scene, quad, simple
    from texcc_tools.testing.make_lamp_blend import aim
    folder = os.path.dirname(os.path.abspath(out))
    scene = new_scene(64, 48, 64)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.data.lens = 35.0
    cam.location = (0.0, -6.0, 1.6)
    aim(cam, (0.0, 0.0, 0.8))
    scene.collection.objects.link(cam)
    scene.camera = cam
    floor = simple("Floor", "ShaderNodeBsdfDiffuse", (0.5, 0.5, 0.5, 1))
    box = simple("Box", "ShaderNodeBsdfDiffuse", (0.4, 0.55, 0.35, 1))
    metal = simple("Metal", "ShaderNodeBsdfGlossy", (0.9, 0.75, 0.5, 1))
    metal.node_tree.nodes["Glossy BSDF"].inputs["Roughness"].default_value = 0.25
    add_mesh("Floor", quad("floor", 8.0, 0.0), floor)
    add_mesh("Cube", cube_mesh(), box).location = (-0.9, 0.3, 0.0)
    add_mesh("Ball", sphere_mesh(0.6, (0.9, -0.2, 0.6)), metal)
    t = scene.world.node_tree
    background = t.nodes["Background"]
    env = t.nodes.new("ShaderNodeTexEnvironment")
    env.name = "Sky"
    t.links.new(env.outputs["Color"], background.inputs["Color"])
    if case == "env":
        env.image = map_image(bpy, folder, "sky", pack=False)
    elif case == "env-rotated":
        env.image = map_image(bpy, folder, "sky-packed", pack=True)
        background.inputs["Strength"].default_value = 0.8
        coords = t.nodes.new("ShaderNodeTexCoord")
        mapping = t.nodes.new("ShaderNodeMapping")
        mapping.vector_type = "POINT"
        mapping.inputs["Rotation"].default_value = (math.radians(12.0), 0.0, math.radians(75.0))
        t.links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
        t.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    elif case == "refused":
        gone = bpy.data.images.new("Gone", 2, 2)
        gone.source, gone.filepath = "FILE", os.path.join(folder, "does-not-exist.exr")
        env.image = gone
        env.projection = "MIRROR_BALL"
        env.interpolation = "Cubic"
        coords = t.nodes.new("ShaderNodeTexCoord")
        mapping = t.nodes.new("ShaderNodeMapping")
        mapping.name = "Turn"
        mapping.inputs["Location"].default_value = (1.0, 0.0, 0.0)
        t.links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
        t.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
        value = t.nodes.new("ShaderNodeValue")
        t.links.new(value.outputs["Value"], background.inputs["Strength"])
        background.inputs["Color"].default_value = (0.2, 0.25, 0.3, 1.0)
    else:
        raise SystemExit("make_world_blend.py: unknown case '%s' (cases: %s, refused)"
                         % (case, ", ".join(CASES)))
    bpy.ops.wm.save_as_mainfile(filepath=out)
