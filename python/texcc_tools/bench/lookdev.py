"""Figure: live look-development on the atrium with rust at a 256x256 preview (issue 23).

A scripted session plays a user at the browser preview: 50 slider moves (five float arguments of
the rust graph, ten values each) and 5 rewirings (mask.noise onto another float node), one at a
time. Five times: ten slider moves as a drag (each sent THINK seconds after the previous one's
first frame arrived), the last of them followed until its first full-resolution frame, then,
THINK seconds later (the renderer is refining at full resolution by then), a rewiring, also
followed to its first full-resolution frame. Measured per edit at the client: the time from
sending the message to receiving the first frame that contains the edit ("first frame"; with
texrender's default --first-pass=reduced that frame has 1/4 to 1/256 of the pixels, by texrender's time budget) and, where
followed, to the first frame at full resolution. Kernel builds: texrender's count (foreground and background) before the first edit
and after the last; they must not change. The session runs once per first-pass configuration
(reduced, full), interleaved.

Transport: through the WebSocket of the browser preview (texrender --serve, scripts/serve.py;
the page's own messages) when aiohttp is importable, else through `texrender --watch --control`
directly; the result says which.

A source edit: in a copy of rust.cl a constant of the code (a random one: no cache has the new
kernel) is changed and saved SETTLE seconds after the quick tier's warm-up (shape mode,
--tier=auto; texrender --watch builds the programs of the quick tier, one per texture function,
in the background after the first complete frame). Measured from the save: the first frame
rendered with the new code (texcc in the background, then the foreground build of the changed
function's quick program only; tier quick), the first full-resolution frame with it, and the
first frame of the shape tier (the shape kernel is built behind the quick tier once its first
full-resolution pass is done and takes over when ready; its interp fallback follows once a frame
is complete); texrender's own
split of that first frame ("source change" line: texcc, the compiler priming waited for, the
adoption and its program builds, the pass) and its own time from the change to the takeover
("the background build is done: ... N ms after the change that needed it").

Issue 36 (--save-to-image): save -> first image with the new code in the default configuration
(texcc without --mode, texrender --watch without options) and in each mode, from a cold session
(empty program caches) and a warm one, interleaved; bench/results/lookdev-save.json.

usage: bench/lookdev.py [--quick] [--transport ws|control] [--build DIR] [--out FILE]
       bench/lookdev.py --save-to-image [--modes default,shape] [--saves 4] [--reps 2]
"""
import argparse
import asyncio
import json
import os
import queue
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from texcc_tools.bench import common

SCENE = os.path.join(common.ROOT, "examples", "atrium", "scene.json")
RUST = os.path.join(common.ROOT, "examples", "rust")
SIZE = "256x256"
SPP = 16
THINK = 0.1
SLIDERS = [("patches", "scale", [2.0, 2.2, 2.4, 2.6, 2.8, 3.0, 2.7, 2.5, 2.3, 2.1]),
           ("grain", "scale", [10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0, 17.0, 18.0, 14.0]),
           ("tone", "t", [0.30, 0.35, 0.40, 0.45, 0.50, 0.55, 0.60, 0.50, 0.45, 0.40]),
           ("mask", "threshold", [0.30, 0.32, 0.34, 0.36, 0.38, 0.40, 0.42, 0.40, 0.38, 0.36]),
           ("mask", "softness", [0.04, 0.06, 0.08, 0.10, 0.12, 0.10, 0.08, 0.06, 0.05, 0.08])]
REWIRES = [("mask", "noise", s) for s in ("tone", "grain", "patches", "tone", "patches01")]
TIMEOUT = 120
# The source edit is saved this long after the shape tier's complete frame (a user reads the
# image first; texrender primes the OpenCL compiler after that frame).
SETTLE = 2.0


def script():
    """The 55 edits: ten slider moves (two per slider, round robin), then a rewiring; five
    times. Each: (kind, node, arg, value or source)."""
    moves = [("set", n, a, vals[i]) for i in range(10) for n, a, vals in SLIDERS]
    out = []
    for k in range(5):
        out += moves[10 * k:10 * k + 10]
        out.append(("rewire",) + REWIRES[k])
    return out


def prepare(tools, work):
    """A copy of the rust example (rust.cl copied, so that the source edit changes the copy
    only; the shared textures by absolute path) and its interp and shape folders."""
    folder = os.path.join(work, "rust")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(RUST, "graph.json")) as f:
        graph = json.load(f)
    graph["sources"] = [s if s == "rust.cl" else os.path.normpath(os.path.join(RUST, s))
                        for s in graph["sources"]]
    shutil.copy(os.path.join(RUST, "rust.cl"), os.path.join(folder, "rust.cl"))
    path = os.path.join(folder, "graph.json")
    with open(path, "w") as f:
        json.dump(graph, f, indent=1)
    out = {}
    for mode in ("interp", "shape"):
        out[mode] = os.path.join(work, "tex-" + mode)
        common.texcc(tools, path, out[mode], mode)
    return folder, out


class Control:
    """texrender --watch --control: edit lines on its stdin, events from its stdout."""
    name = "control"

    def __init__(self, tools, textures, extra, work):
        self.events = queue.Queue()
        self.log_name = os.path.join(work, "texrender-%d.log" % time.monotonic_ns())
        self.log = open(self.log_name, "w")
        cmd = [tools.texrender, SCENE, "--textures", textures, "--size", SIZE, "--spp", str(SPP),
               "--device", tools.device, "--cache-dir", tools.cache, "--watch", "--control",
               "-o", os.path.join(work, "frame.png")] + extra
        self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=self.log, text=True, bufsize=1)
        threading.Thread(target=self.pump, daemon=True).start()

    def pump(self):
        for line in self.proc.stdout:
            e = json.loads(line)
            e["t"] = time.perf_counter()
            self.events.put(e)
        self.events.put(None)

    def send(self, eid, kind, node, arg, value):
        text = "%s %s.%s=%s" % (kind, node, arg, value if kind == "rewire" else json.dumps(value))
        self.proc.stdin.write("%d %s\n" % (eid, text))
        self.proc.stdin.flush()

    def close(self):
        try:
            self.proc.stdin.write("quit\n")
            self.proc.stdin.close()
        except OSError:
            pass
        self.proc.wait(timeout=60)
        self.log.close()


class WebSocket:
    """The browser preview: texrender --serve (scripts/serve.py), driven over /ws as the page
    drives it. Events are the page's messages, named as texrender's (hello -> ready)."""
    name = "ws"

    def __init__(self, tools, textures, extra, work):
        self.events = queue.Queue()
        self.log_path = os.path.join(work, "serve-%d.log" % time.monotonic_ns())
        self.log = open(self.log_path, "w")
        cmd = [tools.texrender, "--serve=0", SCENE, "--textures", textures, "--size", SIZE,
               "--spp", str(SPP), "--device", tools.device, "--cache-dir", tools.cache] + extra
        self.proc = subprocess.Popen(cmd, stdout=self.log, stderr=subprocess.PIPE, text=True,
                                     start_new_session=True)
        self.port = None
        for line in self.proc.stderr:
            self.log.write(line)
            m = re.search(r"preview at http://[^:]+:(\d+)/", line)
            if m:
                self.port = int(m.group(1))
                break
        if self.port is None:
            raise common.BenchError("texrender --serve did not start (see %s)" % self.log_path)
        threading.Thread(target=self.copy_log, daemon=True).start()
        self.loop = asyncio.new_event_loop()
        self.ready = threading.Event()
        threading.Thread(target=self.loop.run_until_complete, args=(self.run(),),
                         daemon=True).start()
        if not self.ready.wait(TIMEOUT):
            raise common.BenchError("could not open the preview's WebSocket")

    def copy_log(self):
        for line in self.proc.stderr:
            self.log.write(line)
            self.log.flush()  # wait_log reads the file while the session runs

    async def run(self):
        import aiohttp
        url = "http://127.0.0.1:%d" % self.port
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(url + "/ws", headers={"Origin": url},
                                          max_msg_size=0) as ws:
                self.ws = ws
                self.ready.set()
                async for msg in ws:
                    if msg.type != aiohttp.WSMsgType.TEXT:
                        continue  # the PNG after a frame message
                    e = json.loads(msg.data)
                    e["t"] = time.perf_counter()
                    e["event"] = {"hello": "ready"}.get(e.get("type"), e.get("type"))
                    self.events.put(e)
        self.events.put(None)

    def send(self, eid, kind, node, arg, value):
        msg = {"type": kind, "id": eid, "node": node, "arg": arg}
        msg["source" if kind == "rewire" else "value"] = value
        asyncio.run_coroutine_threadsafe(self.ws.send_str(json.dumps(msg)), self.loop).result()

    def close(self):
        os.killpg(self.proc.pid, signal.SIGTERM)
        self.proc.wait(timeout=60)
        self.log.close()


def next_event(ch, pred, what):
    deadline = time.perf_counter() + TIMEOUT
    while True:
        try:
            e = ch.events.get(timeout=max(0.1, deadline - time.perf_counter()))
        except queue.Empty:
            raise common.BenchError("%s: timed out waiting for %s" % (ch.name, what))
        if e is None:
            raise common.BenchError("%s: the session ended before %s" % (ch.name, what))
        if e.get("event") == "error" and e.get("id") is not None:
            raise common.BenchError("%s: edit %s refused: %s" % (ch.name, e["id"], e["message"]))
        if pred(e):
            return e


def is_frame(e, spp=None, tier=None):
    return e.get("event") == "frame" and (spp is None or e.get("spp") == spp) and \
        (tier is None or e.get("tier") == tier)


def percentile(values, p):
    v = sorted(values)
    k = (len(v) - 1) * p / 100.0
    lo = int(k)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (k - lo)


def summary(ms):
    return {"p50": percentile(ms, 50), "p95": percentile(ms, 95), "min": min(ms),
            "max": max(ms), "n": len(ms)}


def edit_session(transport, tools, textures, first_pass, work):
    ch = transport(tools, textures, ["--first-pass=" + first_pass], work)
    try:
        next_event(ch, lambda e: e.get("event") == "ready", "ready")
        builds0 = next_event(ch, lambda e: is_frame(e, SPP), "the first complete frame")["builds"]
        rows = []
        edits = script()
        for eid, (kind, node, arg, value) in enumerate(edits, 1):
            t0 = time.perf_counter()
            ch.send(eid, kind, node, arg, value)
            first = next_event(ch, lambda e: is_frame(e) and e.get("edit") == eid,
                               "the first frame of edit %d" % eid)
            full = None
            if eid == len(edits) or edits[eid][0] == "rewire" or kind == "rewire":
                full = first
                if first.get("reduced"):
                    full = next_event(ch, lambda e: is_frame(e) and e.get("edit") == eid,
                                      "the full-resolution frame of edit %d" % eid)
            rows.append({"edit": "%s %s.%s=%s" % (kind, node, arg, value),
                         "firstFrameMs": (first["t"] - t0) * 1000,
                         "fullFrameMs": None if full is None else (full["t"] - t0) * 1000,
                         "texrenderLatencyMs": first.get("latency_ms"),
                         "split": first.get("split"), "tier": first.get("tier"),
                         "factor": first.get("factor", 1) if first.get("reduced") else 1,
                         "width": first.get("width")})
            time.sleep(THINK)
        builds1 = next_event(ch, lambda e: is_frame(e, SPP), "the last complete frame")["builds"]
    finally:
        ch.close()
    moves = [r for r in rows if r["edit"].startswith("set")]
    rewires = [r for r in rows if r["edit"].startswith("rewire")]
    return {"firstPass": first_pass, "transport": ch.name, "kernelBuilds": builds1 - builds0,
            "firstFrameMs": summary([r["firstFrameMs"] for r in rows]),
            "fullFrameMs": summary([r["fullFrameMs"] for r in rows if r["fullFrameMs"]]),
            "sliderFirstFrameMs": summary([r["firstFrameMs"] for r in moves]),
            "rewireFirstFrameMs": summary([r["firstFrameMs"] for r in rewires]),
            "edits": rows}


def source_edit(transport, tools, textures, folder, work, wait_quick=True):
    """Saves a copy of rust.cl with one constant changed while the preview is idle (after the
    quick tier's warm-up; wait_quick False: binaries without the quick tier)."""
    path = os.path.join(folder, "rust.cl")
    with open(path) as f:
        original = f.read()
    ch = transport(tools, textures, [], work)
    try:
        next_event(ch, lambda e: e.get("event") == "ready", "ready")
        next_event(ch, lambda e: is_frame(e, SPP, "shape"), "a complete frame of the shape tier")
        # texrender --watch then builds the quick tier's programs in the background (shape
        # mode, docs/live.md); a save during that warm-up waits for it: measured after it.
        log = getattr(ch, "log_path", None) or getattr(ch, "log_name", None)
        warm = wait_log(log, r"the quick tier's programs are built \((\d+) in (\d+) ms\)",
                        "the quick tier's warm-up", ch) if wait_quick else None
        time.sleep(SETTLE)
        while not ch.events.empty():
            ch.events.get()
        edited = change_constant(original)
        t0 = time.perf_counter()
        with open(path, "r+") as f:  # in place, as an editor saving
            f.write(edited)
            f.truncate()
        first = next_event(ch, is_frame, "the first frame with the new code")
        full = first if not first.get("reduced") else \
            next_event(ch, lambda e: is_frame(e) and not e.get("reduced"),
                       "the first full-resolution frame with the new code")
        shape = first if first.get("tier") == "shape" else \
            full if full.get("tier") == "shape" else \
            next_event(ch, lambda e: is_frame(e, tier="shape"), "the new shape kernel's frame")
    finally:
        ch.close()
        with open(path, "w") as f:
            f.write(original)
    return {"firstFrameMs": (first["t"] - t0) * 1000, "firstFrameTier": first.get("tier"),
            "shapeTakeoverMs": takeover_ms(log) if log else None,
            "quickWarmUp": {"programs": int(warm.group(1)), "ms": int(warm.group(2))}
            if warm else None,
            "fullFrameMs": (full["t"] - t0) * 1000,
            "shapeFrameMs": (shape["t"] - t0) * 1000, "settleSeconds": SETTLE,
            "texrenderSplit": source_split(log) if log else None}


SAVE_MODES = ("default", "interp", "shape", "inline", "wavefront")


def save_to_image(tools, mode, folder, work, cold, saves):
    """Issue 36: save -> the first image with the new code, for a texcc mode ("default": no
    --mode flag) in a fresh session (cold: empty texrender and PoCL program caches; warm: the
    shared cache, whose kernels the warm-up filled, and PoCL's), `saves` saves of rust.cl with a
    new constant each (no cache has that kernel), each made once the previous save's change has
    reached a complete frame; the first is made right after the session's first complete frame.
    Measured at the client: from the save to the frame event that carries texrender's "source"
    split (the first image written with the new code; it includes the up to 100 ms until
    texrender's poll notices the save). The default configuration: texrender without
    TEXRENDER_FIRST_BUILD (the quick first build on)."""
    path = os.path.join(folder, "rust.cl")
    with open(path) as f:
        original = f.read()
    tex = os.path.join(work, "tex-save-%s-%d" % (mode, time.monotonic_ns()))
    cmd = [tools.texcc, "--graph", os.path.join(folder, "graph.json"), "-o", tex]
    if mode != "default":
        cmd.insert(1, "--mode=" + mode)
    common.run(cmd)
    env = dict(os.environ)
    for var in ("TEXRENDER_FIRST_BUILD", "TEXRENDER_PREBUILT_DIR", "TEXRENDER_ANNOUNCE_AFTER"):
        env.pop(var, None)
    cache = tools.cache
    if cold:
        cache = os.path.join(work, "cold-cache-%d" % time.monotonic_ns())
        env["POCL_CACHE_DIR"] = os.path.join(cache, "pocl")
        os.makedirs(env["POCL_CACHE_DIR"])
    log_name = os.path.join(work, "save-%s-%d.log" % (mode, time.monotonic_ns()))
    events = queue.Queue()
    with open(log_name, "w") as log:
        proc = subprocess.Popen([tools.texrender, SCENE, "--textures", tex, "--size", SIZE,
                                 "--spp", str(SPP), "--device", tools.device, "--cache-dir",
                                 cache, "--watch", "--control", "-o",
                                 os.path.join(work, "save.png")],
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log,
                                text=True, bufsize=1, env=env, start_new_session=True)

        def pump():
            for line in proc.stdout:
                e = json.loads(line)
                e["t"] = time.perf_counter()
                events.put(e)
            events.put(None)
        threading.Thread(target=pump, daemon=True).start()

        class Ch:
            name = "control"
        Ch.events = events
        out = []
        try:
            next_event(Ch, lambda e: is_frame(e, SPP), "the session's first complete frame")
            for _ in range(saves):
                edited = change_constant(original)
                t0 = time.perf_counter()
                with open(path, "r+") as f:
                    f.write(edited)
                    f.truncate()
                first = next_event(Ch, lambda e: is_frame(e) and "source" in e,
                                   "the first frame with the new code")
                out.append({"ms": (first["t"] - t0) * 1000, "tier": first.get("tier"),
                            "reduced": bool(first.get("reduced")),
                            "texrender": first["source"]})
                common.log("lookdev: save -> image, %s %s: %.0f ms (tier %s; build %s ms)" % (
                    mode, "cold" if cold else "warm", out[-1]["ms"], out[-1]["tier"],
                    first["source"].get("build_ms")))
                next_event(Ch, lambda e: is_frame(e, SPP), "a complete frame with the new code")
        finally:
            os.killpg(proc.pid, signal.SIGKILL)  # quit would first finish background builds
            proc.wait()
            with open(path, "w") as f:
                f.write(original)
            if cold:
                shutil.rmtree(cache, ignore_errors=True)
    return out


def save_to_image_figures(tools, folder, work, reps, saves, modes):
    """Every mode, cold and warm sessions, interleaved (the order rotating per repetition);
    p50/p95 of the saves pooled per mode and kind, and of the first save of each session."""
    runs = {m: {"cold": [], "warm": []} for m in modes}
    loads = []
    for rep in range(reps):
        order = modes[rep % len(modes):] + modes[:rep % len(modes)]
        for mode in order:
            for cold in (True, False):
                loads.append(float(open("/proc/loadavg").read().split()[0]))
                runs[mode]["cold" if cold else "warm"].append(
                    save_to_image(tools, mode, folder, work, cold, saves))
    out = {"saves": saves, "reps": reps, "load1": [min(loads), max(loads)], "modes": {}}
    for mode in modes:
        out["modes"][mode] = {}
        for kind in ("cold", "warm"):
            sessions = runs[mode][kind]
            ms = [x["ms"] for s in sessions for x in s]
            first = [s[0]["ms"] for s in sessions if s]
            out["modes"][mode][kind] = {
                "p50": percentile(ms, 50), "p95": percentile(ms, 95), "max": max(ms),
                "n": len(ms), "firstEditMs": [round(x) for x in first],
                "tiers": sorted({x["tier"] for s in sessions for x in s}),
                "sessions": sessions}
    return out


def takeover_ms(log_path):
    """texrender's time from the change to the shape kernel built behind the quick tier
    taking over (its 'the background build is done' line), or None."""
    try:
        with open(log_path) as f:
            m = re.search(r"the shape kernel behind the quick tier, (\d+) ms after", f.read())
    except OSError:
        return None
    return int(m.group(1)) if m else None


def wait_log(log_path, pattern, what, ch):
    """The match of pattern in texrender's stderr log, waited for (TIMEOUT)."""
    deadline = time.perf_counter() + TIMEOUT
    rx = re.compile(pattern)
    while time.perf_counter() < deadline:
        try:
            with open(log_path) as f:
                for line in f:
                    m = rx.search(line)
                    if m:
                        return m
        except OSError:
            pass
        time.sleep(0.05)
    raise common.BenchError("%s: timed out waiting for %s" % (ch.name, what))


def change_constant(text):
    """rust.cl with the first floating-point literal of its code (not of a comment: texcc keeps
    comments, but PoCL's kernel cache hashes the preprocessed text, so a comment edit is a
    cache hit there) nudged by a random amount, so that no program cache, texrender's or
    PoCL's, has the new kernel, even from an earlier run."""
    code = re.sub(r"/\*.*?\*/|//[^\n]*", lambda c: " " * len(c.group(0)), text, flags=re.S)
    m = re.compile(r"(?<![\w.])(\d+\.\d+)f?").search(code, code.index("{"))
    if not m:
        raise common.BenchError("rust.cl: no floating-point constant to change")
    value = float(m.group(1)) + 1e-4 * (1 + random.randrange(10000) / 1e4)
    return text[:m.start(1)] + repr(value) + text[m.end(1):]


def source_split(log_path):
    """texrender's account of the last regenerated kernel's first frame (its stderr line
    'source change: ...'), as {stage: ms}."""
    try:
        with open(log_path) as f:
            lines = [l for l in f if "watch: source change: first frame" in l]
    except OSError:
        return None
    if not lines:
        return None
    line = lines[-1].strip()
    num = lambda pat: (lambda m: int(m.group(1)) if m else None)(re.search(pat, line))
    return {"line": line,
            "texccMs": num(r"texcc (\d+) ms"),
            "primeWaitMs": num(r"waited (\d+) ms for it"),
            "adoptMs": num(r"later in (\d+) ms"),
            "foregroundProgramMs": num(r"(\d+) ms loading, building and warming up"),
            "builds": num(r"\((\d+) kernel build\(s\) from source"),
            "passMs": num(r"pass(?: \(1/\d+\))? (\d+) ms after"),
            "writeMs": num(r"image written in (\d+) ms")}


def pick_transport(name):
    if name == "control":
        return Control
    try:
        import aiohttp  # noqa: F401
    except ImportError:
        if name == "ws":
            raise common.BenchError("aiohttp missing: scripts/serve.sh --install")
        return Control
    return WebSocket


def uptime():
    return subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip()


def measure(tools, quick, transport_name="auto"):
    transport = pick_transport(transport_name)
    work = tempfile.mkdtemp(prefix="lookdev-", dir=tools.work)
    folder, textures = prepare(tools, work)
    reps = 1 if quick else 2
    out = {"transport": transport.name, "size": SIZE, "spp": SPP, "thinkSeconds": THINK,
           "uptimeBefore": uptime(), "sessions": [], "sourceEdits": []}
    # Warm the program cache with the kernels of both folders (not part of any figure).
    for mode in ("interp", "shape"):
        common.texrender(tools, SCENE, textures[mode], "lookdev-warm-" + mode,
                         ["--size", SIZE, "--spp", "1"])
    for _ in range(reps):
        for first_pass in ("reduced", "full"):
            out["sessions"].append(edit_session(transport, tools, textures["interp"],
                                                first_pass, work))
            common.log("lookdev: %s first pass: p50 %.0f ms, p95 %.0f ms, %d build(s)" % (
                first_pass, out["sessions"][-1]["firstFrameMs"]["p50"],
                out["sessions"][-1]["firstFrameMs"]["p95"], out["sessions"][-1]["kernelBuilds"]))
        out["sourceEdits"].append(source_edit(transport, tools, textures["shape"], folder, work))
    out["uptimeAfter"] = uptime()
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--transport", choices=("auto", "ws", "control"), default="auto")
    common.add_build_argument(ap)
    ap.add_argument("--device", default="0")
    ap.add_argument("--out", help="result file (default bench/results/lookdev.json)")
    ap.add_argument("--save-to-image", action="store_true",
                    help="only the issue-36 figure: save -> first image with the new code, "
                         "per mode (--modes), cold and warm sessions")
    ap.add_argument("--modes", default=",".join(SAVE_MODES))
    ap.add_argument("--saves", type=int, default=4, help="saves per session (--save-to-image)")
    ap.add_argument("--reps", type=int, default=2, help="sessions per mode and kind")
    args = ap.parse_args()
    tools = common.Tools(os.path.abspath(args.build), tempfile.mkdtemp(prefix="texcc-bench-"),
                         args.device)
    if args.save_to_image:
        work = tempfile.mkdtemp(prefix="lookdev-", dir=tools.work)
        folder, textures = prepare(tools, work)
        for mode in ("interp", "shape"):  # the warm sessions' cache (not part of any figure)
            common.texrender(tools, SCENE, textures[mode], "lookdev-warm-" + mode,
                             ["--size", SIZE, "--spp", "1"])
        modes = [m for m in args.modes.split(",") if m]
        data = {"saveToImage": save_to_image_figures(tools, folder, work, args.reps, args.saves,
                                                     modes),
                "uptime": uptime()}
        data["date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        data["git"] = common.git_head()
        data["command"] = "bench/lookdev.py " + " ".join(sys.argv[1:])
        common.save("lookdev-save", data, args.out)
        for mode, kinds in data["saveToImage"]["modes"].items():
            for kind, r in kinds.items():
                print("%-9s %-4s save -> image p50 %5.0f ms  p95 %5.0f ms  max %5.0f ms  "
                      "first edits %s  tiers %s" % (mode, kind, r["p50"], r["p95"], r["max"],
                                                    r["firstEditMs"], ",".join(r["tiers"])))
        return
    data = measure(tools, args.quick, args.transport)
    data["date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    data["git"] = common.git_head()
    data["command"] = "bench/lookdev.py " + " ".join(sys.argv[1:])
    common.save("lookdev", data, args.out)


if __name__ == "__main__":
    try:
        main()
    except common.BenchError as e:
        sys.stderr.write("lookdev: error: %s\n" % e)
        sys.exit(1)
