#!/usr/bin/env python3
"""The split of texrender's fixed start-up cost (bench/startup.md): classifies the CPU samples
of `perf record -e cpu-clock --call-graph dwarf` of one texrender run by phase.

A sample belongs to the first phase (in PHASES' order) with a function on its call chain; a
sample without one goes, in a thread with classified samples, with that thread's next
classified sample (a chain perf could not unwind), and otherwise (Embree's TBB workers, PoCL's
device threads) with the last classified sample before it of any thread, so that the worker
threads' share of a BVH build counts for that build.

usage: perf record -e cpu-clock -F 2000 --call-graph dwarf,32768 -o P texrender ...
       perf script -i P -F pid,tid,time,ip,sym > P.txt
       python3 bench/startup_split.py P.txt

The measurement is texcc_tools.bench.startup_split (python/texcc_tools/bench/startup_split.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench.startup_split import main

if __name__ == "__main__":
    main()
