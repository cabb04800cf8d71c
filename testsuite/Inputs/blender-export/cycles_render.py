"""How the Cycles references of the blender-export tests are rendered (cycles_reference.py,
glossy_furnace.py cycles): bpy only, imported from inside Blender's Python."""


def render_npy(scene, spp, exr, npy, transparent=False):
    """Renders `scene` with Cycles as the references are made (CPU, `spp` samples, no denoising,
    no adaptive sampling, a box pixel filter of 1 px; a transparent film when `transparent`,
    so that alpha is the coverage) into the 32-bit EXR `exr`, and saves its RGBA pixels, top
    row first, as the NumPy array `npy`."""
    import bpy
    import numpy as np
    c = scene.cycles
    c.device, c.samples, c.use_denoising, c.use_adaptive_sampling = "CPU", spp, False, False
    c.pixel_filter_type, c.filter_width = "BOX", 1.0
    scene.render.film_transparent = transparent
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = exr
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(exr)
    pixels = np.empty(len(image.pixels), np.float32)
    image.pixels.foreach_get(pixels)
    np.save(npy, pixels.reshape(image.size[1], image.size[0], 4)[::-1])
