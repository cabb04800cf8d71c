#!/usr/bin/env python3
"""blender_export.py: a Blender scene as texcc's graph.json, texrender's scene.json and OBJ meshes.

    scripts/blender_export.py FILE.blend -o OUTDIR [--scene NAME] [--camera NAME] [--frame N]
                              [--lenient]
    blender -b FILE.blend --python scripts/blender_export.py -- -o OUTDIR [...]

The exporter is texcc_tools.blender.export (python/texcc_tools/blender/); docs/blender.md."""
import os
import sys

if "bpy" in sys.modules and "--" in sys.argv:
    # Inside Blender: its own Python has no .venv and does not put this folder on the module
    # path; the package is found next to it (the one module-path edit of the tools).
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                    "python"))
else:
    import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.blender.export import main  # noqa: E402

if __name__ == "__main__":
    main()
