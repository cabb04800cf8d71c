"""How the Cycles references of the blender-export tests are rendered (cycles_reference.py,
glossy_furnace.py cycles, the make_*_blend.py scripts' --reference): imported from .venv's
Python (bpy)."""
import json
import os
import subprocess
import sys
import tempfile

from texcc_tools.exr import read_channels
from texcc_tools.paths import INPUTS

HERE = os.path.join(INPUTS, "blender-export")  # region_means.py and the cycles-*.json references


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
    channels = read_channels(exr)  # RGBA, top row first, as Blender wrote them
    np.save(npy, np.stack([channels[c] for c in "RGBA"], axis=-1))


def render_file(blend, spp, transparent=False):
    """The Cycles image of the .blend file `blend` at `spp`, as the references are made, into
    BLEND.exr and BLEND.npy (a make_*_blend.py script's --render)."""
    import bpy
    bpy.ops.wm.open_mainfile(filepath=blend)
    render_npy(bpy.context.scene, spp, blend + ".exr", blend + ".npy", transparent)


def write_reference(script, blend, make_args, spp, expected, blocks, tolerance, edges=False):
    """A test's Cycles reference: `script` (a make_*_blend.py) writes `blend` (SCRIPT BLEND
    MAKE_ARGS...), renders it in another process (SCRIPT --render BLEND SPP), and its block
    means go into `expected` (region_means.py --write; `edges` marks the blocks a silhouette
    crosses), which starts as BLOCKS (columns, rows) and TOLERANCE when it does not exist."""
    subprocess.check_call([sys.executable, script, blend] + list(make_args))
    subprocess.check_call([sys.executable, script, "--render", blend, str(spp)])
    if not os.path.exists(expected):
        with open(expected, "w") as f:
            f.write(json.dumps({"blocks": list(blocks), "tolerance": tolerance, "means": []}) +
                    "\n")
    subprocess.check_call([sys.executable, os.path.join(HERE, "region_means.py"), blend + ".npy",
                           expected, "--write"] + (["--edges"] if edges else []))


def case_main(script, make, cases, default, kind):
    """The command line of a make_*_blend.py script with cases (make(OUT, CASE) writes one):
    SCRIPT OUT.blend [CASE] (default `default`); SCRIPT --all OUTDIR (every case of `cases`,
    OUTDIR/CASE.blend, in one bpy process); SCRIPT --render BLEND SPP; SCRIPT --reference
    [--spp N] [--cases A,B] (each case's Cycles block means into cycles-KIND-CASE.json, 4 x 3
    blocks, tolerance 0.02 when new; N default 4096)."""
    argv = sys.argv[1:]
    if argv[0] == "--render":
        render_file(argv[1], int(argv[2]))
    elif argv[0] == "--reference":
        spp = int(argv[argv.index("--spp") + 1]) if "--spp" in argv else 4096
        chosen = argv[argv.index("--cases") + 1].split(",") if "--cases" in argv else cases
        work = tempfile.mkdtemp()
        for case in chosen:
            expected = os.path.join(HERE, "cycles-%s-%s.json" % (kind, case))
            write_reference(script, os.path.join(work, case + ".blend"), [case], spp, expected,
                            (4, 3), 0.02)
            print("%s: %s: %s (%d spp)" % (os.path.basename(script)[:-3], case, expected, spp))
    elif argv[0] == "--all":
        for case in cases:
            make(os.path.join(argv[1], case + ".blend"), case)
    else:
        make(argv[0], argv[1] if len(argv) > 1 else default)
