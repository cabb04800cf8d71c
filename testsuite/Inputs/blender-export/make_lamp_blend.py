"""make_lamp_blend.py: .blend files lit only by Blender's point, spot and area lamps, for
testsuite/blender-export/export-lamps.test and bench/cycles.py's lamp figures (bpy; .venv).

The cases are texcc_tools.testing.make_lamp_blend's (python/texcc_tools/testing/make_lamp_blend.py); the command line
is cycles_render.case_main's."""
from texcc_tools.testing.cycles_render import case_main
from texcc_tools.testing.make_lamp_blend import CASES, make

if __name__ == "__main__":
    case_main(__file__, make, CASES, "point", "lamp")
