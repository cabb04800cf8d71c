"""Kills a command with SIGKILL part way through, again and again, and checks that its output
folder never holds a partial file (docs/reliability.md, "Nothing half-written").

  kill_test.py --out DIR --old OLD --new NEW --delays 0.1,0.5,... -- COMMAND [ARG...]

Before each run DIR is reset to a copy of OLD (the previous complete outputs). The command,
writing into DIR, is killed after each delay (if still running). Afterwards every file of OLD
and NEW must be in DIR under its name with exactly its OLD or its NEW bytes; a file whose
contents vary between runs (a stats.json with timings) must be equal to OLD or parse as complete
JSON. Hidden files (temporaries, named ".NAME.tmpPID") are ignored. Prints one summary line.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import time


def complete(path, old, new, varying):
    with open(path, "rb") as f:
        data = f.read()
    name = os.path.basename(path)
    versions = [os.path.join(d, name) for d in (old, new) if os.path.exists(os.path.join(d, name))]
    for v in versions:
        with open(v, "rb") as f:
            if f.read() == data:
                return True
    if name in varying:
        try:
            json.loads(data)
            return True
        except ValueError:
            return False
    return False


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--out", required=True)
    p.add_argument("--old", required=True)
    p.add_argument("--new", required=True)
    p.add_argument("--delays", required=True)
    p.add_argument("--varying", default="", help="comma-separated names whose bytes vary")
    p.add_argument("command", nargs=argparse.REMAINDER)
    a = p.parse_args()
    command = a.command[1:] if a.command[:1] == ["--"] else a.command
    varying = set(filter(None, a.varying.split(",")))
    names = sorted(set(os.listdir(a.old)) | set(os.listdir(a.new)))
    killed = 0
    for delay in [float(d) for d in a.delays.split(",")]:
        shutil.rmtree(a.out, ignore_errors=True)
        shutil.copytree(a.old, a.out)
        proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(delay)
        if proc.poll() is None:
            proc.send_signal(signal.SIGKILL)
            killed += 1
        proc.wait()
        for name in names:
            path = os.path.join(a.out, name)
            if not os.path.exists(path):
                sys.exit(f"kill_test.py: after {delay:g} s: {name} is missing")
            if not complete(path, a.old, a.new, varying):
                sys.exit(f"kill_test.py: after {delay:g} s: {name} is neither the old nor a "
                         f"complete new file")
    print(f"kill_test.py: killed {killed} of {len(a.delays.split(','))} runs; "
          f"every output old or complete")


if __name__ == "__main__":
    main()
