"""make_world_blend.py: .blend files lit only by an HDR world (an Environment Texture), for
testsuite/blender-export/export-world*.test and bench/cycles.py --env (bpy; .venv).

The cases are texcc_tools.testing.make_world_blend's
(python/texcc_tools/testing/make_world_blend.py); the command line
is cycles_render.case_main's."""
from texcc_tools.testing.cycles_render import case_main
from texcc_tools.testing.make_world_blend import CASES, make

if __name__ == "__main__":
    case_main(__file__, make, CASES, "env", "world")
