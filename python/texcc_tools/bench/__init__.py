"""The benchmarks: shared code (common: texcc/texrender runs, stats, results files; resources;
cycles: Blender Cycles as a reference renderer) and each measurement, whose command is the file
of the same name in bench/ (bench/run runs bench/bench.py). BENCHMARKS.md's generator
(bench/report*.py, bench/charts.py) stays in bench/."""
