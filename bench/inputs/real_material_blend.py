"""real_material_blend.py: the "real material" scene of issue 37 for bench/real_material.py
(bpy; .venv): a PBR-textured object under an HDR world and an area lamp.

    real_material_blend.py OUT.blend [CASE]

The scene (Blender's Z up), built on make_world_blend.py's: a grey diffuse floor, a smooth UV
sphere (make_world_blend.py's, radius 0.8, UV-mapped) with a Principled BSDF whose Base Color,
Roughness and Normal come from three images this script makes beside OUT.blend -- albedo.png
(8-bit, sRGB: a tile pattern of four colours with dark grout), roughness.png (8-bit, Non-Color:
0.25 on the tiles, 0.8 in the grout) and normal.png (8-bit, Non-Color: a tangent-space normal
map of a dome on each tile, flat grout, through a Normal Map node of Strength 1) -- the world
an Environment Texture of make_world_blend.py's sky (an EXR with a small sun) and an area lamp
(1 m square, 60 W, warm). Cycles with the settings texrender reproduces (make_blend.py's
reproducible()). CASES: "real" (as above), "real-metal" (Metallic 1, the albedo as the metal's
colour).
"""
import math
import os
import sys


CASES = ("real", "real-metal")
TEX = 256  # texels per side of each image
TILES = 8  # tiles per side


def patterns():
    """albedo (sRGB-encoded, 0..1), roughness (linear), normal (encoded 0..1) images, TEX x TEX,
    row 0 the top."""
    import numpy as np
    v, u = np.meshgrid((np.arange(TEX) + 0.5) / TEX, (np.arange(TEX) + 0.5) / TEX,
                       indexing="ij")
    fu, fv = (u * TILES) % 1.0, (v * TILES) % 1.0
    iu, iv = (u * TILES).astype(int), (v * TILES).astype(int)
    grout = (np.minimum(np.minimum(fu, 1 - fu), np.minimum(fv, 1 - fv)) < 0.06)
    colours = np.array([[0.80, 0.35, 0.20], [0.25, 0.45, 0.70], [0.85, 0.80, 0.55],
                        [0.30, 0.60, 0.30]])
    albedo = colours[(iu + 2 * iv) % 4]
    albedo[grout] = [0.08, 0.08, 0.08]
    rough = np.where(grout, 0.8, 0.25)
    # Height: a dome per tile, zero in the grout; the normal from its slopes (u right, v up:
    # image rows run down, so the v slope flips).
    du, dv = fu - 0.5, fv - 0.5
    height = np.where(grout, 0.0, np.maximum(0.0, 0.16 - du * du - dv * dv))
    gu = np.gradient(height, axis=1) * TEX * 0.05
    gv = -np.gradient(height, axis=0) * TEX * 0.05
    n = np.stack([-gu, -gv, np.ones_like(gu)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return albedo, rough, n * 0.5 + 0.5


def save_png(bpy, folder, name, rgb, colorspace):
    """An 8-bit image saved as FOLDER/NAME.png, the values as given (a byte image's pixels are
    its stored values, whatever its colour space)."""
    import numpy as np
    img = bpy.data.images.new(name, TEX, TEX, alpha=False)
    img.colorspace_settings.name = colorspace
    rgb3 = np.broadcast_to(rgb[..., None] if rgb.ndim == 2 else rgb, (TEX, TEX, 3))
    rgba = np.concatenate([rgb3, np.ones((TEX, TEX, 1))], axis=-1).astype(np.float32)
    img.pixels.foreach_set(rgba[::-1].ravel())  # Blender's row 0 is the bottom
    img.filepath_raw = os.path.join(folder, name + ".png")
    img.file_format = "PNG"
    img.save()
    return img


def pbr_material(bpy, folder, metallic):
    albedo, rough, normal = patterns()
    m = bpy.data.materials.new("Tiles")
    m.use_nodes = True
    t = m.node_tree
    bsdf = t.nodes["Principled BSDF"]
    bsdf.inputs["Metallic"].default_value = metallic

    def image_node(name, img):
        n = t.nodes.new("ShaderNodeTexImage")
        n.name, n.image = name, img
        return n
    a = image_node("Albedo", save_png(bpy, folder, "albedo", albedo, "sRGB"))
    r = image_node("Roughness", save_png(bpy, folder, "roughness", rough, "Non-Color"))
    n = image_node("NormalImage", save_png(bpy, folder, "normal", normal, "Non-Color"))
    nmap = t.nodes.new("ShaderNodeNormalMap")
    nmap.name = "NormalMap"
    nmap.uv_map = "UVMap"
    t.links.new(a.outputs["Color"], bsdf.inputs["Base Color"])
    t.links.new(r.outputs["Color"], bsdf.inputs["Roughness"])
    t.links.new(n.outputs["Color"], nmap.inputs["Color"])
    t.links.new(nmap.outputs["Normal"], bsdf.inputs["Normal"])
    return m


def make(out, case):
    import bpy
    from texcc_tools.testing.make_blend import add_mesh, new_scene, quad, simple
    from texcc_tools.testing.make_lamp_blend import aim, lamp
    from texcc_tools.testing.make_world_blend import map_image, sphere_mesh
    if case not in CASES:
        raise SystemExit("real_material_blend.py: unknown case '%s' (cases: %s)"
                         % (case, ", ".join(CASES)))
    folder = os.path.dirname(os.path.abspath(out))
    scene = new_scene(64, 48, 64)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.data.lens = 50.0
    cam.location = (0.0, -5.0, 1.5)
    aim(cam, (0.0, 0.0, 0.7))
    scene.collection.objects.link(cam)
    scene.camera = cam
    add_mesh("Floor", quad("floor", 8.0, 0.0), simple("Floor", "ShaderNodeBsdfDiffuse",
                                                       (0.5, 0.5, 0.5, 1)))
    ball = add_mesh("Ball", sphere_mesh(0.8, (0.0, 0.0, 0.8), uvs=True),
                    pbr_material(bpy, folder, 1.0 if case == "real-metal" else 0.0))
    ball.rotation_euler = (0.0, 0.0, math.radians(30.0))
    t = scene.world.node_tree
    env = t.nodes.new("ShaderNodeTexEnvironment")
    env.name = "Sky"
    env.image = map_image(bpy, folder, "sky", pack=False)
    t.links.new(env.outputs["Color"], t.nodes["Background"].inputs["Color"])
    lamp(scene, "Key", "AREA", (-2.5, -2.0, 3.0), (0.0, 0.0, 0.8), 60.0, (1.0, 0.9, 0.8),
         size=1.0, shape="SQUARE")
    bpy.ops.wm.save_as_mainfile(filepath=out)


if __name__ == "__main__":
    make(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "real")
