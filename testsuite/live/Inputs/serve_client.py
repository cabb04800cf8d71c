"""Plays a browser (or an attacker's page) against the preview server, scripts/serve.py, run
with the fake texrender (serve_fake_texrender.py): one safety behaviour per CASE.

  serve_client.py CASE [--renderer TEXRENDER] -- SCENE --textures DIR [texrender options]

Starts the server on a free port (with the fake texrender unless --renderer names the real
one), waits for the page's hello, runs CASE, prints what it saw (one fact a line, for
FileCheck), asks the server to quit and prints "server exit N". The control lines that reached
the fake texrender are read from its log ($SERVE_FAKE_LOG).
"""
import asyncio
import collections
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time

import aiohttp
from waits import WAIT_S  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SERVE = os.path.join(HERE, "..", "..", "..", "scripts", "serve.py")
FAKE = os.path.join(HERE, "serve_fake_texrender.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Session:
    def __init__(self, render_args, hold=False, server_args=(), renderer=FAKE):
        self.tmp = tempfile.mkdtemp(prefix="serve-client-")
        self.log = os.path.join(self.tmp, "control.log")
        env = dict(os.environ, SERVE_FAKE_LOG=self.log)
        # hold: the fake texrender answers an edit only while the file self.hold exists.
        self.hold = os.path.join(self.tmp, "hold") if hold else None
        if self.hold:
            env["SERVE_FAKE_HOLD"] = self.hold
        # $SERVE_AUDIT_LOG: the server runs under an audit hook that logs every file it opens.
        audit = [os.path.join(HERE, "serve_audit.py")] if "SERVE_AUDIT_LOG" in os.environ else []
        self.proc = subprocess.Popen(
            [sys.executable] + audit + [SERVE, "--port", "0", "--texrender", renderer]
            + list(server_args)
            + ["--"] + render_args, stderr=subprocess.PIPE, text=True, env=env)
        self.lines = []  # the server's log up to the address line, then all of it (a thread)
        for line in self.proc.stderr:
            self.lines.append(line)
            m = re.search(r"preview at http://127\.0\.0\.1:(\d+)/(\S*)", line)
            if m:
                self.port = int(m.group(1))
                self.query = m.group(2)
                break
        else:
            sys.exit("serve_client.py: the server ended before listening")
        threading.Thread(target=lambda: self.lines.extend(self.proc.stderr), daemon=True).start()
        self.url = f"http://127.0.0.1:{self.port}"
        self.host = f"127.0.0.1:{self.port}"

    def forwarded(self):
        """The control lines the fake texrender received."""
        if not os.path.exists(self.log):
            return []
        with open(self.log) as f:
            return f.read().splitlines()

    def rss_kib(self):
        with open(f"/proc/{self.proc.pid}/status") as f:
            return int(re.search(r"VmRSS:\s+(\d+)", f.read()).group(1))

    def alive(self):
        return self.proc.poll() is None

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        try:
            code = self.proc.wait(timeout=WAIT_S)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            code = "killed"
        print(f"server exit {code}")


async def open_page(session, http, **kw):
    ws = await http.ws_connect(session.url + "/ws", **kw)
    hello = await next_of(ws, "hello")
    return ws, hello


async def next_of(ws, kind, timeout=WAIT_S):
    """The next text message of type KIND (frames and their PNGs are skipped)."""
    deadline = time.monotonic() + timeout
    while True:
        if time.monotonic() > deadline:  # frames keep coming: receive() alone never times out
            raise TimeoutError(f"no {kind} message within {timeout} s")
        msg = await ws.receive(timeout=max(0.1, deadline - time.monotonic()))
        if msg.type == aiohttp.WSMsgType.TEXT:
            data = json.loads(msg.data)
            if data["type"] == kind:
                return data
        elif msg.type != aiohttp.WSMsgType.BINARY:
            raise RuntimeError(f"socket closed ({msg.type}, {msg.data}) waiting for {kind}")


async def refused(ws, text):
    """Sends TEXT, prints the error it gets."""
    await ws.send_str(text)
    err = await next_of(ws, "error")
    print(f"error id={err['id']}: {err['message']}")


async def still_serving(s, http):
    """A valid edit from a fresh page is applied: the server serves on."""
    ws, _ = await open_page(s, http)
    await ws.send_str(json.dumps({"type": "set", "id": 99, "node": "t", "arg": "gain",
                                  "value": 0.5}))
    applied = await next_of(ws, "applied")
    frame = await next_of(ws, "frame")
    png = (await ws.receive(timeout=WAIT_S)).data
    is_png = png[:8] == PNG_SIGNATURE
    print(f"applied id={applied['id']} value={applied['value']}; then a frame of "
          f"{len(png)} bytes (PNG: {is_png})")
    await ws.close()


async def case_foreign_origin(s, http):
    page = await http.get(s.url + "/", headers={"Origin": "http://evil.example"})
    print(f"page from a foreign Origin: {page.status}")
    try:
        await http.ws_connect(s.url + "/ws", origin="http://evil.example")
        print("websocket from a foreign Origin: accepted")
    except aiohttp.WSServerHandshakeError as e:
        print(f"websocket from a foreign Origin: {e.status}")
    ws, hello = await open_page(s, http, origin=s.url)
    print(f"websocket from its own Origin: {hello['type']}")
    await ws.close()


async def case_foreign_host(s, http):
    for host in ("evil.example", f"evil.example:{s.port}", f"127.0.0.1:{s.port + 1}"):
        page = await http.get(s.url + "/", headers={"Host": host})
        try:
            await http.ws_connect(s.url + "/ws", headers={"Host": host})
            verdict = "accepted"
        except aiohttp.WSServerHandshakeError as e:
            verdict = e.status
        shown = host.replace(str(s.port + 1), "PORT+1").replace(str(s.port), "PORT")
        print(f"Host {shown}: page {page.status}, websocket {verdict}")
    page = await http.get(s.url + "/", headers={"Host": f"localhost:{s.port}"})
    print(f"Host localhost:PORT: page {page.status}")


async def case_malformed(s, http):
    ws, _ = await open_page(s, http)
    for text in ('{"type": "set", "id": 1, ', "[1, 2]", '"set"', "",
                 '{"type": "set", "id": 1, "id": 2, "node": "t", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 1, "node": "t", "arg": "gain"}',
                 '{"type": "set", "id": 1, "node": "t", "arg": "gain", "value": 1, "path": "/etc"}',
                 '{"type": "set", "id": "1", "node": "t", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": true, "node": "t", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 9007199254740992, "node": "t", "arg": "gain", "value": 1}',
                 '{"type": ["set"], "id": 1, "node": "t", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 2, "node": ["t"], "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 3, "node": "t", "arg": "a.gain", "value": 1}',
                 '{"type": "set", "id": 4, "node": "t=1", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 5, "node": "t\\nquit", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 6, "node": "t", "arg": "gain", "value": ' + "[" * 9 + "]" * 9 + "}",
                 '{"type": "set", "id": 7, "node": "t", "arg": "gain", "value": ' + "[" * 30000 + "]" * 30000 + "}",
                 '{"type": "set", "id": 8, "node": "t", "arg": "gain", "value": "\\ud800"}',
                 '{"type": "set", "id": 9, "node": "t", "arg": "gain", "value": ' + "9" * 5000 + "}"):
        await refused(ws, text)
    await ws.send_bytes(b"\x00\x01")
    err = await next_of(ws, "error")
    print(f"binary: {err['message']}")
    print(f"lines that reached texrender: {len(s.forwarded())}")
    await ws.close()
    await still_serving(s, http)


async def case_oversized(s, http):
    ws, _ = await open_page(s, http)
    big = json.dumps({"type": "set", "id": 1, "node": "t", "arg": "gain", "value": 1,
                      "pad": "x" * 100000})
    await refused(ws, big)
    await ws.send_str(json.dumps({"type": "set", "id": 2, "node": "t", "arg": "gain",
                                  "value": 0.25}))
    print(f"next message applied: id={(await next_of(ws, 'applied'))['id']}")
    await ws.send_str("x" * (2 * 1024 * 1024))
    msg = await ws.receive(timeout=WAIT_S)
    while msg.type in (aiohttp.WSMsgType.TEXT, aiohttp.WSMsgType.BINARY):
        msg = await ws.receive(timeout=WAIT_S)
    print(f"2 MiB message: socket {msg.type.name} code {ws.close_code}")
    print(f"lines that reached texrender: {s.forwarded()}")
    await still_serving(s, http)


async def case_unknown(s, http):
    ws, _ = await open_page(s, http)
    for text in ('{"type": "load", "id": 1, "path": "/etc/passwd"}',
                 '{"type": "set", "id": 6, "node": "t", "arg": "gain", "value": "0.5"}',
                 '{"type": "set", "id": 7, "node": "t", "arg": "color", "value": [1, 0]}',
                 '{"type": "set", "id": 8, "node": "o", "arg": "octaves", "value": 2.5}',
                 '{"type": "set", "id": 2, "node": "nope", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 3, "node": "t", "arg": "nope", "value": 1}',
                 '{"type": "rewire", "id": 4, "node": "t", "arg": "gain", "source": "nope"}',
                 '{"type": "rewire", "id": 5, "node": "t", "arg": "gain", "source": "t"}'):
        await refused(ws, text)
    await ws.close()
    await still_serving(s, http)


async def case_nan(s, http):
    ws, _ = await open_page(s, http)
    for value in ("NaN", "Infinity", "-Infinity", "1e400", "[0.5, NaN, 0.5]"):
        arg = "color" if value.startswith("[") else "gain"
        await refused(ws, f'{{"type": "set", "id": 7, "node": "t", "arg": "{arg}", '
                          f'"value": {value}}}')
    print(f"lines that reached texrender: {len(s.forwarded())}")
    await ws.close()


async def case_refused_downstream(s, http):
    """An edit that passes the server's checks but texrender refuses: the error reaches the
    page that sent it, with its id, and the next edit goes through."""
    ws, _ = await open_page(s, http)
    other, _ = await open_page(s, http)
    await ws.send_str(json.dumps({"type": "rewire", "id": 41, "node": "t", "arg": "color",
                                  "source": "o"}))
    err = await next_of(ws, "error")
    print(f"error id={err['id']}: {err['message']}")
    await ws.send_str(json.dumps({"type": "rewire", "id": 42, "node": "t", "arg": "color",
                                  "source": "u"}))
    applied = await next_of(ws, "applied")
    print(f"applied id={applied['id']}: {applied['node']}.{applied['arg']} <- {applied['source']}")
    seen = await next_of(other, "applied")
    print(f"the other page: applied id={seen['id']} {seen['node']}.{seen['arg']} <- {seen['source']}")
    print(f"lines that reached texrender: {[l.split(' ', 1)[1] for l in s.forwarded()]}")
    await ws.close()
    await other.close()


async def burst(s, ws, first_id, n):
    """n set messages sent while the fake texrender holds its answer to the first (the edit in
    flight), released once the server has read them all (its answer to a message of an unknown
    type sent after them: it reads a page's messages in order): the server must coalesce the
    rest into one line."""
    if os.path.exists(s.hold):
        os.remove(s.hold)
    for i in range(n):
        await ws.send_str(json.dumps({"type": "set", "id": first_id + i, "node": "t",
                                      "arg": "gain", "value": (i + 1) / n}))
    await ws.send_str(json.dumps({"type": "read-them-all", "id": first_id + n}))
    await next_of(ws, "error")
    open(s.hold, "w").close()
    last = first_id + n - 1
    while True:
        applied = await next_of(ws, "applied", timeout=WAIT_S)
        if applied["id"] == last:
            return applied


async def case_burst(s, http):
    ws, _ = await open_page(s, http)
    applied = await burst(s, ws, 1, 1000)
    lines = s.forwarded()
    print(f"1000 messages: {len(lines)} control lines reached texrender; the last applied is "
          f"id {applied['id']} value {applied['value']} (coalesced {applied['coalesced']})")
    print(f"last line: {lines[-1].split(' ', 1)[1]}")
    before = s.rss_kib()
    for k in range(10):
        await burst(s, ws, 10000 * (k + 1), 1000)
    after = s.rss_kib()
    growth = after - before
    print(f"rss after 1000: {before} KiB, after 10000 more: {after} KiB; growth {growth} KiB")
    print("rss bounded" if growth < 4096 else "rss grows")
    print(f"control lines in all: {len(s.forwarded())}")
    await ws.close()


async def case_flood_unread(s, http):
    """20,000 refused messages sent without reading the answers, then read."""
    ws, _ = await open_page(s, http)
    before = s.rss_kib()
    n = 20000
    for i in range(n):
        await ws.send_str(json.dumps({"type": "set", "id": i, "node": "t", "arg": "gain.x",
                                      "value": 1}))
    sent_rss = s.rss_kib()
    errors = 0
    while errors < n:
        msg = await ws.receive(timeout=WAIT_S)
        if msg.type == aiohttp.WSMsgType.TEXT and json.loads(msg.data)["type"] == "error":
            errors += 1
        elif msg.type not in (aiohttp.WSMsgType.TEXT, aiohttp.WSMsgType.BINARY):
            break
    growth = max(sent_rss, s.rss_kib()) - before
    print(f"{n} refused messages sent unread: {errors} errors received in the end")
    print(f"rss growth {growth} KiB: " + ("bounded" if growth < 8192 else "grows"))
    print(f"lines that reached texrender: {len(s.forwarded())}")
    await ws.close()
    await still_serving(s, http)


def stream_forever(port):
    """The killed client: reads frames until it is killed."""
    async def run():
        async with aiohttp.ClientSession() as http:
            async with http.ws_connect(f"http://127.0.0.1:{port}/ws") as ws:
                await ws.send_str(json.dumps({"type": "set", "id": 1, "node": "t",
                                              "arg": "gain", "value": 0.75}))
                frames = 0
                async for msg in ws:
                    if msg.type == aiohttp.WSMsgType.BINARY:
                        frames += 1
                        if frames == 3:
                            print("streaming", flush=True)
    asyncio.run(run())


async def case_killed_client(s, http):
    child = subprocess.Popen([sys.executable, __file__, "--stream", str(s.port)],
                             stdout=subprocess.PIPE, text=True)
    print(f"client: {child.stdout.readline().strip()}")
    child.kill()
    child.wait()
    print("client killed mid-stream")
    await asyncio.sleep(0.5)
    print(f"server alive: {s.alive()}")
    await still_serving(s, http)


def fuzz_message(rng):
    """One random page message: (kind, payload). Kinds: "text" (a str), "bytes" (a binary
    frame), "raw-text" (a text frame of raw bytes: invalid UTF-8 fails the connection, RFC 6455
    7.1.7). About a third are well-formed edits."""
    nodes = ["t", "u", "o", "Mat/Noise.Fac", "a.b.c", "", "t\u00e9", "\ud800"]
    args = ["gain", "color", "octaves", "p", "nope", "a.b", "x=y", "\n"]
    def number():
        return rng.choice([rng.uniform(-1e6, 1e6), rng.randint(-2 ** 40, 2 ** 40), 0, -0.0,
                           10 ** rng.randint(15, 400), 1e308, 5e-324, 0.1])
    def value(depth=0):
        r = rng.random()
        if r < 0.45 or depth > 3:
            return number()
        if r < 0.75:
            return [number() for _ in range(rng.randint(0, 5))]
        if r < 0.85:
            return [value(depth + 1) for _ in range(rng.randint(0, 3))]
        return rng.choice(["x", None, True, {"node": "u"}, {"attr": "ObjectPos"}, {}, "\u0000"])
    r = rng.random()
    ident = rng.randint(0, 10 ** 6)
    if r < 0.33:
        if rng.random() < 0.8:
            msg = {"type": "set", "id": ident, "node": rng.choice(nodes[:3]),
                   "arg": rng.choice(args[:4]), "value": value()}
        else:
            msg = {"type": "rewire", "id": ident, "node": rng.choice(nodes[:3]),
                   "arg": rng.choice(args[:4]), "source": rng.choice(nodes[:4])}
        return "text", json.dumps(msg)
    if r < 0.55:  # a field of the wrong kind or value
        msg = {"type": "set", "id": ident, "node": rng.choice(nodes), "arg": rng.choice(args),
               "value": value()}
        key = rng.choice(["type", "id", "node", "arg", "value", "extra", None])
        bad = rng.choice([[1, 2], ["set"], {"a": 1}, 10 ** 310, -1, 2 ** 53, 1.5, True, None,
                          "set\nquit", "x" * 2000])
        if key is None:
            msg.pop(rng.choice(list(msg)))
        else:
            msg[key] = bad
        return "text", json.dumps(msg)
    if r < 0.62:  # nesting under the size limit
        n = rng.choice([9, 100, 1000, 30000])
        return "text", ('{"type": "set", "id": 1, "node": "t", "arg": "gain", "value": '
                        + "[" * n + "]" * n + "}")
    if r < 0.70:  # JSON that Python's json accepts and JSON does not, or no JSON at all
        return "text", rng.choice(['{"type": "set", "id": 1, "node": "t", "arg": "gain", '
                                   '"value": NaN}', '{"type": "set", "id": 1, "node": "t", '
                                   '"arg": "gain", "value": 1e400}', "[", "{}", "null", "1" * 5000,
                                   '{"type": "set", "id": 1, "id": 1}', "\u0000", ""])
    if r < 0.78:
        return "text", json.dumps(value())
    if r < 0.86:
        return "bytes", bytes(rng.getrandbits(8) for _ in range(rng.randint(0, 64)))
    if r < 0.94:  # an edit over the size limit (under the hard limit that closes the socket)
        return "text", json.dumps({"type": "set", "id": ident, "node": "t", "arg": "gain",
                                   "value": [0.5] * rng.randint(14000, 60000)})
    return "raw-text", rng.choice([b"\xff\xfe", b'{"type": "set", "id": 1, "node": "\xc3"}',
                                   b"\xed\xa0\x80"])


async def case_fuzz(s, http):
    """A seeded generator sends N random messages, well-formed and ill-formed; every one is
    answered: an 'applied' or 'error' with its id, an error without one (framing), a place in
    the 'coalesced' count of a later edit of the same argument, or, for a text frame that is
    not UTF-8, the close RFC 6455 requires (1007) after which a new page connects. The server
    keeps serving throughout and after."""
    import random
    seed, n = int(os.environ.get("SERVE_FUZZ_SEED", "36")), int(os.environ.get("SERVE_FUZZ_N", "3000"))
    rng = random.Random(seed)
    ws, _ = await open_page(s, http)
    kinds = collections.Counter()
    answered = closed = 0
    pending = 0

    async def drain(until_zero):
        nonlocal pending, answered
        while pending > 0:
            msg = await ws.receive(timeout=WAIT_S)
            if msg.type == aiohttp.WSMsgType.TEXT:
                data = json.loads(msg.data)
                if data["type"] == "error":
                    pending -= 1 + data.get("coalesced", 0)
                    answered += 1 + data.get("coalesced", 0)
                elif data["type"] == "applied" and data["id"] is not None:
                    pending -= 1 + data["coalesced"]
                    answered += 1 + data["coalesced"]
            elif msg.type != aiohttp.WSMsgType.BINARY:
                raise RuntimeError(f"socket closed ({msg.type}) with {pending} messages unanswered")
            if not until_zero and pending < 20:
                return

    for i in range(n):
        kind, payload = fuzz_message(rng)
        kinds[kind] += 1
        if kind == "raw-text":
            await drain(True)
            await ws.send_frame(payload, aiohttp.WSMsgType.TEXT)
            msg = await ws.receive(timeout=WAIT_S)
            while msg.type in (aiohttp.WSMsgType.TEXT, aiohttp.WSMsgType.BINARY):
                msg = await ws.receive(timeout=WAIT_S)
            if ws.close_code == 1007:
                closed += 1
            else:
                print(f"invalid UTF-8 text frame: closed with {ws.close_code}")
            ws, _ = await open_page(s, http)
            continue
        if kind == "bytes":
            await ws.send_bytes(payload)
        else:
            await ws.send_str(payload)
        pending += 1
        if pending >= 50:
            await drain(False)
    await drain(True)
    print(f"seed {seed}: {n} messages ({kinds['text']} text, {kinds['bytes']} binary, "
          f"{kinds['raw-text']} text frames not UTF-8)")
    print(f"answered: {answered + closed == n} ({answered} answers, {closed} closes with 1007)")
    print(f"server alive: {s.alive()}")
    await ws.close()
    await still_serving(s, http)


async def case_token(s, http):
    """--listen 0.0.0.0: a warning, a token printed once in the address, required on the page
    and on the WebSocket; an idle connection is closed (--idle-timeout 1)."""
    warned = any("warning: listening on 0.0.0.0" in line for line in s.lines)
    token = re.fullmatch(r"\?token=([A-Za-z0-9_-]{20,})", s.query)
    print(f"warning printed: {warned}; token in the address: {bool(token)}")
    real = token.group(1)
    wrong = ("y" if real[0] == "x" else "x") + real[1:]  # differs from the token in one place
    for what, query in (("no token", ""), ("a wrong token", "?token=" + wrong),
                        ("the token", "?" + s.query[1:])):
        page = await http.get(s.url + "/" + query)
        try:
            ws = await http.ws_connect(s.url + "/ws" + query)
            verdict = (await next_of(ws, "hello"))["type"]
            await ws.close()
        except aiohttp.WSServerHandshakeError as e:
            verdict = e.status
        print(f"{what}: page {page.status}, websocket {verdict}")
    script = await http.get(s.url + "/app.js")
    print(f"app.js without the token: {script.status}")
    reader, writer = await asyncio.open_connection("127.0.0.1", s.port)
    data = await asyncio.wait_for(reader.read(), 60)  # the server closes it: EOF
    print(f"an idle connection is closed by the server: {data == b''}")
    writer.close()


async def case_dotted(s, http):
    """Node ids holding dots, as the Blender exporter writes them ("Mat/Noise.Fac"): the edit
    line splits NODE.ARG at the last dot (texrender's grammar) and the answer, which names the
    node and argument as texrender parsed them, reaches the sending page and the others."""
    ws, hello = await open_page(s, http)
    other, _ = await open_page(s, http)
    # (The old server's hello had "controls", not "schema": read either, to see where it fails.)
    nodes = hello["schema"]["nodes"] if "schema" in hello else hello["controls"]
    print("nodes: " + ", ".join(n.get("id", n.get("node")) for n in nodes))
    await ws.send_str(json.dumps({"type": "set", "id": 5, "node": "Mat/Noise.Fac",
                                  "arg": "gain", "value": 0.25}))
    applied = await next_of(ws, "applied")
    print(f"applied id={applied['id']}: {applied['node']}.{applied['arg']}={applied['value']}")
    seen = await next_of(other, "applied")
    print(f"the other page: id={seen['id']} {seen['node']}.{seen['arg']}={seen['value']}")
    await ws.send_str(json.dumps({"type": "rewire", "id": 6, "node": "Mat/Noise.Fac",
                                  "arg": "color", "source": "a.b.c"}))
    applied = await next_of(ws, "applied")
    print(f"applied id={applied['id']}: {applied['node']}.{applied['arg']} <- {applied['source']}")
    print(f"lines that reached texrender: {[l.split(' ', 1)[1] for l in s.forwarded()]}")
    third, hello = await open_page(s, http)
    node = next(n for n in hello["schema"]["nodes"] if n["id"] == "Mat/Noise.Fac")
    print("a page opened later: " + ", ".join(
        f"{i['name']}={i.get('value', i.get('node'))}" for i in node["inputs"]))
    for w in (ws, other, third):
        await w.close()


async def case_later_page(s, http):
    """Edits from one page, then a page opened later: its hello's schema has each edited input
    as texrender's applied event gave it (the server applies no edit to its copy itself)."""
    ws, _ = await open_page(s, http)
    for i, (arg, value) in enumerate((("gain", {"node": "b"}), ("color", [0.25, 0.5, 1.0])), 1):
        await ws.send_str(json.dumps({"type": "set", "id": i, "node": "t", "arg": arg,
                                      "value": value}))
        applied = await next_of(ws, "applied")
        print(f"applied id={applied['id']}: {applied['node']}.{applied['arg']}")
    later, hello = await open_page(s, http)
    node = next(n for n in hello["schema"]["nodes"] if n["id"] == "t")
    for put in node["inputs"]:
        print(f"a page opened later: t.{put['name']}: " +
              ", ".join(f"{k}={put[k]}" for k in ("value", "node", "attr") if k in put))
    for w in (ws, later):
        await w.close()


async def case_huge_lines(s, http):
    """texrender's log and events with 10 MiB lines (the fake writes them first): the server
    reads on (no line limit ends its readers), the page gets the error cut to a bounded size."""
    ws, hello = await open_page(s, http)
    error = hello["error"]
    if error is None:
        error = (await next_of(ws, "error"))["message"]
    print(f"the page's error: {error[:24]}... {len(error)} characters, "
          f"ends {error[error.rindex('('):]}")
    await ws.close()
    await still_serving(s, http)
    log = "".join(s.lines)
    print(f"the 10 MiB log line passed through: {'x' * 1000 in log}")


async def case_graph_not_a_file(s, http):
    """graph.json replaced by a FIFO, then by a symbolic link to /dev/zero, while the preview
    runs (the real texrender): the server reads no user file, texrender refuses each with an
    error that every page shows, new pages are served, and the graph restored renders again."""
    folder = os.path.dirname(os.path.abspath(sys.argv[sys.argv.index("--") + 1]))
    graph = os.path.join(folder, "graph.json")
    with open(graph) as f:
        good = f.read()
    ws, _ = await open_page(s, http)

    async def replace(make, what):
        tmp = graph + ".new"
        make(tmp)
        os.replace(tmp, graph)
        err = await next_of(ws, "error", timeout=WAIT_S)
        print(f"{what}: the page shows: {err['message'][err['message'].index('graph.json'):][:80]}")
        other, hello = await open_page(s, http)
        print(f"{what}: a new page is served, its hello has the error: {hello['error'] is not None}")
        await other.close()
        with open(tmp, "w") as f:
            f.write(good)
        os.replace(tmp, graph)
        hello = await next_of(ws, "hello", timeout=WAIT_S)
        print(f"{what}: graph.json restored: a new hello, error {hello['error']}")

    await replace(os.mkfifo, "a FIFO")
    await replace(lambda p: os.symlink("/dev/zero", p), "a link to /dev/zero")
    await ws.close()
    await still_serving(s, http)
    if "SERVE_AUDIT_LOG" in os.environ:
        with open(os.environ["SERVE_AUDIT_LOG"]) as f:
            opened = sorted({p.strip() for p in f if p.startswith(folder + os.sep)})
        print(f"files the server opened in the scene's folder: {opened}")


async def main_async(case, s):
    # A new connection per request: the server closes idle keep-alive connections
    # (--idle-timeout; 1 s in the token case), and a pooled connection reused as the server
    # closes it fails the request, a race that a loaded machine wins.
    async with aiohttp.ClientSession(connector=aiohttp.TCPConnector(force_close=True)) as http:
        await globals()["case_" + case.replace("-", "_")](s, http)


def main():
    if sys.argv[1] == "--stream":
        stream_forever(int(sys.argv[2]))
        return
    case = sys.argv[1]
    cut = sys.argv.index("--")
    hold = case == "burst"
    if case == "huge-lines":
        os.environ["SERVE_FAKE_HUGE_LINES"] = "1"
    server_args = ["--listen", "0.0.0.0", "--idle-timeout", "1"] if case == "token" else []
    head = sys.argv[2:cut]
    renderer = head[head.index("--renderer") + 1] if "--renderer" in head else FAKE
    s = Session(sys.argv[cut + 1:], hold, server_args, renderer)
    try:
        asyncio.run(main_async(case, s))
    finally:
        s.stop()


if __name__ == "__main__":
    main()
