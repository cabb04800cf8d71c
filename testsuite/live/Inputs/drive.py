"""Drives a long-running command (texrender --watch) as a user at an editor would: waits for
lines it prints, saves files, snapshots its output, then stops it with a signal.

  drive.py STEP... -- COMMAND [ARG...]

Steps, run in order; each --wait reads the command's stderr (copied to stdout) until a line
matches:
  --wait REGEX        the next line matching REGEX (Python re.search); 60 s at most
  --save SRC DST      copies SRC over DST's contents (in place, as an editor saving)
  --snap SRC DST      copies SRC (the image being rendered) to DST
  --signal INT|TERM   sends the signal, then copies the rest of its output
Finally prints "exit N" (N: the command's exit status). Fails (exit 2) when a wait times out
or the command ends first.
"""
import queue
import re
import shutil
import signal
import subprocess
import sys
import threading


def parse(args):
    steps, i = [], 0
    arity = {"--wait": 1, "--save": 2, "--snap": 2, "--signal": 1}
    while args[i] != "--":
        n = arity[args[i]]
        steps.append((args[i], args[i + 1:i + 1 + n]))
        i += 1 + n
    return steps, args[i + 1:]


def main():
    steps, command = parse(sys.argv[1:])
    proc = subprocess.Popen(command, stderr=subprocess.PIPE, text=True)
    lines = queue.Queue()

    def pump():
        for line in proc.stderr:
            lines.put(line)
        lines.put(None)

    threading.Thread(target=pump, daemon=True).start()
    for kind, vals in steps:
        if kind == "--wait":
            pattern = re.compile(vals[0])
            while True:
                try:
                    line = lines.get(timeout=60)
                except queue.Empty:
                    proc.kill()
                    sys.exit(f"drive.py: timed out waiting for /{vals[0]}/")
                if line is None:
                    print(f"exit {proc.wait()}")
                    sys.exit(f"drive.py: the command ended before /{vals[0]}/")
                sys.stdout.write(line)
                if pattern.search(line):
                    break
        elif kind == "--save":
            with open(vals[0], "rb") as src, open(vals[1], "r+b") as dst:
                data = src.read()
                dst.seek(0)
                dst.write(data)
                dst.truncate()
        elif kind == "--snap":
            shutil.copyfile(vals[0], vals[1])
        elif kind == "--signal":
            proc.send_signal({"INT": signal.SIGINT, "TERM": signal.SIGTERM}[vals[0]])
    while True:
        line = lines.get(timeout=120)
        if line is None:
            break
        sys.stdout.write(line)
    print(f"exit {proc.wait(timeout=60)}")


if __name__ == "__main__":
    main()
