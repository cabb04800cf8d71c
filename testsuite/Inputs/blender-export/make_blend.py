"""make_blend.py: small .blend files for the exporter's tests (bpy; run with .venv's Python).

    make_blend.py OUT.blend [CASE]

The cases are texcc_tools.testing.make_blend's (python/texcc_tools/testing/make_blend.py)."""
from texcc_tools.testing.make_blend import main

if __name__ == "__main__":
    main()
