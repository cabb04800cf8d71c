"""texcc_tools: the shared code of texcc's Python tools (scripts/ and bench/ hold the commands).

paths     the repository's folders, the build folder (--build, TEXCC_BUILD_DIR) and its binaries
process   subprocess runs whose failure is one clear error
exr       the one OpenEXR reader and writer (texrender's files, Blender's 32-bit float ones)
manifest  the one reader (and writer) of a texcc output folder's layout.json
atomic    every output file written through a temporary and a rename
bpy_env   the pinned bpy (Blender as a module), installed on first use
blender   the Blender exporter and its tables (scripts/blender_export.py runs it)
bench     the benchmarks: their shared helpers and each measurement (bench/*.py run them)
farm      the render farm (scripts/farm.py, bench/farm.py)
scripts   the code of the other commands in scripts/ (make_scenes, swatches, ...)
testing   what the test suite's input scripts share (scenes, .blend makers, the Cycles fixtures'
          comparison); testsuite/Inputs/ keeps the files the tests run by path
"""
