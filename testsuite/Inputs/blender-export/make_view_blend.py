"""make_view_blend.py: a .blend whose scenes differ only in Color Management, for the exporter's
view-transform tests (bpy; run with .venv's Python).

    make_view_blend.py OUT.blend

Scene "AgX": AgX, look "AgX - Punchy", exposure 0.5, gamma 1.2 (film.view written).
Scene "Filmic": Filmic, look "Medium High Contrast", exposure -1.
Scene "Standard": Standard, no look, exposure 0, gamma 1 (no film.view: texrender's default).
Scene "Refused": display "Display P3", view "ACES 2.0", Curves on, White Balance on, the
output's own Color Management (Override): each refused, listed together.
Each has a camera, a sun and a grey plane, and the render settings texrender reproduces.
"""
import os
import sys

import bpy

from texcc_tools.testing.make_blend import new_scene  # noqa: E402  (after bpy)


def copy_scene(base, name):
    bpy.context.window.scene = base
    bpy.ops.scene.new(type="LINK_COPY")
    scene = bpy.context.scene
    scene.name = name
    return scene


def main():
    out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else sys.argv[1]
    base = new_scene(32, 24, 4, color=(0.2, 0.25, 0.3, 1.0), strength=1.0)
    base.name = "Standard"
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.location, cam.rotation_euler = (0.0, -4.0, 2.0), (1.1, 0.0, 0.0)
    base.collection.objects.link(cam)
    base.camera = cam
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    base.collection.objects.link(sun)
    bpy.ops.mesh.primitive_plane_add(size=4.0)
    settings = {
        "AgX": dict(view_transform="AgX", look="AgX - Punchy", exposure=0.5, gamma=1.2),
        "Filmic": dict(view_transform="Filmic", look="Medium High Contrast", exposure=-1.0),
        "Refused": dict(view_transform="ACES 2.0", use_curve_mapping=True,
                        use_white_balance=True),
    }
    for name, values in settings.items():
        scene = copy_scene(base, name)
        if name == "Refused":  # a display first: it resets a view it does not have
            scene.display_settings.display_device = "Display P3"
            scene.render.image_settings.color_management = "OVERRIDE"
        for key, value in values.items():
            setattr(scene.view_settings, key, value)
    bpy.ops.wm.save_as_mainfile(filepath=out)


if __name__ == "__main__":
    main()
