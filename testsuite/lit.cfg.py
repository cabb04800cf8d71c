# lit configuration for texcc's FileCheck tests. Tools come in by substitution, never by path.
import os
import subprocess
import sys

import lit.formats

config.name = "texcc"
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "utils"))
from kernel_check import KernelCheckedShTest  # noqa: E402

# Every passing test's proctex*.cl files are syntax-checked by clang (utils/kernel_check.py).
config.test_format = KernelCheckedShTest(config.clang, not lit_config.isWindows)
config.suffixes = [".cl", ".json", ".test"]
config.excludes = ["Inputs", "Unit", "utils", "lit.cfg.py", "CMakeLists.txt"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = os.path.join(config.texcc_obj_root, "testsuite")

# The sanitizer build (scripts/test-asan.sh): ASan reserves terabytes of address space for its
# shadow memory, so tests that pin memory with `ulimit -v` cannot run there (UNSUPPORTED: asan).
if getattr(config, "texcc_sanitize", "OFF").upper() in ("ON", "1", "TRUE", "YES"):
    config.available_features.add("asan")
# REQUIRES: slow-tier — the slow tier (docs/testing.md): statistical comparisons with Cycles,
# every-example and every-node sweeps, multi-process farm runs and large-scale reliability cases.
# The default run (scripts/test.sh) reports them UNSUPPORTED; `scripts/test.sh --slow` (lit
# --param slow-tier=1) runs them too, as CI does (.ci/run). Each marked test says why in a
# "Slow tier:" comment and keeps a cheaper neighbour of its feature area in the default tier.
if lit_config.params.get("slow-tier", "0") not in ("", "0"):
    config.available_features.add("slow-tier")
else:
    lit_config.note("the slow tier is off: tests that REQUIRE slow-tier are skipped "
                    "(scripts/test.sh --slow runs them)")
tools = config.texcc_tools_dir
config.substitutions.append(("%texcc-src", config.texcc_src_root))
config.substitutions.append(("%inputs", os.path.join(config.test_source_root, "Inputs")))
config.substitutions.append(("%python", sys.executable))
# Longest names first: lit substitutes in order.
config.substitutions.append(("texcc-cl-probe", os.path.join(tools, "texcc-cl-probe")))
config.substitutions.append((r"(?<![\w/.-])texcc-fe(?![\w.-])", os.path.join(tools, "texcc-fe")))
config.substitutions.append(("texrender", os.path.join(tools, "texrender")))
config.substitutions.append((r"(?<![\w/.-])texcc-graph(?![\w.-])", os.path.join(tools, "texcc-graph")))
# Tool names are matched as whole words: a substituted path (".../bin/texcc-fe") must not be
# substituted again by a shorter name.
config.substitutions.append((r"(?<![\w/.-])texcc(?![\w.-])", os.path.join(tools, "texcc")))
config.substitutions.append(("FileCheck", config.filecheck))
config.substitutions.append(("not ", config.not_tool + " "))
config.substitutions.append(("%clang", config.clang))

config.environment["TEXCC_SRC"] = config.texcc_src_root
for var in ("HOME", "TMPDIR", "POCL_CACHE_DIR", "OCL_ICD_VENDORS", "POCL_DEVICES"):
    if var in os.environ:
        config.environment[var] = os.environ[var]
# Tests count kernel builds and name tiers: they run texrender without the prebuilt fixed
# kernels (build/programs) and without the quick first build (docs/runtime.md, "Cold start"),
# whose background optimised build would make those counts depend on timing. The tests of
# those two features (runtime/coldstart-*) turn them back on with env.
config.environment["TEXRENDER_PREBUILT_DIR"] = ""
config.environment["TEXRENDER_FIRST_BUILD"] = "optimised"

# REQUIRES: opencl — present only when an OpenCL device answers.
probe = os.path.join(tools, "texcc-cl-probe")
try:
    found = subprocess.run([probe], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=60).returncode == 0
except (OSError, subprocess.TimeoutExpired):
    found = False
if found:
    config.available_features.add("opencl")
else:
    lit_config.note("no OpenCL device found: tests that REQUIRE opencl are skipped")

shared = os.path.join(config.texcc_src_root, "..", "shared")
if os.path.isdir(os.path.join(shared, "assets")):
    config.available_features.add("shared-assets")
    config.substitutions.append(("%shared", os.path.abspath(shared)))
else:
    lit_config.note("../shared/assets is absent: tests that REQUIRE shared-assets are skipped")

# REQUIRES: ray — scripts/farm.py's tests need Ray in .venv/ (scripts/requirements-farm.txt;
# .ci/run installs it).
import glob  # noqa: E402
if glob.glob(os.path.join(config.texcc_src_root, ".venv", "lib", "python3*", "site-packages",
                          "ray", "__init__.py")):
    config.available_features.add("ray")
else:
    lit_config.note("Ray is not installed in .venv/ (pip install -r scripts/requirements-farm.txt): "
                    "tests that REQUIRE ray are skipped")

# REQUIRES: bpy — the Blender exporter's tests (scripts/blender_export.py) need the bpy wheel in
# .venv/ (the exporter installs it on first use: about 370 MB).
if glob.glob(os.path.join(config.texcc_src_root, ".venv", "lib", "python3*", "site-packages",
                          "bpy-*.dist-info")):
    config.available_features.add("bpy")
else:
    lit_config.note("bpy is not installed in .venv/ (pip install -r "
                    "scripts/requirements-blender.txt): tests that REQUIRE bpy (the Blender "
                    "exporter on .blend files) are skipped")

# REQUIRES: aiohttp — the browser preview's server (scripts/serve.py) and its tests;
# `scripts/serve.sh --install` puts it into .venv/ (scripts/requirements-serve.txt).
# REQUIRES: chromium — the browser test drives Debian's chromium + chromium-driver with selenium.
import importlib.util  # noqa: E402
import shutil  # noqa: E402
if importlib.util.find_spec("aiohttp"):
    config.available_features.add("aiohttp")
else:
    lit_config.note("aiohttp is not installed (scripts/serve.sh --install): the browser "
                    "preview's tests (REQUIRES: aiohttp) are skipped")
if shutil.which("chromium") and shutil.which("chromedriver") and importlib.util.find_spec("selenium"):
    config.available_features.add("chromium")
else:
    lit_config.note("chromium, chromium-driver (apt) or selenium (scripts/serve.sh --install) "
                    "is missing: the browser test (REQUIRES: chromium) is skipped")
