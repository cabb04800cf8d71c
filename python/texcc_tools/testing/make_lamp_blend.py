"""make_lamp_blend.py: .blend files lit only by Blender's point, spot and area lamps, for
testsuite/blender-export/export-lamps.test and bench/cycles.py's lamp figures (bpy; .venv).

    make_lamp_blend.py OUT.blend CASE
    make_lamp_blend.py --all OUTDIR            OUTDIR/CASE.blend for every case of CASES
    make_lamp_blend.py --reference [--spp N] [--cases A,B]

The scene (Blender's Z up): a grey diffuse floor (8 m square), a pale red back wall at y = 2.5,
a green-grey cube (1 m) at the origin, a black world, a camera at (0, -6, 2.2) looking at
(0, 0, 0.8), 64x48, Cycles with the settings texrender reproduces (make_blend.py's
reproducible(): Max Bounces 6 -> maxDepth 8, no light tree, no clamping, box filter). Every
lamp is above the camera's view (the image shows what they light, not the lamps). CASES:
"point" (radius 0.2, 300 W, warm), "spot" (radius 0.1, 800 W, 40 deg, blend 0.3, aimed at the
cube), "area-rect" (1.5 m x 0.6 m, the object scaled 1.2 in X, tilted, 150 W), "area-disk"
(1 m disk, 120 W, bluish), "three-point" (a key area rectangle, a fill point lamp and a rim
spot behind the cube), "sphere" (a point lamp of radius 0.4 with Soft Falloff off, 0.9 m from
the cube: Cycles' sphere lamp, in view of the camera but not visible to it), "visible" (a
point lamp, an area rectangle facing the camera and a spot aimed at it, all in view with Ray
Visibility > Camera on: the camera sees the point's disk, the rectangle's lit side and the
spot's disk inside its cone); "refused" (for the error test: a point lamp without Soft Falloff, a
square spot scaled (1, 2, 1), an area lamp of Spread 90 deg and Max Bounces 2, a point lamp
with Light Linking and Glossy visibility off, and a portal); "interior" (bench only: the
three-lamp interior, a closed room lit by an area key, a point fill and a spot accent).

--reference renders each case with Cycles (CPU, N spp, default 4096; cycles_render.py) and
writes the 16x16-pixel block means into cycles-lamp-CASE.json (region_means.py --write).
"""
import math
import os


CASES = ("point", "spot", "area-rect", "area-disk", "three-point", "sphere", "visible")


def aim(obj, target):
    """Rotates obj so that its -Z looks at target (lamps and cameras look down their -Z)."""
    from mathutils import Vector
    d = Vector(target) - obj.location
    obj.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()


def lamp(scene, name, kind, location, target, energy, color=(1, 1, 1), **settings):
    import bpy
    data = bpy.data.lights.new(name, kind)
    data.energy = energy
    data.color = color
    for key, value in settings.items():
        setattr(data, key, value)
    obj = bpy.data.objects.new(name, data)
    obj.location = location
    scene.collection.objects.link(obj)
    if target is not None:
        aim(obj, target)
    return obj


def make(out, case):
    import bpy
    from texcc_tools.testing.make_blend import add_mesh, cube_mesh, new_scene, quad, simple
    scene = new_scene(64, 48, 64, color=(0, 0, 0, 1))
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.data.lens = 50.0
    cam.location = (0.0, -6.0, 2.2)
    aim(cam, (0.0, 0.0, 0.8))
    scene.collection.objects.link(cam)
    scene.camera = cam
    floor = simple("Floor", "ShaderNodeBsdfDiffuse", (0.6, 0.6, 0.6, 1))
    wall = simple("Wall", "ShaderNodeBsdfDiffuse", (0.7, 0.45, 0.4, 1))
    box = simple("Box", "ShaderNodeBsdfDiffuse", (0.4, 0.55, 0.35, 1))
    add_mesh("Floor", quad("floor", 8.0, 0.0), floor)
    back = add_mesh("Wall", quad("wall", 8.0, 0.0), wall)
    back.rotation_euler = (math.pi / 2, 0.0, 0.0)  # the quad's +Z normal turns to -Y
    back.location = (0.0, 2.5, 0.0)
    add_mesh("Cube", cube_mesh(), box)
    if case == "point":
        lamp(scene, "Point", "POINT", (1.5, -1.0, 3.0), None, 300.0, (1.0, 0.9, 0.8),
             shadow_soft_size=0.2)
    elif case == "spot":
        lamp(scene, "Spot", "SPOT", (-1.5, -1.5, 3.2), (0.0, 0.0, 0.5), 800.0,
             shadow_soft_size=0.1, spot_size=math.radians(40.0), spot_blend=0.3)
    elif case == "area-rect":
        o = lamp(scene, "Rect", "AREA", (0.3, -1.5, 3.0), (0.0, 0.3, 0.0), 150.0,
                 shape="RECTANGLE", size=1.5, size_y=0.6)
        o.scale = (1.2, 1.0, 1.0)
    elif case == "area-disk":
        lamp(scene, "Disk", "AREA", (1.2, 0.5, 3.0), (0.8, 0.3, 0.0), 120.0, (0.8, 0.9, 1.0),
             shape="DISK", size=1.0)
    elif case == "three-point":
        lamp(scene, "Key", "AREA", (-2.0, -2.0, 3.0), (0.0, 0.0, 0.5), 250.0, (1.0, 0.95, 0.9),
             shape="RECTANGLE", size=1.2, size_y=0.8)
        lamp(scene, "Fill", "POINT", (2.5, -1.5, 3.2), None, 120.0, (0.8, 0.85, 1.0),
             shadow_soft_size=0.3)
        lamp(scene, "Rim", "SPOT", (0.5, 2.0, 3.5), (0.0, 0.0, 0.8), 500.0, (1.0, 1.0, 0.9),
             shadow_soft_size=0.05, spot_size=math.radians(35.0), spot_blend=0.15)
    elif case == "sphere":
        lamp(scene, "Ball", "POINT", (1.0, -0.6, 1.5), None, 150.0, (1.0, 0.9, 0.8),
             shadow_soft_size=0.4, use_soft_falloff=False)
    elif case == "visible":  # lamps the camera sees (Ray Visibility > Camera on)
        lamp(scene, "Bulb", "POINT", (-1.0, -1.0, 1.2), None, 100.0,
             shadow_soft_size=0.15).visible_camera = True
        lamp(scene, "Panel", "AREA", (1.2, -0.5, 1.2), (0.0, -6.0, 1.5), 60.0,
             shape="RECTANGLE", size=0.6, size_y=0.3).visible_camera = True
        lamp(scene, "Beam", "SPOT", (0.0, -1.0, 0.3), (0.0, -6.0, 2.2), 50.0,
             shadow_soft_size=0.1, spot_size=math.radians(60.0)).visible_camera = True
    elif case == "interior":
        interior(scene, cam, floor, wall, box)
    elif case == "refused":
        lamp(scene, "Sphere", "POINT", (1.5, -1.0, 3.0), None, 100.0, shadow_soft_size=0.2,
             use_soft_falloff=False)
        o = lamp(scene, "Square", "SPOT", (-1.5, -1.5, 3.2), (0.0, 0.0, 0.5), 100.0,
                 use_square=True)
        o.scale = (1.0, 2.0, 1.0)
        o = lamp(scene, "Narrow", "AREA", (0.3, -1.5, 3.0), (0.0, 0.3, 0.0), 100.0,
                 spread=math.radians(90.0))
        o.data.cycles.max_bounces = 2
        o = lamp(scene, "Linked", "POINT", (0.0, 1.0, 3.0), None, 50.0)
        o.light_linking.receiver_collection = bpy.data.collections.new("Receivers")
        o.visible_glossy = False
        o = lamp(scene, "Window", "AREA", (0.0, 2.4, 1.5), (0.0, 0.0, 1.5), 100.0)
        o.data.cycles.is_portal = True
    else:
        raise SystemExit("make_lamp_blend.py: unknown case '%s' (cases: %s)"
                         % (case, ", ".join(CASES)))
    bpy.ops.wm.save_as_mainfile(filepath=out)


def interior(scene, cam, floor, wall, box):
    """The three-lamp interior: the floor and wall of make() become a closed room (6 x 5 x 3 m,
    walls and ceiling pale), a second box, the camera inside (24 mm lens) and three lamps: an
    area key on the ceiling, a point fill and a spot accent on the cube."""
    import bpy
    from texcc_tools.testing.make_blend import add_mesh, cube_mesh, quad
    for name in ("Floor", "Wall", "Cube"):
        bpy.data.objects.remove(bpy.data.objects[name])
    ceiling_mat = bpy.data.materials["Wall"]
    add_mesh("Floor", quad("floor", 1.0, 0.0), floor).scale = (6.0, 5.0, 1.0)
    c = add_mesh("Ceiling", quad("ceiling", 1.0, 0.0), ceiling_mat)
    c.scale, c.location = (6.0, 5.0, 1.0), (0.0, 0.0, 3.0)
    for name, loc, rot, scale in (("Back", (0.0, 2.5, 1.5), (math.pi / 2, 0, 0), (6.0, 3.0, 1)),
                                  ("Front", (0.0, -2.5, 1.5), (math.pi / 2, 0, 0), (6.0, 3.0, 1)),
                                  ("Left", (-3.0, 0.0, 1.5), (0, math.pi / 2, 0), (3.0, 5.0, 1)),
                                  ("Right", (3.0, 0.0, 1.5), (0, math.pi / 2, 0), (3.0, 5.0, 1))):
        w = add_mesh(name, quad(name.lower(), 1.0, 0.0), wall)
        w.location, w.rotation_euler, w.scale = loc, rot, scale
    add_mesh("Cube", cube_mesh(), box).location = (0.6, 0.8, 0.0)
    b = add_mesh("Shelf", cube_mesh(), floor)
    b.location, b.scale = (-1.8, 1.6, 0.0), (1.2, 0.6, 1.6)
    cam.location = (0.4, -2.3, 1.5)
    cam.data.lens = 24.0
    aim(cam, (0.0, 1.0, 0.9))
    lamp(scene, "Key", "AREA", (0.5, 0.3, 2.95), (0.5, 0.3, 0.0), 60.0, (1.0, 0.95, 0.85),
         shape="RECTANGLE", size=1.2, size_y=0.6)
    lamp(scene, "Fill", "POINT", (-2.0, -1.2, 2.2), None, 25.0, (0.8, 0.85, 1.0),
         shadow_soft_size=0.15)
    lamp(scene, "Accent", "SPOT", (2.4, 1.8, 2.6), (0.6, 0.8, 0.5), 150.0, (1.0, 0.9, 0.7),
         shadow_soft_size=0.05, spot_size=math.radians(50.0), spot_blend=0.4)
