"""Plays a browser (or an attacker's page) against the preview server, scripts/serve.py, run
with the fake texrender (serve_fake_texrender.py): one safety behaviour per CASE.

  serve_client.py CASE --texcc TEXCC -- SCENE --textures DIR

Starts the server on a free port, waits for the page's hello, runs CASE, prints what it saw
(one fact a line, for FileCheck), asks the server to quit and prints "server exit N". The
control lines that reached the fake texrender are read from its log ($SERVE_FAKE_LOG).
"""
import asyncio
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

import aiohttp

HERE = os.path.dirname(os.path.abspath(__file__))
SERVE = os.path.join(HERE, "..", "..", "..", "scripts", "serve.py")
FAKE = os.path.join(HERE, "serve_fake_texrender.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Session:
    def __init__(self, texcc, render_args, delay_ms=0):
        self.tmp = tempfile.mkdtemp(prefix="serve-client-")
        self.log = os.path.join(self.tmp, "control.log")
        env = dict(os.environ, SERVE_FAKE_LOG=self.log, SERVE_FAKE_DELAY_MS=str(delay_ms))
        self.proc = subprocess.Popen(
            [sys.executable, SERVE, "--port", "0", "--texrender", FAKE, "--texcc", texcc, "--"]
            + render_args, stderr=subprocess.PIPE, text=True, env=env)
        for line in self.proc.stderr:
            m = re.search(r"preview at http://127\.0\.0\.1:(\d+)/", line)
            if m:
                self.port = int(m.group(1))
                break
        else:
            sys.exit("serve_client.py: the server ended before listening")
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
            code = self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            code = "killed"
        print(f"server exit {code}")


async def open_page(session, http, **kw):
    ws = await http.ws_connect(session.url + "/ws", **kw)
    hello = await next_of(ws, "hello")
    return ws, hello


async def next_of(ws, kind, timeout=20):
    """The next text message of type KIND (frames and their PNGs are skipped)."""
    deadline = time.monotonic() + timeout
    while True:
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
    png = (await ws.receive(timeout=20)).data
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
                 '{"type": "set", "id": 2, "node": "t", "arg": "gain", "value": "0.5"}',
                 '{"type": "set", "id": 3, "node": "t", "arg": "gain", "value": [0.5]}',
                 '{"type": "set", "id": 4, "node": "t", "arg": "color", "value": [1, 0]}',
                 '{"type": "set", "id": 5, "node": "o", "arg": "octaves", "value": 2.5}',
                 '{"type": "set", "id": 6, "node": "o", "arg": "octaves", "value": true}'):
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
    msg = await ws.receive(timeout=20)
    while msg.type in (aiohttp.WSMsgType.TEXT, aiohttp.WSMsgType.BINARY):
        msg = await ws.receive(timeout=20)
    print(f"2 MiB message: socket {msg.type.name} code {ws.close_code}")
    print(f"lines that reached texrender: {s.forwarded()}")
    await still_serving(s, http)


async def case_unknown(s, http):
    ws, _ = await open_page(s, http)
    for text in ('{"type": "load", "id": 1, "path": "/etc/passwd"}',
                 '{"type": "set", "id": 2, "node": "nope", "arg": "gain", "value": 1}',
                 '{"type": "set", "id": 3, "node": "t", "arg": "nope", "value": 1}',
                 '{"type": "rewire", "id": 4, "node": "t", "arg": "gain", "source": "nope"}',
                 '{"type": "rewire", "id": 5, "node": "t", "arg": "gain", "source": "t"}'):
        await refused(ws, text)
    print(f"lines that reached texrender: {len(s.forwarded())}")
    await ws.close()


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


async def burst(ws, first_id, n):
    for i in range(n):
        await ws.send_str(json.dumps({"type": "set", "id": first_id + i, "node": "t",
                                      "arg": "gain", "value": (i + 1) / n}))
    last = first_id + n - 1
    while True:
        applied = await next_of(ws, "applied", timeout=60)
        if applied["id"] == last:
            return applied


async def case_burst(s, http):
    ws, _ = await open_page(s, http)
    applied = await burst(ws, 1, 1000)
    lines = s.forwarded()
    print(f"1000 messages: {len(lines)} control lines reached texrender; the last applied is "
          f"id {applied['id']} value {applied['value']} (coalesced {applied['coalesced']})")
    print(f"last line: {lines[-1].split(' ', 1)[1]}")
    before = s.rss_kib()
    for k in range(10):
        await burst(ws, 10000 * (k + 1), 1000)
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
        await ws.send_str(json.dumps({"type": "set", "id": i, "node": "nope", "arg": "gain",
                                      "value": 1}))
    sent_rss = s.rss_kib()
    errors = 0
    while errors < n:
        msg = await ws.receive(timeout=60)
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


async def main_async(case, s):
    async with aiohttp.ClientSession() as http:
        await globals()["case_" + case.replace("-", "_")](s, http)


def main():
    if sys.argv[1] == "--stream":
        stream_forever(int(sys.argv[2]))
        return
    case = sys.argv[1]
    cut = sys.argv.index("--")
    texcc = sys.argv[sys.argv.index("--texcc") + 1]
    delay = 200 if case == "burst" else 0
    s = Session(texcc, sys.argv[cut + 1:], delay)
    try:
        asyncio.run(main_async(case, s))
    finally:
        s.stop()


if __name__ == "__main__":
    main()
