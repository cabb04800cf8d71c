"""The pinned bpy (Blender as a module) for the scripts that need it: the one reader of
scripts/requirements-blender.txt, and the install-on-first-use step they share."""

import os
import subprocess
import sys

from texcc_tools.paths import ROOT, SCRIPTS, VENV_PYTHON

REQUIREMENTS = os.path.join(SCRIPTS, "requirements-blender.txt")


def _pinned_version():
    with open(REQUIREMENTS) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("bpy=="):
                return line[len("bpy=="):]
    raise SystemExit("%s: no bpy==VERSION line" % REQUIREMENTS)


BPY_VERSION = _pinned_version()


def ensure_bpy(tool, exact=True):
    """Returns when `import bpy` works in this process (the pinned version, else exits);
    otherwise installs scripts/requirements-blender.txt into .venv/ and re-executes the calling
    script with .venv's python. `tool` prefixes the error messages; exact=False accepts any bpy
    already loaded (the exporter inside a Blender of another version)."""
    try:
        import bpy  # noqa: F401
    except ImportError:
        pass
    else:
        if exact and bpy.app.version_string != BPY_VERSION:
            sys.exit("%s: error: bpy %s found, %s pinned (%s)" %
                     (tool, bpy.app.version_string, BPY_VERSION, REQUIREMENTS))
        return
    if os.path.realpath(sys.executable) == os.path.realpath(VENV_PYTHON) and \
            os.environ.get("TEXCC_BPY_INSTALLED"):
        sys.exit("%s: error: bpy==%s did not install into .venv" % (tool, BPY_VERSION))
    if not os.path.exists(VENV_PYTHON):
        subprocess.check_call([sys.executable, "-m", "venv", os.path.join(ROOT, ".venv")])
    probe = subprocess.run([VENV_PYTHON, "-c", "import bpy"], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
    if probe.returncode != 0:
        print("%s: installing bpy==%s into .venv/ (about 370 MB, once)" % (tool, BPY_VERSION),
              file=sys.stderr)
        subprocess.check_call([VENV_PYTHON, "-m", "pip", "install", "-q",
                               "--disable-pip-version-check", "-r", REQUIREMENTS])
        os.environ["TEXCC_BPY_INSTALLED"] = "1"
    os.execv(VENV_PYTHON, [VENV_PYTHON] + sys.argv)
