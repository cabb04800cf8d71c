"""make_normal_map_blend.py: a .blend of tangent-space Normal Map nodes, for the exporter's
tangents (blender-export/export-normal-map.test).

    .venv/bin/python make_normal_map_blend.py OUT.blend [refused]
    .venv/bin/python make_normal_map_blend.py --reference [SPP]   # Cycles' block means ->
                                                                 # cycles-normal-map.json

A normal map made by this script (24x16 texels of sloped bumps, Non-Color, packed 8-bit PNG)
feeds Normal Map nodes (Tangent Space, the UV map) on eight objects seen from -y (128x64
pixels; 8x8-pixel blocks of 0.5 x 0.5 at the objects' plane). Seven show the node's Normal as
colour (0.5 N + 0.5 through an Emission, no lights): the top row four smooth UV spheres (32
segments, 16 rings) at Strength 0, 0.5, 1 and 2 (the last scaled (1, 0.6, 0.8) and turned); the bottom row planes at Strength 1 with UVs
turned by 90 degrees and scaled, the object turned by 30 degrees about its normal and scaled
by (0.7, 0.5, 0.55) (not uniformly: Cycles forms the frame in the object's space); with the UVs
mirrored (bitangent sign -1); and seen from behind (Cycles turns the normal on a back face).
The eighth, bottom right, is a UV sphere whose Diffuse BSDF takes the Normal Map's Normal
through a Bump node's Normal (Strength 0.7), lit by a sun. `refused` adds what the exporter
refuses: Object Space, another UV map, a mesh without UVs.
"""
import math
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "cycles-normal-map.json")


def normal_map_pixels(w, h):
    """Unit normals of the height sin(2 pi (x + 0.3 y)) sin(2 pi y) / 6 (x, y in texels / size),
    as 8-bit colours 0.5 n + 0.5, rows bottom first (Blender's order)."""
    out = []
    for j in range(h):
        for i in range(w):
            x, y = (i + 0.5) / w, (j + 0.5) / h
            a, b = 2 * math.pi * (x + 0.3 * y), 2 * math.pi * y
            dx = 2 * math.pi * math.cos(a) * math.sin(b) / 6.0
            dy = (0.3 * 2 * math.pi * math.cos(a) * math.sin(b) +
                  2 * math.pi * math.sin(a) * math.cos(b)) / 6.0
            n = (-dx, -dy, 1.0)
            length = math.sqrt(sum(c * c for c in n))
            out += [round((0.5 * c / length + 0.5) * 255) / 255.0 for c in n] + [1.0]
    return out


def material(bpy, name, image, strength, lit=False, space="TANGENT", uv_map=""):
    mat = bpy.data.materials.new(name)
    tree = mat.node_tree
    tree.nodes.clear()
    tex = tree.nodes.new("ShaderNodeTexImage")
    tex.name, tex.image, tex.interpolation = "Image", image, "Linear"
    nmap = tree.nodes.new("ShaderNodeNormalMap")
    nmap.name, nmap.space, nmap.uv_map = "Normal Map", space, uv_map
    nmap.inputs["Strength"].default_value = strength
    tree.links.new(tex.outputs["Color"], nmap.inputs["Color"])
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    if lit:
        bump = tree.nodes.new("ShaderNodeBump")
        bump.inputs["Strength"].default_value = 0.0  # the Normal Map's normal, passed on
        diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (0.8, 0.8, 0.8, 1.0)
        tree.links.new(nmap.outputs["Normal"], bump.inputs["Normal"])
        tree.links.new(bump.outputs["Normal"], diffuse.inputs["Normal"])
        tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        return mat
    encode = tree.nodes.new("ShaderNodeVectorMath")
    encode.operation = "MULTIPLY_ADD"
    encode.inputs[1].default_value = (0.5, 0.5, 0.5)
    encode.inputs[2].default_value = (0.5, 0.5, 0.5)
    emission = tree.nodes.new("ShaderNodeEmission")
    tree.links.new(nmap.outputs["Normal"], encode.inputs[0])
    tree.links.new(encode.outputs["Vector"], emission.inputs["Color"])
    tree.links.new(emission.outputs["Emission"], out.inputs["Surface"])
    return mat


def link(bpy, scene, name, mesh, mat, location, rotation=(0.0, 0.0, 0.0)):
    if mat is not None:
        mesh.materials.append(mat)
    obj = bpy.data.objects.new(name, mesh)
    obj.location, obj.rotation_euler = location, rotation
    scene.collection.objects.link(obj)
    return obj


def uv_sphere(bpy, name):
    import bmesh
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    bm.loops.layers.uv.new("UVMap")
    bmesh.ops.create_uvsphere(bm, u_segments=32, v_segments=16, radius=0.85, calc_uvs=True)
    bm.to_mesh(mesh)
    bm.free()
    mesh.shade_smooth()
    return mesh


def square(bpy, name, uvs):
    """A 2 x 2 square in the x-z plane facing -y (towards the camera), with the corners' UVs."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)], [], [(0, 1, 2, 3)])
    layer = mesh.uv_layers.new(name="UVMap")
    for loop, coord in enumerate(uvs):
        layer.data[loop].uv = coord
    return mesh


def make(out, refused=False):
    import bpy
    from texcc_tools.testing.make_blend import new_scene
    scene = new_scene(128, 64, 16, max_bounces=2, color=(0.0, 0.0, 0.0, 1.0))
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    # 8 units across at y = 0, 12 away: 36 mm sensor, lens 36 * 12 / 8.
    cam.data.lens = 54.0
    cam.location, cam.rotation_euler = (0.0, -12.0, 0.0), (math.pi / 2, 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy, sun.data.angle = 3.0, math.radians(1.0)
    sun.rotation_euler = (math.radians(60), 0.0, math.radians(-30))
    scene.collection.objects.link(sun)

    image = bpy.data.images.new("NormalMap", 24, 16, alpha=True)
    image.colorspace_settings.name = "Non-Color"
    image.pixels.foreach_set(normal_map_pixels(24, 16))
    image.filepath_raw = os.path.join(os.path.dirname(os.path.abspath(out)), "normal-map.png")
    image.file_format = "PNG"
    image.save()
    image.pack()
    image.colorspace_settings.name = "Non-Color"

    for k, strength in enumerate((0.0, 0.5, 1.0, 2.0)):
        obj = link(bpy, scene, "Sphere%d" % k, uv_sphere(bpy, "Sphere%d" % k),
                   material(bpy, "Strength%g" % strength, image, strength),
                   (-3.0 + 2 * k, 0.0, 1.0))
    obj.scale, obj.rotation_euler = (1.0, 0.6, 0.8), (0.3, 0.2, 0.1)  # Strength 2: not uniform
    turned = [(0.0, 2.0), (0.0, 0.0), (2.0, 0.0), (2.0, 2.0)]  # u along the square's -z
    obj = link(bpy, scene, "Turned", square(bpy, "Turned", turned),
               material(bpy, "TurnedUV", image, 1.0), (-3.0, 0.0, -1.0),
               (0.0, math.radians(30), 0.0))
    obj.scale = (0.7, 0.5, 0.55)  # turned, it stays inside its 2 x 2 slot; not uniform
    mirrored = [(1.0, 0.0), (0.0, 0.0), (0.0, 1.0), (1.0, 1.0)]  # u along -x
    link(bpy, scene, "Mirrored", square(bpy, "Mirrored", mirrored),
         material(bpy, "MirroredUV", image, 1.0), (-1.0, 0.0, -1.0))
    plain = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    # Turned half a turn about z: its front faces +y, away from the camera.
    link(bpy, scene, "Back", square(bpy, "Back", plain), material(bpy, "BackFace", image, 1.0),
         (1.0, 0.0, -1.0), (0.0, 0.0, math.pi))
    link(bpy, scene, "Lit", uv_sphere(bpy, "Lit"), material(bpy, "Lit", image, 1.0, lit=True),
         (3.0, 0.0, -1.0))
    if refused:
        bpy.data.materials["Strength1"].node_tree.nodes["Normal Map"].space = "OBJECT"
        sphere = bpy.data.objects["Sphere0"].data
        sphere.uv_layers.new(name="Other")
        bpy.data.materials["Strength0"].node_tree.nodes["Normal Map"].uv_map = "Other"
        bare = bpy.data.meshes.new("Bare")
        bare.from_pydata([(-1, 0, -1), (1, 0, -1), (1, 0, 1)], [], [(0, 1, 2)])
        link(bpy, scene, "Bare", bare, bpy.data.materials["Strength0.5"], (0.0, 2.0, 3.0))
    bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(out))


def reference(spp):
    """Cycles' block means (8x8 pixels; the silhouettes marked) into REFERENCE."""
    from texcc_tools.testing.cycles_render import write_reference
    blend = os.path.join(tempfile.mkdtemp(), "normal-map.blend")
    write_reference(__file__, blend, [], spp, REFERENCE, (16, 8), 0.01, edges=True)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--reference"]:
        reference(int(sys.argv[2]) if len(sys.argv) > 2 else 1024)
    elif sys.argv[1:2] == ["--render"]:
        from texcc_tools.testing.cycles_render import render_file
        render_file(sys.argv[2], int(sys.argv[3]), transparent=True)
    else:
        make(sys.argv[1], sys.argv[2:3] == ["refused"])
