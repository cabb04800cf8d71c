"""The benchmarks' shared code: common (texcc/texrender runs, stats, results files), resources
(kernel resource usage), accuracy (image error against references), startup_split (profiles of
texrender's start), cycles (Blender Cycles as a reference renderer). bench/*.py are the
commands (bench/run runs them)."""
