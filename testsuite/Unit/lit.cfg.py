# lit configuration for the GoogleTest binaries (every *Tests executable in build/unittests).
import os

import lit.formats

config.name = "texcc-unit"
config.test_format = lit.formats.GoogleTest(".", "Tests")
config.test_source_root = config.unittest_dir
config.test_exec_root = config.unittest_dir
for var in ("HOME", "TMPDIR", "POCL_CACHE_DIR", "OCL_ICD_VENDORS", "POCL_DEVICES"):
    if var in os.environ:
        config.environment[var] = os.environ[var]
config.environment["TEXCC_SRC"] = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
