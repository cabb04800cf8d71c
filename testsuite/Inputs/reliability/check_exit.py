"""Runs a command and succeeds only if it exited with exactly the expected status.

  check_exit.py CODE [--empty DIR]... [--timeout S] -- COMMAND [ARG...]

lit's `not` accepts any non-zero status; the reliability corpus wants exactly 1 (an error
reported), never a signal (a crash) or a hang. The command's stdout and stderr pass through.
--empty DIR: DIR must be missing or empty afterwards (no partial output, no temporaries).
--timeout S (default 120) is multiplied by $TEXCC_TIMEOUT_SCALE when set: the sanitizer build
runs the tools several times slower (reliability/lit.local.cfg sets it there). The limit only
turns a hang into a failure: it is far above any command's time on a loaded 2-core machine
(the corpus' slowest default-limit test took 8 s beside `stress-ng --cpu 2`), so no verdict
depends on the machine's load.

A failure is also written to the test script's own stderr (the parent shell's): in
`%check-exit ... 2>&1 | FileCheck` this script's stderr is the pipe, and a FileCheck that
passes would swallow the only word of what went wrong (lit would show "Exit Code: 1" alone).
"""
import os
import subprocess
import sys


def fail(message):
    sys.stderr.write(message + "\n")
    sys.stderr.flush()
    try:
        with open(f"/proc/{os.getppid()}/fd/2", "w") as shell_err:
            mine, theirs = os.fstat(2), os.fstat(shell_err.fileno())
            if (mine.st_dev, mine.st_ino) != (theirs.st_dev, theirs.st_ino):
                shell_err.write(message + "\n")
    except OSError:
        pass
    sys.exit(1)


def main():
    args = sys.argv[1:]
    if "--" not in args:
        sys.exit("check_exit.py: usage: CODE [--empty DIR]... [--timeout S] -- COMMAND...")
    split = args.index("--")
    opts, command = args[:split], args[split + 1:]
    expected, empty_dirs, timeout = int(opts[0]), [], 120.0
    rest = opts[1:]
    while rest:
        flag, value, rest = rest[0], rest[1], rest[2:]
        if flag == "--empty":
            empty_dirs.append(value)
        elif flag == "--timeout":
            timeout = float(value)
        else:
            sys.exit(f"check_exit.py: unknown option {flag}")
    timeout *= float(os.environ.get("TEXCC_TIMEOUT_SCALE", "1"))
    try:
        status = subprocess.run(command, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        fail(f"check_exit.py: '{command[0]}' did not finish within {timeout:g} s (a hang)")
    if status < 0:
        fail(f"check_exit.py: '{command[0]}' was killed by signal {-status} (a crash)")
    if status != expected:
        fail(f"check_exit.py: '{command[0]}' exited with {status}, expected {expected}")
    for d in empty_dirs:
        left = sorted(os.listdir(d)) if os.path.isdir(d) else []
        if left:
            fail(f"check_exit.py: {d} is not empty: {', '.join(left)}")


if __name__ == "__main__":
    main()
