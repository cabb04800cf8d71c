"""farm.py: renders frames and tiles of a texrender scene on a Ray cluster (docs/farm.md).

  farm.py render scene.json --textures T [--frames 1-48] [--tiles 4x4] -o out/frame.####.exr
          [--address ADDR] [--workers N] [--task-threads N] [--sweep NODE.ARG=A:B:N]
          [texrender options ...]
  farm.py stitch --size WxH -o OUT.exr TILE.exr@X,Y ...

render: one Ray task per (frame, tile) runs `texrender --region X,Y,W,H --frame N` with the
texrender options given (--size, --spp, --seed, --max-depth, --set, ...), so that the stitched
frame equals `texrender` run alone with the same options, bit for bit. Each task is given its
share of its node's cores: it reserves --task-threads CPUs of the node (Ray's num_cpus) and runs
texrender --threads with as many, so the tasks a node runs at once never have more threads than
it has cores (tasks x threads <= CPUs). The scene.json, the OBJ
files it names, the texcc output folder and the images its layout binds travel to the workers
through Ray's object store (no shared file system). A task whose worker dies is retried; each
frame is written atomically once all its tiles are there. --sweep renders one frame per value
through texrender --edit-script (one kernel build per task, not per value).

Ray comes from PyPI (scripts/requirements-farm.txt) and is installed into the repository's
.venv/ on first use. Without --address a local Ray cluster is started (--workers CPUs).
"""
import argparse
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

from texcc_tools import exr
from texcc_tools import manifest
from texcc_tools.atomic import AtomicWriteError, write_bytes
from texcc_tools.paths import SCRIPTS, VENV_PYTHON, tool

REQUIREMENTS = os.path.join(SCRIPTS, "requirements-farm.txt")
# texrender options that farm.py sets per task (or that make no sense per tile).
OWN_OPTIONS = {"-o", "--output", "--region", "--frame", "--stats", "--variance", "--edit-script",
               "--interactive", "--textures", "--list-devices"}
# texrender options that take a value (the rest are flags), to split the pass-through list.
VALUE_OPTIONS = {"--spp", "--size", "--max-depth", "--ao-samples", "--ao-distance", "--seed",
                 "--set", "--tier", "--device", "--trace", "--ao-method", "--kernels",
                 "--cache-dir", "--time-limit", "--fps"}


class FarmError(Exception):
    pass


def first_line(error):
    text = str(error).strip()
    return text.splitlines()[0] if text else type(error).__name__


def fail(message):
    sys.stderr.write("farm.py: error: %s\n" % message)
    sys.exit(1)


# --- Ray, from .venv ---------------------------------------------------------------------------

def import_ray():
    """Ray, installed into .venv/ on first use (farm.py runs under .venv's Python)."""
    try:
        import ray  # noqa: F401
    except ImportError:
        sys.stderr.write("farm.py: installing Ray into .venv/ (%s)\n" % REQUIREMENTS)
        r = subprocess.run([VENV_PYTHON, "-m", "pip", "install", "-q", "-r", REQUIREMENTS])
        if r.returncode != 0:
            fail("cannot install Ray (pip install -r %s failed)" % REQUIREMENTS)
    import ray
    return ray


# --- the bundle: every file a task reads ------------------------------------------------------

def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def make_bundle(scene_path, textures_dir):
    """{relative path: bytes}: scene.json (its OBJ paths rewritten to meshes/K_NAME, no
    "textures" key), the texcc output folder under textures/ (layout.json's images rewritten to
    images/K_NAME), and those files. Paths are resolved as texrender resolves them."""
    files = {}
    scene_dir = os.path.dirname(os.path.abspath(scene_path))
    try:
        scene = json.loads(read_bytes(scene_path))
    except (OSError, ValueError) as e:
        raise FarmError("%s: %s" % (scene_path, e))
    scene.pop("textures", None)
    for k, mesh in enumerate(scene.get("meshes", [])):
        if isinstance(mesh, dict) and isinstance(mesh.get("obj"), str):
            src = os.path.join(scene_dir, mesh["obj"])
            name = "meshes/%d_%s" % (k, os.path.basename(src))
            files[name] = read_bytes(src)
            mesh["obj"] = name
    files["scene.json"] = json.dumps(scene, indent=1).encode()
    for entry in sorted(os.listdir(textures_dir)):
        path = os.path.join(textures_dir, entry)
        if os.path.isfile(path):
            files["textures/" + entry] = read_bytes(path)
    def ship(k, path):
        src = os.path.join(textures_dir, path)
        name = "../images/%d_%s" % (k, os.path.basename(src))
        files[name[3:]] = read_bytes(src)
        return name

    layout = manifest.loads(files["textures/layout.json"], manifest.path(textures_dir))
    files["textures/layout.json"] = manifest.dumps(manifest.with_image_paths(layout, ship))
    return files


def bundle_digest(files):
    h = hashlib.sha256()
    for name in sorted(files):
        h.update(name.encode() + b"\0" + hashlib.sha256(files[name]).digest())
    return h.hexdigest()[:16]


# --- one task ---------------------------------------------------------------------------------

def unpack_bundle(files, digest):
    """The bundle's folder on this node (written once per node and bundle, atomically)."""
    root = os.path.join(tempfile.gettempdir(), "texcc-farm-%d" % os.getuid(), digest)
    if os.path.isdir(root):
        return root
    os.makedirs(os.path.dirname(root), exist_ok=True)
    tmp = tempfile.mkdtemp(dir=os.path.dirname(root))
    for name, data in files.items():
        path = os.path.join(tmp, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    try:
        os.rename(tmp, root)
    except OSError:  # another worker of this node was first
        shutil.rmtree(tmp, ignore_errors=True)
    return root


def render_tile(texrender, files, digest, options, frame, region, sweep, crash_marker):
    """Renders one tile of one frame (one image per sweep value); returns the EXR bytes."""
    if crash_marker:
        # Test hook (FARM_TEST_CRASH_ONCE): the first task to get here kills its worker process.
        try:
            fd = os.open(crash_marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            os.close(fd)
            os._exit(1)
        except FileExistsError:
            pass
    root = unpack_bundle(files, digest)
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "tile.exr")
        cmd = [texrender, os.path.join(root, "scene.json"), "--textures",
               os.path.join(root, "textures"), "--quiet", "--frame", str(frame),
               "--region", "%d,%d,%d,%d" % region, "-o", out] + options
        outs = [out]
        if sweep:
            node_arg, values = sweep
            cmd += ["--set", "%s=%s" % (node_arg, values[0])]
            script = os.path.join(work, "sweep.txt")
            with open(script, "w") as f:
                f.writelines("set %s=%s\n" % (node_arg, v) for v in values[1:])
            cmd += ["--edit-script", script]
            outs = [os.path.join(work, "tile.frame%d.exr" % k) for k in range(len(values))]
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            lines = r.stderr.strip().splitlines()
            raise FarmError(lines[0] if lines else "texrender exited with %d" % r.returncode)
        return [read_bytes(p) for p in outs]


# --- options ----------------------------------------------------------------------------------

# Bounds checked before anything is allocated or started: texrender's --frame is a 32-bit int,
# and every (frame, tile) task is submitted at once (a longer run is split into several).
MAX_FRAME = 2 ** 31 - 1
MAX_TASKS = 1000000
MAX_SWEEP = 10000
MAX_RETRIES = 100
MAX_TASK_THREADS = 1024  # texrender --threads' bound
FRAME_PART = re.compile(r"(\d+)(?:-(\d+))?$")


def parse_frames(text):
    """N, A-B or a comma list of them, each frame once, in the order given; the count is
    checked before the list is built."""
    ranges, count = [], 0
    for part in text.split(","):
        m = FRAME_PART.match(part)
        if not m:
            raise FarmError("--frames: expected N, A-B or a comma list of them, got '%s'" % text)
        lo, hi = int(m.group(1)), int(m.group(2) or m.group(1))
        if hi < lo:
            raise FarmError("--frames %s: %d-%d is empty" % (text, lo, hi))
        if hi > MAX_FRAME:
            raise FarmError("--frames %s: frame %d is past texrender's last frame %d"
                            % (text, hi, MAX_FRAME))
        count += hi - lo + 1
        if count > MAX_TASKS:
            raise FarmError("--frames %s: more than %d frames in one run; split it into several "
                            "runs" % (text, MAX_TASKS))
        ranges.append((lo, hi))
    seen = sorted(ranges)
    for (a_lo, a_hi), (b_lo, b_hi) in zip(seen, seen[1:]):
        if b_lo <= a_hi:
            raise FarmError("--frames %s: frame %d is listed twice; list each frame once"
                            % (text, b_lo))
    return [f for lo, hi in ranges for f in range(lo, hi + 1)]


def parse_pair(option, text, sep):
    try:
        a, b = (int(v) for v in text.split(sep))
    except ValueError:
        raise FarmError("%s: expected A%sB, got '%s'" % (option, sep, text))
    if a < 1 or b < 1:
        raise FarmError("%s %s: both must be at least 1" % (option, text))
    return a, b


def parse_sweep(text):
    """NODE.ARG=A:B:N -> (NODE.ARG, N values from A to B, evenly spaced, as --set text)."""
    node_arg, _, spec = text.partition("=")
    parts = spec.split(":")
    try:
        a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
        if len(parts) != 3 or n < 1 or "." not in node_arg:
            raise ValueError
    except (ValueError, IndexError):
        raise FarmError("--sweep: expected NODE.ARG=A:B:N, got '%s'" % text)
    if not (math.isfinite(a) and math.isfinite(b)) or max(abs(a), abs(b)) > 3.4e38:
        raise FarmError("--sweep %s: A and B must be finite 32-bit floats" % text)
    if n > MAX_SWEEP:
        raise FarmError("--sweep %s: at most %d values" % (text, MAX_SWEEP))
    values = [a + (b - a) * k / (n - 1) if n > 1 else a for k in range(n)]
    # Integer ends and steps stay integers (an int parameter refuses "2.0").
    if all(v == int(v) for v in values) and "." not in parts[0] + parts[1]:
        return node_arg, [str(int(v)) for v in values]
    return node_arg, [repr(v) for v in values]


def tiles_of(width, height, nx, ny):
    """(x, y, w, h) of an nx x ny grid over the film; edge tiles take the remainder."""
    if nx > width or ny > height or nx * ny > MAX_TASKS:
        raise FarmError("--tiles %dx%d: more tiles than pixels (%dx%d)" % (nx, ny, width, height))
    xs = [width * i // nx for i in range(nx + 1)]
    ys = [height * j // ny for j in range(ny + 1)]
    return [(xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j])
            for j in range(ny) for i in range(nx)]


def film_size(scene, options):
    """The film's size as texrender will use it (--size, else the scene's film); a value
    texrender refuses is refused by the validation run, this only has to not crash."""
    size = None
    for k, opt in enumerate(options):
        if opt == "--size" and k + 1 < len(options):
            size = options[k + 1]
        elif opt.startswith("--size="):
            size = opt.split("=", 1)[1]
    if size:
        return parse_pair("--size", size, "x")
    film = scene.get("film", {})
    width, height = (film.get("width", 256), film.get("height", 256)) \
        if isinstance(film, dict) else (256, 256)
    if not all(isinstance(v, int) and v >= 1 for v in (width, height)):
        return 256, 256  # texrender's validation run names the problem
    return width, height


def check_passthrough(options):
    k = 0
    while k < len(options):
        name = options[k].split("=", 1)[0]
        if name == "--threads":
            raise FarmError("--threads: not passed to the tasks (farm.py gives each task its "
                            "share of its node's cores; --task-threads N sets the share)")
        if name in OWN_OPTIONS:
            raise FarmError("%s: not passed to the tasks (farm.py sets -o, --region, --frame and "
                            "--textures itself; --stats, --variance, --edit-script, "
                            "--interactive and --list-devices do not apply to tiles)" % name)
        if not name.startswith("-"):
            raise FarmError("unexpected argument '%s'" % options[k])
        k += 2 if name in VALUE_OPTIONS and "=" not in options[k] else 1


def output_name(pattern, frame, sweep_index):
    if "#" not in pattern:
        raise FarmError("-o %s: the name needs #### for the frame number" % pattern)
    if not pattern.lower().endswith(".exr"):
        raise FarmError("-o %s: frames are written as .exr (linear float)" % pattern)
    start = pattern.index("#")
    end = start
    while end < len(pattern) and pattern[end] == "#":
        end += 1
    name = pattern[:start] + "%0*d" % (end - start, frame) + pattern[end:]
    if sweep_index is not None:
        stem, ext = os.path.splitext(name)
        name = "%s.v%d%s" % (stem, sweep_index, ext)
    return name


def find_texrender(given):
    path = given or shutil.which("texrender") or tool("texrender")
    if not os.access(path, os.X_OK):
        raise FarmError("cannot find texrender (give --texrender PATH)")
    return os.path.abspath(path)


def validate(texrender, scene, textures, options, frame):
    """A bad scene, texture folder or option fails here, once, before any task: texrender on
    the first frame's top-left pixel at 1 spp with every other option as given."""
    opts = []
    k = 0
    while k < len(options):  # keep the options, but 1 spp
        if options[k] == "--spp":
            k += 2
            continue
        if not options[k].startswith("--spp="):
            opts.append(options[k])
        k += 1
    with tempfile.TemporaryDirectory() as work:
        r = subprocess.run([texrender, scene, "--textures", textures, "--quiet", "--spp", "1",
                            "--frame", str(frame), "--region", "0,0,1,1",
                            "-o", os.path.join(work, "check.exr")] + opts,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        lines = r.stderr.strip().splitlines()
        raise FarmError(lines[0] if lines else "texrender exited with %d" % r.returncode)


# --- render -----------------------------------------------------------------------------------

class Progress:
    """One status line on stderr: redrawn in place on a terminal (twice a second), else a new
    line every 10 seconds and at the end (logs stay readable)."""

    def __init__(self, frames, tasks):
        self.frames, self.tasks, self.start = frames, tasks, time.time()
        self.last = self.start
        self.tty = sys.stderr.isatty()

    def show(self, frames_done, tasks_done, in_flight, final=False):
        now = time.time()
        if not final and now - self.last < (0.5 if self.tty else 10.0):
            return
        self.last = now
        eta = "?"
        if tasks_done:
            eta = "%.0f s" % ((now - self.start) / tasks_done * (self.tasks - tasks_done))
        line = ("farm.py: frames %d/%d done, tiles %d/%d done, %d in flight, ETA %s"
                % (frames_done, self.frames, tasks_done, self.tasks, in_flight, eta))
        if self.tty:
            sys.stderr.write("\r" + line + "   " + ("\n" if final else ""))
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()


def check_cluster_options(args):
    """--workers, --retries and --address, before Ray starts: Ray's own checks are a
    traceback (--workers -3) or none at all (--workers 0 schedules nothing and waits forever)."""
    if args.address is not None and args.workers is not None:
        raise FarmError("--workers: applies to the local cluster farm.py starts; with --address "
                        "each node's `ray start --num-cpus` sets its CPUs")
    if args.workers is not None and not 1 <= args.workers <= 4096:
        raise FarmError("--workers %d: expected 1 to 4096 CPUs" % args.workers)
    if not 0 <= args.retries <= MAX_RETRIES:
        raise FarmError("--retries %d: expected 0 to %d" % (args.retries, MAX_RETRIES))
    if args.task_threads is not None:
        text = args.task_threads
        if not re.fullmatch(r"[0-9]+", text) or not 1 <= int(text) <= MAX_TASK_THREADS:
            raise FarmError("--task-threads: expected an integer from 1 to %d, got '%s'"
                            % (MAX_TASK_THREADS, text))
        args.task_threads = int(text)
        cpus = args.workers or os.cpu_count()
        if args.address is None and args.task_threads > cpus:
            raise FarmError("--task-threads %d: more than the local cluster's %d CPUs%s: no task "
                            "could start" % (args.task_threads, cpus,
                                             " (--workers)" if args.workers else ""))


def task_share(ray, args, tasks):
    """Threads (and reserved CPUs) per task: --task-threads, else the smallest live node's CPUs
    divided by the tasks each node gets when they are spread evenly (at least 1): one task
    alone on a node uses all its cores, as many tasks as cores use one each."""
    cpus = [int(n.get("Resources", {}).get("CPU", 0)) for n in ray.nodes() if n.get("Alive")]
    cpus = [c for c in cpus if c > 0]
    if not cpus:
        raise FarmError("the Ray cluster has no node with a CPU")
    if args.task_threads is not None:
        if args.task_threads > max(cpus):
            raise FarmError("--task-threads %d: no node of the cluster has that many CPUs (the "
                            "largest has %d): no task could start" % (args.task_threads,
                                                                      max(cpus)))
        return args.task_threads
    smallest = min(cpus)
    per_node = min(smallest, -(-tasks // len(cpus)))
    return max(1, smallest // per_node)


def read_scene(path):
    try:
        scene = json.loads(read_bytes(path))
    except ValueError as e:
        raise FarmError("%s: not JSON: %s" % (path, e))
    if not isinstance(scene, dict):
        raise FarmError("%s: expected a JSON object (docs/scene.md)" % path)
    return scene


def render(args, options):
    check_cluster_options(args)
    check_passthrough(options)
    frames = parse_frames(args.frames)
    sweep = parse_sweep(args.sweep) if args.sweep else None
    nx, ny = parse_pair("--tiles", args.tiles, "x")
    if len(frames) * nx * ny > MAX_TASKS:
        raise FarmError("--frames %s --tiles %s: %d tasks, more than %d in one run; split it "
                        "into several runs" % (args.frames, args.tiles, len(frames) * nx * ny,
                                               MAX_TASKS))
    scene = read_scene(args.scene)
    width, height = film_size(scene, options)
    tiles = tiles_of(width, height, nx, ny)
    texrender = find_texrender(args.texrender)
    textures = args.textures or os.path.join(
        os.path.dirname(os.path.abspath(args.scene)), str(scene.get("textures", "")))
    if not manifest.exists(textures):
        raise FarmError("%s: not a texcc output folder (no layout.json)" % textures)
    for out_dir in sorted({os.path.dirname(os.path.abspath(output_name(args.output, f, None)))
                           for f in frames}):
        if not os.path.isdir(out_dir):
            raise FarmError("-o %s: '%s' is not a folder" % (args.output, out_dir))
        if not os.access(out_dir, os.W_OK | os.X_OK):
            raise FarmError("-o %s: cannot write into '%s'" % (args.output, out_dir))
    validate(texrender, args.scene, textures, options, frames[0])
    files = make_bundle(args.scene, textures)
    digest = bundle_digest(files)

    if args.address:
        # `ray start --head` turns token authentication on (Ray 2.60); a driver joining it must
        # ask for token mode itself, before Ray is imported, when it has the token
        # (~/.ray/auth_token, RAY_AUTH_TOKEN_PATH or RAY_AUTH_TOKEN).
        token_file = os.environ.get("RAY_AUTH_TOKEN_PATH",
                                    os.path.join(os.path.expanduser("~"), ".ray", "auth_token"))
        if "RAY_AUTH_MODE" not in os.environ and (os.environ.get("RAY_AUTH_TOKEN")
                                                  or os.path.exists(token_file)):
            os.environ["RAY_AUTH_MODE"] = "token"
    # farm.py reports the first failed task itself; the tasks failing beside it would each print
    # a traceback at exit ("Unhandled error").
    os.environ.setdefault("RAY_IGNORE_UNHANDLED_ERRORS", "1")
    ray = import_ray()
    try:
        if args.address:
            ray.init(address=args.address, logging_level="ERROR", log_to_driver=False)
        else:
            ray.init(num_cpus=args.workers or os.cpu_count(), logging_level="ERROR",
                     log_to_driver=False, include_dashboard=False)
    except Exception as e:  # Ray's own errors (a wrong --address, a node that cannot start)
        raise FarmError("Ray did not start%s: %s" % (
            " at --address " + args.address if args.address else "", first_line(e)))
    share = task_share(ray, args, len(frames) * len(tiles))
    # The tasks travel by value: a worker of another cluster (--address) need not have the
    # package installed.
    from ray import cloudpickle
    for module in (sys.modules[__name__], exr, sys.modules[write_bytes.__module__]):
        cloudpickle.register_pickle_by_value(module)
    task = ray.remote(num_cpus=share, max_retries=args.retries)(render_tile)
    options = options + ["--threads", str(share)]
    files_ref = ray.put(files)
    crash = os.environ.get("FARM_TEST_CRASH_ONCE", "")
    pending = {}
    for f in frames:
        for t in tiles:
            ref = task.remote(texrender, files_ref, digest, options, f, t, sweep, crash)
            pending[ref] = (f, t)
    got = {f: {} for f in frames}
    progress = Progress(len(frames), len(pending))
    done_frames = tasks_done = 0
    refs = list(pending)
    while refs:
        ready, refs = ray.wait(refs, num_returns=1, timeout=0.5)
        for ref in ready:
            f, t = pending[ref]
            try:
                images = ray.get(ref)
            except ray.exceptions.RayTaskError as e:  # texrender failed in the task
                cause = e.cause if getattr(e, "cause", None) else e
                raise FarmError("frame %d, tile %s: %s" % (f, "%d,%d,%d,%d" % t, cause))
            except ray.exceptions.RayError as e:  # a worker or node lost more times than retried
                raise FarmError("frame %d, tile %s: %s (after %d retries)"
                                % (f, "%d,%d,%d,%d" % t, first_line(e), args.retries))
            got[f][t] = images
            tasks_done += 1
            if len(got[f]) == len(tiles):
                write_frame(args.output, f, width, height, got.pop(f), sweep)
                done_frames += 1
        progress.show(done_frames, tasks_done, len(refs))
    progress.show(done_frames, tasks_done, 0, final=True)
    ray.shutdown()


def write_frame(pattern, frame, width, height, tiles, sweep):
    import numpy as np
    for k in range(len(sweep[1]) if sweep else 1):
        image = np.zeros((height, width, 3), dtype=np.float32)
        for (x, y, w, h), images in tiles.items():
            image[y:y + h, x:x + w] = exr.read_exr(images[k])
        write_bytes(output_name(pattern, frame, k if sweep else None), exr.write_exr(image))


# --- stitch -----------------------------------------------------------------------------------

def stitch(args):
    """Places tiles (TILE.exr@X,Y) into a WxH image: for texrender --region outputs."""
    import numpy as np
    width, height = parse_pair("--size", args.size, "x")
    image = np.zeros((height, width, 3), dtype=np.float32)
    for spec in args.tiles:
        path, _, at = spec.rpartition("@")
        try:
            x, y = (int(v) for v in at.split(","))
            if not path or x < 0 or y < 0:
                raise ValueError
        except ValueError:
            raise FarmError("expected TILE.exr@X,Y with X, Y at least 0, got '%s'" % spec)
        tile = exr.read_exr(read_bytes(path))
        h, w, _ = tile.shape
        if x + w > width or y + h > height:
            raise FarmError("%s: a %dx%d tile at %d,%d is outside %dx%d" % (path, w, h, x, y,
                                                                           width, height))
        image[y:y + h, x:x + w] = tile
    write_bytes(args.output, exr.write_exr(image))


def main(argv):
    p = argparse.ArgumentParser(prog="farm.py", description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("render", help="render frames and tiles on a Ray cluster",
                       epilog="Every other option (--size, --spp, --seed, --max-depth, --set, "
                              "--fps, ...) is passed to each texrender task (docs/farm.md).")
    r.add_argument("scene")
    r.add_argument("--textures", help="texcc output folder (default: scene.json \"textures\")")
    r.add_argument("--frames", default="0", help="frames: N, A-B or a comma list (default 0)")
    r.add_argument("--tiles", default="1x1", help="tiles per frame, NXxNY (default 1x1)")
    r.add_argument("-o", "--output", required=True, help="frame file name with #### (EXR)")
    r.add_argument("--address", help="an existing Ray cluster (default: start a local one)")
    r.add_argument("--workers", type=int,
                   help="CPUs of the local cluster, 1 to 4096 (default: all)")
    r.add_argument("--task-threads", metavar="N",
                   help="threads of each texrender task, and CPUs it reserves on its node, 1 to "
                        "%d (default: a node's CPUs divided by the tasks it gets)"
                        % MAX_TASK_THREADS)
    r.add_argument("--retries", type=int, default=3, help="retries of a task whose worker dies, 0 to %d (default 3)" % MAX_RETRIES)
    r.add_argument("--sweep", help="NODE.ARG=A:B:N: one image per value (live edits)")
    r.add_argument("--texrender", help="texrender on every node (default: PATH, then build/bin)")
    s = sub.add_parser("stitch", help="place texrender --region tiles into one EXR")
    s.add_argument("--size", required=True)
    s.add_argument("-o", "--output", required=True)
    s.add_argument("tiles", nargs="+", metavar="TILE.exr@X,Y")
    args, rest = p.parse_known_args(argv)
    try:
        if args.command == "stitch":
            if rest:
                raise FarmError("unexpected arguments: %s" % " ".join(rest))
            stitch(args)
        else:
            render(args, rest)
    except (FarmError, exr.ExrError, manifest.ManifestError, AtomicWriteError) as e:
        fail(str(e))
    except OSError as e:
        fail("%s: %s" % (e.filename, e.strerror) if e.filename and e.strerror else str(e))
    except KeyboardInterrupt:
        fail("interrupted (frames written so far are complete; no partial file is left)")
    except MemoryError:
        fail("out of memory")
    except Exception as e:  # a bug of farm.py: still one line, never a traceback
        fail("internal error: %s: %s" % (type(e).__name__, first_line(e)))
    return 0

