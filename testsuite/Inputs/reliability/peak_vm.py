"""Runs a command and prints its peak virtual memory (VmPeak of /proc/PID/status, in KiB, the
measure `ulimit -v` limits) on stdout; exits with the command's status. The command's own
output goes to stderr.

  peak_vm.py -- COMMAND [ARG...]

VmPeak is the process's high-water mark, so polling it finds a peak that lasted a moment, as
long as the process lives a little after it (the last value read before the process exits).
"""
import subprocess
import sys
import time


def vm_peak(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmPeak:"):
                    return int(line.split()[1])
    except (OSError, ValueError):
        pass
    return None


def main():
    args = sys.argv[1:]
    if not args or args[0] != "--" or len(args) < 2:
        sys.exit("peak_vm.py: usage: -- COMMAND [ARG...]")
    proc = subprocess.Popen(args[1:], stdout=sys.stderr)
    peak = 0
    while proc.poll() is None:
        v = vm_peak(proc.pid)
        if v:
            peak = max(peak, v)
        time.sleep(0.002)
    print(peak)
    sys.exit(proc.returncode)


if __name__ == "__main__":
    main()
