"""Subprocess runs whose failure is one clear error: the command, how it ended (exit status,
signal, time limit, not found) and the end of its stderr."""
import shlex
import signal
import subprocess
import time


class RunError(Exception):
    """A command that failed; `cmd`, `returncode` (None: did not start or timed out) and
    `stderr` are kept for callers."""

    def __init__(self, message, cmd, returncode=None, stderr=""):
        super().__init__(message)
        self.cmd, self.returncode, self.stderr = cmd, returncode, stderr


def command_line(cmd):
    return " ".join(shlex.quote(str(c)) for c in cmd)


def _how(returncode):
    if returncode < 0:
        try:
            return "killed by %s" % signal.Signals(-returncode).name
        except ValueError:
            return "killed by signal %d" % -returncode
    return "exit %d" % returncode


def run(cmd, timeout=None, cwd=None, env=None, input=None, capture=True, tail=2000):
    """Runs cmd (a list); returns the CompletedProcess (stdout and stderr as text when
    capture). Raises RunError when the command cannot start, runs past `timeout` seconds or
    exits non-zero: "failed (exit N): CMD" and the last `tail` characters of its stderr."""
    pipe = subprocess.PIPE if capture else None
    try:
        r = subprocess.run([str(c) for c in cmd], stdout=pipe, stderr=pipe, text=True,
                           timeout=timeout, cwd=cwd, env=env, input=input)
    except subprocess.TimeoutExpired:
        raise RunError("timed out after %ss: %s" % (timeout, command_line(cmd)), cmd) from None
    except OSError as e:
        raise RunError("cannot run %s: %s" % (command_line(cmd), e.strerror or e), cmd) from None
    if r.returncode != 0:
        err = (r.stderr or "").strip()[-tail:] if capture else ""
        raise RunError("failed (%s): %s%s" % (_how(r.returncode), command_line(cmd),
                                              "\n" + err if err else ""),
                       cmd, r.returncode, r.stderr or "")
    return r


def timed(cmd, **kwargs):
    """run(cmd, **kwargs) and its wall seconds: (seconds, CompletedProcess)."""
    start = time.perf_counter()
    r = run(cmd, **kwargs)
    return time.perf_counter() - start, r
