"""Drives a long-running command (texrender --watch) as a user at an editor would: waits for
lines it prints, saves files, snapshots its output, then stops it with a signal.

  drive.py STEP... -- COMMAND [ARG...]

Steps, run in order; each --wait reads the command's stderr, each --event its standard output
(both copied to stdout in the order they arrive) until a line matches:
  --wait REGEX        the next stderr line matching REGEX (Python re.search); 60 s at most
  --event REGEX       the next standard output line (a --control JSON event) matching REGEX
  --send LINE         writes LINE and a newline to the command's standard input
  --send-long N       writes a line of N bytes ('x') and a newline to its standard input
  --close             closes its standard input
  --sleep S           waits S seconds
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
import time
from waits import WAIT_S  # noqa: E402


def parse(args):
    steps, i = [], 0
    arity = {"--wait": 1, "--event": 1, "--save": 2, "--snap": 2, "--signal": 1,
             "--send": 1, "--send-long": 1, "--close": 0, "--sleep": 1}
    while args[i] != "--":
        n = arity[args[i]]
        steps.append((args[i], args[i + 1:i + 1 + n]))
        i += 1 + n
    return steps, args[i + 1:]


def main():
    steps, command = parse(sys.argv[1:])
    proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    lines = queue.Queue()  # (stream, line); line None: the stream ended

    def pump(stream, name):
        for line in stream:
            lines.put((name, line))
        lines.put((name, None))

    for stream, name in ((proc.stderr, "err"), (proc.stdout, "out")):
        threading.Thread(target=pump, args=(stream, name), daemon=True).start()
    ended = set()
    for kind, vals in steps:
        if kind in ("--wait", "--event"):
            pattern = re.compile(vals[0])
            want = "err" if kind == "--wait" else "out"
            while True:
                try:
                    name, line = lines.get(timeout=WAIT_S)
                except queue.Empty:
                    proc.kill()
                    sys.exit(f"drive.py: timed out waiting for /{vals[0]}/")
                if line is None:
                    ended.add(name)
                    if name == want:
                        print(f"exit {proc.wait()}")
                        sys.exit(f"drive.py: the command ended before /{vals[0]}/")
                    continue
                sys.stdout.write(line)
                if name == want and pattern.search(line):
                    break
        elif kind in ("--send", "--send-long"):
            text = vals[0] if kind == "--send" else "x" * int(vals[0])
            proc.stdin.write(text + "\n")
            proc.stdin.flush()
        elif kind == "--close":
            proc.stdin.close()
        elif kind == "--sleep":
            time.sleep(float(vals[0]))
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
    while len(ended) < 2:
        name, line = lines.get(timeout=WAIT_S)
        if line is None:
            ended.add(name)
        else:
            sys.stdout.write(line)
    print(f"exit {proc.wait(timeout=WAIT_S)}")


if __name__ == "__main__":
    main()
