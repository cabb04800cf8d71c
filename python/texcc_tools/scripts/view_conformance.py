"""view_conformance.py: texrender's PNG against Blender's PNG of the same EXR, through the same
Color Management (view transform, look, exposure, gamma; display sRGB).

For each EXR (a generated one, and any given with --exr) and each case, texrender writes the
PNG (`texrender --from-exr IN.exr -o OUT.png --view-transform V --look L --exposure E --gamma G
--ocio-config CONFIG`) and Blender (bpy 5.0.1, in this process) loads the EXR as an image and
saves it as an 8-bit PNG with the scene's view settings (Image.save_render, dither off). Per
channel: the fraction of values within 1/255 and the largest difference in 1/255 steps. Exit 1
when a case has a channel with fewer than --min-within of its values within 1/255.

  .venv/bin/python scripts/view_conformance.py --exe build/bin/texrender -o OUT [--all]
      [--exr FILE.exr ...] [--min-within 0.99]

The generated EXR (256x128) holds a grey ramp from 2^-12 to 2^10 at several saturations,
saturated hues from 0.01 to 100, colours with negative components (out of Rec.709's gamut)
up to 3, and random colours from 1e-4 to 1e3 per channel.
"""
import argparse
import colorsys
import os
import subprocess
import sys

import numpy as np

from texcc_tools import exr as texexr

# (view transform, look, exposure, gamma); QUICK is the test's subset of ALL.
QUICK = [
    ("Standard", "None", 0.0, 1.0),
    ("Standard", "None", 1.5, 2.2),
    ("AgX", "None", 0.0, 1.0),
    ("AgX", "AgX - Punchy", 0.0, 1.0),
    ("AgX", "AgX - High Contrast", -1.0, 0.8),
    ("Filmic", "Medium High Contrast", 0.5, 1.0),
]
AGX_LOOKS = ["AgX - Punchy", "AgX - Greyscale", "AgX - Very High Contrast", "AgX - High Contrast",
             "AgX - Medium High Contrast", "AgX - Base Contrast", "AgX - Medium Low Contrast",
             "AgX - Low Contrast", "AgX - Very Low Contrast"]
FILMIC_LOOKS = ["Very High Contrast", "High Contrast", "Medium High Contrast", "Medium Contrast",
                "Medium Low Contrast", "Low Contrast", "Very Low Contrast"]
ALL = ([("Standard", "None", 0.0, 1.0), ("Standard", "None", 1.5, 1.0),
        ("Standard", "None", 0.0, 2.2), ("Standard", "None", -2.0, 0.6),
        ("AgX", "None", 0.0, 1.0), ("AgX", "None", 2.0, 1.0), ("AgX", "None", -1.5, 1.8)]
       + [("AgX", look, 0.0, 1.0) for look in AGX_LOOKS]
       + [("AgX", "AgX - Punchy", 1.0, 0.7), ("Filmic", "None", 0.0, 1.0),
          ("Filmic", "None", 1.0, 1.4)]
       + [("Filmic", look, 0.0, 1.0) for look in FILMIC_LOOKS])


def generated_image():
    w, h = 256, 128
    img = np.zeros((h, w, 3), np.float32)
    x = np.arange(w) / (w - 1)
    for r in range(32):  # grey ramp 2^-12..2^10, saturation by row
        lum = 2.0 ** (-12 + 22 * x)
        tint = np.array(colorsys.hsv_to_rgb(r / 32, r / 40, 1.0), np.float32)
        img[r] = lum[:, None] * tint[None, :]
    for r in range(32):  # saturated hues, value 0.01..100 by row
        v = 10 ** (-2 + 4 * r / 31)
        img[32 + r] = [np.array(colorsys.hsv_to_rgb(t, 1.0, 1.0)) * v for t in x]
    rng = np.random.default_rng(7)
    img[64:96] = rng.uniform(-1.0, 3.0, (32, w, 3))  # negative components: out of gamut
    img[96:128] = np.exp(rng.uniform(np.log(1e-4), np.log(1e3), (32, w, 3)))
    return img


def read_png(bpy, path):
    """An 8-bit PNG's RGB codes as an int array (height, width, 3), read by Blender: a byte
    image's pixels are its codes / 255, rows bottom to top."""
    image = bpy.data.images.load(path, check_existing=False)
    w, h = image.size
    values = np.empty(w * h * 4, np.float32)
    image.pixels.foreach_get(values)
    bpy.data.images.remove(image)
    return np.rint(values.reshape(h, w, 4)[::-1, :, :3] * 255).astype(np.int32)


def blender_png(bpy, exr, png, case, dither=0.0):
    view, look, exposure, gamma = case
    scene = bpy.context.scene
    vs = scene.view_settings
    scene.display_settings.display_device = "sRGB"
    vs.view_transform = view
    vs.look = look
    vs.exposure = exposure
    vs.gamma = gamma
    vs.use_curve_mapping = False
    vs.use_white_balance = False
    scene.render.dither_intensity = dither
    settings = scene.render.image_settings
    settings.file_format = "PNG"
    settings.color_mode = "RGB"
    settings.color_depth = "8"
    image = bpy.data.images.load(exr, check_existing=False)
    image.colorspace_settings.name = "Linear Rec.709"
    image.save_render(png, scene=scene)
    bpy.data.images.remove(image)


def check_render(args, config):
    """Renders args.render to render.exr; to a PNG through AgX - Punchy at +0.5 stops given on
    the command line; and to a PNG from a copy of the scene whose film.view says the same, the
    config from $OCIO. Both PNGs must be the EXR through --from-exr, byte for byte. Returns the
    EXR (None: they differ)."""
    import json
    exr = os.path.join(args.out, "render.exr")
    settings = {"transform": "AgX", "look": "AgX - Punchy", "exposure": 0.5}
    view = ["--view-transform", "AgX", "--look", "AgX - Punchy", "--exposure", "0.5",
            "--ocio-config", config]
    subprocess.run([args.exe, args.render, "--quiet", "-o", exr], check=True)
    pngs = [os.path.join(args.out, "render-%s.png" % k) for k in ("exr", "options", "scene")]
    subprocess.run([args.exe, "--from-exr", exr, "-o", pngs[0]] + view, check=True)
    subprocess.run([args.exe, args.render, "--quiet", "-o", pngs[1]] + view, check=True)
    scene = json.load(open(args.render))
    scene.setdefault("film", {})["view"] = settings
    base = os.path.dirname(os.path.abspath(args.render))
    if "textures" in scene:
        scene["textures"] = os.path.join(base, scene["textures"])
    for mesh in scene.get("meshes", []):
        mesh["obj"] = os.path.join(base, mesh["obj"])
    copy = os.path.join(args.out, "scene-view.json")
    json.dump(scene, open(copy, "w"))
    subprocess.run([args.exe, copy, "--quiet", "-o", pngs[2]], check=True,
                   env=dict(os.environ, OCIO=config))
    same = [open(p, "rb").read() == open(pngs[0], "rb").read() for p in pngs[1:]]
    for how, ok in zip(("the command line's view options", "the scene's film.view"), same):
        print("render: the PNG through %s (AgX - Punchy, +0.5) is %s" %
              (how, "its EXR through --from-exr, byte for byte" if ok else
               "NOT its EXR's PNG: FAIL"))
    return exr if all(same) else None


def compare(a, b):
    """Per channel: (fraction within 1/255, largest difference in 1/255 steps)."""
    d = np.abs(a.astype(np.int32) - b.astype(np.int32))
    return [((d[:, :, c] <= 1).mean(), int(d[:, :, c].max())) for c in range(3)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True, help="the texrender binary")
    ap.add_argument("-o", "--out", required=True, help="folder for the EXR and PNG files")
    ap.add_argument("--exr", action="append", default=[], help="another EXR to convert")
    ap.add_argument("--render", metavar="SCENE", help="also render SCENE (scene.json) to an EXR, "
                    "compare it too, and check that a render written as PNG through a view is "
                    "byte for byte its EXR through --from-exr")
    ap.add_argument("--all", action="store_true", help="every view and look (else a quick set)")
    ap.add_argument("--min-within", type=float, default=0.99)
    ap.add_argument("--dither", type=float, default=0.0,
                    help="Blender's Post Processing > Dither for its PNGs (default 0, off)")
    ap.add_argument("--baseline", action="store_true",
                    help="also compare Blender's PNG with texrender's plain sRGB PNG (no view)")
    args = ap.parse_args()
    import bpy  # after argparse: --help needs no Blender
    config = os.path.join(bpy.utils.system_resource("DATAFILES"), "colormanagement", "config.ocio")
    os.makedirs(args.out, exist_ok=True)
    generated = os.path.join(args.out, "generated.exr")
    with open(generated, "wb") as f:
        f.write(texexr.write_exr(generated_image()))
    ok = True
    exrs = [generated] + args.exr
    if args.render:
        exrs.append(check_render(args, config))
        ok &= exrs[-1] is not None
    for exr in filter(None, exrs):
        name = os.path.splitext(os.path.basename(exr))[0]
        for k, case in enumerate(ALL if args.all else QUICK):
            view, look, exposure, gamma = case
            ours = os.path.join(args.out, "%s-%d-texrender.png" % (name, k))
            theirs = os.path.join(args.out, "%s-%d-blender.png" % (name, k))
            subprocess.run([args.exe, "--from-exr", exr, "-o", ours, "--view-transform", view,
                            "--look", look, "--exposure", repr(exposure), "--gamma", repr(gamma),
                            "--ocio-config", config], check=True)
            blender_png(bpy, os.path.abspath(exr), os.path.abspath(theirs), case, args.dither)
            result = compare(read_png(bpy, ours), read_png(bpy, theirs))
            good = all(within >= args.min_within for within, _ in result)
            ok &= good
            same = (read_png(bpy, ours) == read_png(bpy, theirs)).mean()
            print("%-10s %-8s %-26s exposure %+5.2f gamma %4.2f  within 1/255 R %.5f G %.5f "
                  "B %.5f  max %d/%d/%d  identical %.4f  %s"
                  % (name, view, look, exposure, gamma, *[w for w, _ in result],
                     *[m for _, m in result], same, "ok" if good else "FAIL"))
            if args.baseline:
                plain = os.path.join(args.out, "%s-plain.png" % name)
                if not os.path.exists(plain):
                    subprocess.run([args.exe, "--from-exr", exr, "-o", plain], check=True)
                old = compare(read_png(bpy, plain), read_png(bpy, theirs))
                print("%-10s   plain sRGB PNG (texrender before): within 1/255 R %.5f G %.5f B %.5f"
                      "  max %d/%d/%d" % (name, *[w for w, _ in old], *[m for _, m in old]))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
