"""Atomic writes: every output file of the Python tools (farm.py, blender_export.py) is
written here: into a hidden temporary in the destination's own folder, every write, the flush,
the fsync and the close checked, then renamed over the destination. A reader never sees a torn
file, and a failure (a full disk, a file size limit, a folder that vanished) is one
AtomicWriteError naming the destination and the cause, with the temporary removed.

The file gets the mode a plain open() would give a new file, 0666 less the umask (0644 under
the usual umask 022), as texcc and texrender write theirs; a temporary alone would be 0600.

Import it as texcc_tools.atomic.
"""

import contextlib
import os
import tempfile

__all__ = ["AtomicWriteError", "atomic_open", "write_bytes", "write_text", "new_file_mode",
           "new_dir_mode", "make_dir"]


class AtomicWriteError(Exception):
    """'PATH: cannot write: CAUSE' (one line); `path` and `cause` are kept for callers."""

    def __init__(self, path, cause):
        self.path, self.cause = path, cause
        super().__init__("%s: cannot write: %s" % (path, cause))


def _cause(error):
    if isinstance(error, OSError) and error.strerror:
        return error.strerror
    return str(error) or type(error).__name__


_UMASK = None


def _umask():
    """The process's umask (read once; os.umask can only be read by setting it)."""
    global _UMASK
    if _UMASK is None:
        _UMASK = os.umask(0o022)
        os.umask(_UMASK)
    return _UMASK


def new_file_mode():
    """0666 less the umask: what open() gives a new file."""
    return 0o666 & ~_umask()


def new_dir_mode():
    """0777 less the umask: what mkdir gives a new folder (mkdtemp's is 0700)."""
    return 0o777 & ~_umask()


def make_dir(path, label=None):
    """os.makedirs, its failure an AtomicWriteError; the folder gets 0777 less the umask."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        raise AtomicWriteError(label or path, _cause(e)) from None


@contextlib.contextmanager
def atomic_open(path, mode="wb", label=None, encoding="utf-8"):
    """Yields a file object writing a temporary next to `path`; on a normal exit the data is
    flushed, synced and closed (each checked) and the temporary renamed to `path`. Any failure,
    in the block or after it, removes the temporary and raises AtomicWriteError naming `label`
    (default: `path`). An exception of the block's own that is not an OSError passes through
    unchanged (the temporary still removed)."""
    if mode not in ("wb", "w"):
        raise ValueError("atomic_open: mode must be 'wb' or 'w'")
    name = label or path
    folder = os.path.dirname(os.path.abspath(path))
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".",
                                   suffix=".tmp")
    except OSError as e:
        raise AtomicWriteError(name, _cause(e)) from None
    f = None
    try:
        try:
            os.fchmod(fd, new_file_mode())
            f = os.fdopen(fd, mode, **({"encoding": encoding} if mode == "w" else {}))
        except BaseException:
            if f is None:
                os.close(fd)
            raise
        yield f
        f.flush()
        os.fsync(f.fileno())
        f.close()
        os.replace(tmp, path)
        tmp = None
    except OSError as e:
        raise AtomicWriteError(name, _cause(e)) from None
    finally:
        if f is not None and not f.closed:
            try:
                f.close()
            except OSError:  # the buffered data failed to write: the error is being reported
                pass
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def write_bytes(path, data, label=None):
    with atomic_open(path, "wb", label) as f:
        f.write(data)


def write_text(path, text, label=None):
    with atomic_open(path, "w", label) as f:
        f.write(text)
