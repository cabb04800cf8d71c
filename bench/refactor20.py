#!/usr/bin/env python3
"""Issue 20's before/after (bench/refactor-20.md): callgrind instructions per textured hit of
every example in every mode, counted as bench/instructions.py counts them (texcc-eval on PoCL's
CPU device, POCL_LLVM_CPU_NAME=haswell, inclusive Ir of the work-group functions), for one or
more builds, and interp's mechanisms under review (the local-memory value stack, quickened
opcodes) against the kernel without them.

The code is texcc_tools.bench.refactor20 (python/texcc_tools/bench/refactor20.py)."""
import _bootstrap  # noqa: F401  (texcc_tools importable whichever Python runs this)
from texcc_tools.bench import common
from texcc_tools.bench.refactor20 import main

if __name__ == "__main__":
    common.run_main(main, "bench/refactor20.py")
