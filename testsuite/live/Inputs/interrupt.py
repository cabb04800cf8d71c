"""Sends a signal to a command once it has printed its first progress line, as a user pressing
Ctrl-C during a long render would.

  interrupt.py [--signal INT|TERM] [--timeout S] -- COMMAND [ARG...]

The command's stderr is copied to stdout, then "exit N" (N: its exit status; a negative N is
the signal that killed it). Fails (exit 2) if no progress line came, or on a timeout.
"""
import signal
import subprocess
import sys


def main():
    args = sys.argv[1:]
    split = args.index("--")
    opts, command = args[:split], args[split + 1:]
    sig, timeout = signal.SIGINT, 120.0
    while opts:
        flag, value, opts = opts[0], opts[1], opts[2:]
        if flag == "--signal":
            sig = {"INT": signal.SIGINT, "TERM": signal.SIGTERM}[value]
        elif flag == "--timeout":
            timeout = float(value)
        else:
            sys.exit(f"interrupt.py: unknown option {flag}")
    proc = subprocess.Popen(command, stderr=subprocess.PIPE, text=True)
    sent = False
    for line in proc.stderr:
        sys.stdout.write(line)
        if not sent and "elapsed, ETA" in line:
            proc.send_signal(sig)
            sent = True
    try:
        code = proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        sys.exit("interrupt.py: the command did not end after the signal")
    print(f"exit {code}")
    sys.stdout.flush()
    if not sent:
        sys.exit("interrupt.py: no progress line: the signal was never sent")


if __name__ == "__main__":
    main()
