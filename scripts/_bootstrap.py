"""Imported first by every command in scripts/ and bench/ (bench/_bootstrap.py is this file):
makes `import texcc_tools` work whichever Python runs the command.

The package (python/texcc_tools/) is installed in .venv/ by scripts/setup.sh. Run by another
Python (`python3 scripts/make_scenes.py`), the command is re-executed with .venv's; without a
.venv holding the package it says to run scripts/setup.sh. (Inside Blender's own Python,
scripts/blender_export.py finds the package itself.)"""
import os
import sys

try:
    import texcc_tools  # noqa: F401
except ImportError:
    _root = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    _venv = os.path.join(_root, ".venv", "bin", "python")
    if os.path.realpath(sys.prefix) == os.path.realpath(os.path.dirname(os.path.dirname(_venv))) \
            or not os.path.exists(_venv):
        sys.exit("%s: error: the texcc_tools package is not installed in %s: run "
                 "scripts/setup.sh" % (os.path.basename(sys.argv[0]),
                                       os.path.dirname(os.path.dirname(_venv))))
    else:
        os.execv(_venv, [_venv] + sys.argv)
