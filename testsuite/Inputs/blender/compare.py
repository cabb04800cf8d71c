"""compare.py: texcc's Blender nodes (textures/blender/) against the Cycles fixtures.

    compare.py --texcc T --eval E --src ROOT --work DIR [--host] [--tol 1e-4]
               [--cl-options STR] [--rows FILE.json] FIXTURE.json ...

The code is texcc_tools.testing.compare (scripts/swatches.py builds its graph with it too)."""
from texcc_tools.testing.compare import main

if __name__ == "__main__":
    main()
