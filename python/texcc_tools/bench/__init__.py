"""The benchmarks: shared code (common: texcc/texrender runs, stats, results files; resources;
cycles: Blender Cycles as a reference renderer) and each measurement, whose command is the file
of the same name in bench/ (bench/run runs bench/bench.py, whose code is bench here).
BENCHMARKS.md's generator: report (with report_peers and report_texture, its sections on other
renderers and on texture speed) and charts."""
