"""Runs scripts/serve.py with a Python audit hook that appends every path the server opens
(builtins.open, io.open, os.open, in any of its threads) to $SERVE_AUDIT_LOG, one a line: the
tests check that the server opens no file of the user's (docs/live.md, "Browser preview").

  serve_audit.py SERVE.PY [serve.py arguments]
"""
import os
import runpy
import sys

LOG = open(os.environ["SERVE_AUDIT_LOG"], "a", buffering=1)


def hook(event, args):
    if event in ("open", "os.open") and isinstance(args[0], (str, bytes, os.PathLike)):
        LOG.write(os.fsdecode(os.path.abspath(args[0])) + "\n")


sys.addaudithook(hook)
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
