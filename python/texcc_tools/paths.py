"""The repository's folders, the build folder and its binaries: the one place that knows them.

A build folder is --build when a command has that option, else $TEXCC_BUILD_DIR, else build/."""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPTS = os.path.join(ROOT, "scripts")
BENCH = os.path.join(ROOT, "bench")
RESULTS = os.path.join(BENCH, "results")
CHARTS = os.path.join(BENCH, "charts")
EXAMPLES = os.path.join(ROOT, "examples")
KERNELS = os.path.join(ROOT, "kernels")
TEXTURES = os.path.join(ROOT, "textures")
TESTSUITE = os.path.join(ROOT, "testsuite")
INPUTS = os.path.join(TESTSUITE, "Inputs")
VENV_PYTHON = os.path.join(ROOT, ".venv", "bin", "python")


def default_build_dir():
    """$TEXCC_BUILD_DIR, else the repository's build/."""
    return os.environ.get("TEXCC_BUILD_DIR") or os.path.join(ROOT, "build")


def tool(name, build=None):
    """The path of binary `name` (texcc, texrender, texrender-compare...) in a build folder."""
    return os.path.join(build or default_build_dir(), "bin", name)


def add_build_argument(parser, help=None):
    """The --build option every command that runs texcc or texrender takes."""
    parser.add_argument("--build", default=default_build_dir(),
                        help=help or "build folder (default: $TEXCC_BUILD_DIR, else build/)")
