"""texrender --serve: the browser preview's front end (docs/live.md, "Browser preview").

  serve.py [--port P] [--listen ADDR] [--allow-host NAME] [--idle-timeout S] --texrender PATH
           -- SCENE --textures DIR [texrender options]

Runs `texrender SCENE ... --watch --control -o TMPDIR/frame.png` (docs/live.md, protocol B),
serves the page (scripts/serve/) over HTTP and a WebSocket at /ws, forwards every frame
texrender writes to every page, and turns the page's edit messages into texrender's control
lines after checking their framing (python/texcc_tools/serve/messages.py). texrender owns the graph, the edit
schema it sends in its 'ready' and 'reload' events, and the rules of every edit; this process
reads no user file, has no rendering code and no schema of its own.
"""
import argparse
import asyncio
import collections
import ipaddress
import json
import os
import secrets
import signal
import socket
import sys
import tempfile

from aiohttp import WSMsgType, web

# scripts/serve.sh runs this with .venv's Python, which has the package (scripts/setup.sh).
from texcc_tools.serve import messages

STATIC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "serve")
PAGE_FILES = {"/": ("index.html", "text/html"), "/app.js": ("app.js", "text/javascript"),
              "/style.css": ("style.css", "text/css")}
# A page message larger than messages.MAX_MESSAGE is answered with an error and dropped; one
# larger than WS_HARD_LIMIT closes that page's socket (aiohttp refuses to buffer it: code 1009).
MAX_MESSAGE = messages.MAX_MESSAGE
WS_HARD_LIMIT = 1024 * 1024
# texrender's events are read in chunks, not with asyncio's readline (whose limit ends the
# reader); one event longer than this is dropped with a line in the log. Its log (stderr) is
# copied chunk by chunk, whatever its line lengths.
MAX_EVENT = 256 * 1024 * 1024
READ_CHUNK = 64 * 1024
# The longest text of an error message sent to a page.
MAX_PAGE_TEXT = 16 * 1024
# Messages queued for one page. Its own messages' answers hold the reading of its socket at
# half of this (it waits until they are sent); a page that does not read what other pages'
# edits broadcast is disconnected at the limit. Frames are not queued: a page gets the newest.
MAX_OUTBOX = 256
CSP = ("default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' blob:; "
       "connect-src 'self' ws://{host}")


def log(message):
    print(f"serve: {message}", file=sys.stderr, flush=True)


class Page:
    """One connected browser page: its socket and what is waiting to be sent to it."""

    def __init__(self, ws):
        self.ws = ws
        self.outbox = collections.deque()
        self.frame = None  # (meta, png): replaced by a newer frame before it is sent
        self.wake = asyncio.Event()
        self.drained = asyncio.Event()
        self.closed = False

    def send(self, message):
        if self.closed:
            return
        if len(self.outbox) >= MAX_OUTBOX:
            log("a page does not read its messages: disconnecting it")
            self.closed = True
            asyncio.ensure_future(self.ws.close())
            return
        self.outbox.append(message)
        self.wake.set()

    async def backlog(self):
        """Waits while this page's answers are piling up (it sends faster than it reads)."""
        while len(self.outbox) >= MAX_OUTBOX // 2 and not self.closed:
            self.drained.clear()
            await self.drained.wait()

    def send_frame(self, meta, png):
        self.frame = (meta, png)
        self.wake.set()

    async def pump(self):
        try:
            while not self.closed:
                await self.wake.wait()
                self.wake.clear()
                while self.outbox:
                    await self.ws.send_str(json.dumps(self.outbox.popleft()))
                self.drained.set()
                if self.frame is not None:
                    (meta, png), self.frame = self.frame, None
                    await self.ws.send_str(json.dumps(meta))
                    await self.ws.send_bytes(png)
        except (ConnectionError, RuntimeError):
            pass  # the page went away mid-send: its reading side ends too
        finally:
            self.closed = True
            self.drained.set()
            if not self.ws.closed:
                await self.ws.close()


class Edits:
    """The edits waiting for texrender: at most one in flight; the others wait keyed by
    NODE.ARG, so a newer edit of the same argument replaces an older one (a burst of slider
    moves collapses to the latest). The number waiting is bounded by the graph's arguments."""

    def __init__(self, write_line):
        self.write_line = write_line
        self.waiting = {}  # key -> (line, page, page id, coalesced count)
        self.in_flight = None  # server id
        self.owners = {}  # server id -> (page, page id, line, coalesced count)
        self.next_id = 1

    def submit(self, key, line, page, page_id):
        old = self.waiting.pop(key, None)
        coalesced = old[3] + 1 if old else 0
        self.waiting[key] = (line, page, page_id, coalesced)
        self.pump()

    def pump(self):
        if self.in_flight is not None or not self.waiting:
            return
        key = next(iter(self.waiting))
        line, page, page_id, coalesced = self.waiting.pop(key)
        sid = self.next_id
        self.next_id += 1
        self.owners[sid] = (page, page_id, line, coalesced)
        self.in_flight = sid
        self.write_line(f"{sid} {line}")

    def answered(self, sid):
        """texrender answered edit SID: returns its owner, lets the next edit go."""
        owner = self.owners.pop(sid, None)
        if sid == self.in_flight:
            self.in_flight = None
            self.pump()
        return owner

    def drop_page(self, page):
        for key in [k for k, v in self.waiting.items() if v[1] is page]:
            del self.waiting[key]


def bounded(text, limit=MAX_PAGE_TEXT):
    """TEXT, or its first LIMIT characters and how much was left out (a page gets no message
    of megabytes: texrender quoting a huge input, say)."""
    return text if len(text) <= limit else text[:limit] + f"... ({len(text) - limit} more characters)"


async def stream_lines(stream, limit, on_too_long):
    """The lines of STREAM (bytes, without the newline), read in chunks: a line longer than
    LIMIT is skipped (ON_TOO_LONG(size) says so) instead of ending the reader."""
    buf, skipped = bytearray(), 0
    while True:
        chunk = await stream.read(READ_CHUNK)
        if not chunk:
            return
        start = 0
        while True:
            nl = chunk.find(b"\n", start)
            piece = chunk[start:] if nl < 0 else chunk[start:nl]
            if skipped:
                skipped += len(piece)
            else:
                buf += piece
                if len(buf) > limit:
                    skipped = len(buf)
                    buf.clear()
            if nl < 0:
                break
            if skipped:
                on_too_long(skipped)
                skipped = 0
            else:
                yield bytes(buf)
            buf.clear()
            start = nl + 1


class Server:
    """texrender's process, the edit schema it sent last and the connected pages."""

    def __init__(self, opts, tmpdir):
        self.opts = opts
        self.frame_path = os.path.join(tmpdir, "frame.png")
        self.pages = set()
        self.proc = None
        self.ready = None  # texrender's ready event (size, sources)
        self.schema = None  # the edit schema of the last ready/reload, with the edits since
        self.last_error = None  # the last failed file change, until a reload
        self.last_frame = None
        self.last_edit = None  # (server id, page, page id) of the last applied edit
        self.edits = Edits(self.write_line)
        self.exit_code = None
        self.done = asyncio.Event()

    async def start(self):
        cmd = [self.opts.texrender] + self.opts.render_args + [
            "--watch", "--control", "-o", self.frame_path]
        log("runs " + " ".join(cmd))
        self.proc = await asyncio.create_subprocess_exec(
            *cmd, stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE,
            stderr=asyncio.subprocess.PIPE)
        asyncio.ensure_future(self.read_events())
        asyncio.ensure_future(self.read_log())

    def write_line(self, line):
        if self.proc and self.proc.returncode is None and not self.proc.stdin.is_closing():
            self.proc.stdin.write((line + "\n").encode())

    async def read_log(self):
        out = sys.stderr.buffer
        while True:
            chunk = await self.proc.stderr.read(READ_CHUNK)
            if not chunk:
                return
            out.write(chunk)
            out.flush()

    async def read_events(self):
        def too_long(size):
            log(f"texrender wrote an event of {size} bytes (over {MAX_EVENT}): dropped")
        async for raw in stream_lines(self.proc.stdout, MAX_EVENT, too_long):
            try:
                event = json.loads(raw)
                if not isinstance(event, dict):
                    raise ValueError("not a JSON object")
            except (ValueError, RecursionError):
                log("texrender wrote a line that is not a JSON object: "
                    + raw[:200].decode(errors="replace"))
                continue
            try:
                await self.on_event(event)
            except Exception as e:  # a bad event must not end the preview: every page hears
                kind = str(event.get("event"))[:40]
                log(f"event {kind!r} not handled: {e!r}")
                self.broadcast({"type": "error", "id": None,
                                "message": f"serve.py could not handle texrender's {kind!r} "
                                           f"event: {e!r}"[:2000]})
        self.exit_code = await self.proc.wait()
        log(f"texrender ended (exit {self.exit_code})")
        self.broadcast({"type": "error", "id": None,
                        "message": f"texrender ended (exit {self.exit_code})"})
        await asyncio.sleep(0.2)  # lets the pages receive it
        self.done.set()

    async def on_event(self, event):
        kind = event.get("event")
        if kind in ("ready", "reload"):
            schema = event.get("schema")
            if not isinstance(schema, dict) or not isinstance(schema.get("nodes"), list):
                raise ValueError(f"texrender's {kind!r} event has no edit schema")
            if kind == "ready":
                self.ready = event
            self.schema = schema
            if event.get("what") != "restore":  # a fault's error stays while its state is undone
                self.last_error = None
            for page in self.pages:
                page.send(self.hello())
        elif kind == "frame":
            self.on_frame(event)
        elif kind in ("applied", "error"):
            self.on_answer(kind, event)

    def on_frame(self, event):
        try:
            with open(self.frame_path, "rb") as f:
                png = f.read()
        except OSError as e:
            log(f"frame {self.frame_path!r} not readable: {e}")
            return
        self.last_frame = event
        edit = event.get("edit")
        origin = self.last_edit if self.last_edit and self.last_edit[0] == edit else None
        for page in self.pages:
            meta = {"type": "frame", "spp": event.get("spp"), "tier": event.get("tier"),
                    "builds": event.get("builds"), "latency_ms": event.get("latency_ms"),
                    "edit": origin[2] if origin and origin[1] is page else None,
                    "size": len(png), "width": event.get("width"),
                    "height": event.get("height"), "reduced": bool(event.get("reduced")),
                    "factor": event.get("factor", 1)}
            page.send_frame(meta, png)

    def on_answer(self, kind, event):
        sid = event.get("id")
        if sid is None:  # a watched file failed to compile: every page shows it
            self.last_error = bounded(str(event.get("message", "")))
            self.broadcast({"type": "error", "id": None, "message": self.last_error})
            return
        owner = self.edits.answered(sid)
        if owner is None:
            return
        page, page_id, line, coalesced = owner
        if kind == "error":
            if page in self.pages:
                page.send({"type": "error", "id": page_id, "coalesced": coalesced,
                           "message": bounded(str(event.get("message", "")))})
            return
        self.last_edit = (sid, page, page_id)
        # What changed, as texrender parsed it: node ids may hold dots, so nothing is split here.
        change = {k: event[k] for k in ("node", "arg", "value", "source") if k in event}
        self.record(change.get("node"), event.get("input"))
        for other in self.pages:
            other.send(dict(change, type="applied", id=page_id if other is page else None,
                            ms=event.get("ms"), builds=event.get("builds"), coalesced=coalesced))

    def record(self, node_id, entry):
        """Keeps the schema up to date for pages that connect later: the edited input's entry,
        as texrender's 'applied' event gives it, replaces the old one (no edit is re-applied
        here)."""
        if not isinstance(entry, dict):
            return
        for node in self.schema.get("nodes", []) if self.schema else []:
            if node.get("id") == node_id:
                puts = node.get("inputs", [])
                for i, put in enumerate(puts):
                    if put.get("name") == entry.get("name"):
                        puts[i] = entry

    def broadcast(self, message):
        for page in self.pages:
            page.send(message)

    def hello(self):
        r = self.ready or {}
        return {"type": "hello", "schema": self.schema, "sources": r.get("sources", []),
                "width": r.get("width"), "height": r.get("height"), "error": self.last_error}

    def on_message(self, page, data):
        """One page message: its framing checked, then queued for texrender, or answered with
        an error. Any failure here is an error to that page, never a closed socket."""
        msg = None
        try:
            msg = messages.parse_message(data)
            if self.schema is None:
                raise messages.Invalid("texrender is not ready yet")
            key, line = messages.control_line(msg)
        except messages.Invalid as e:
            page.send({"type": "error", "id": msg.get("id") if msg else None,
                       "message": str(e)})
            return
        except Exception as e:  # a bug of this process: the page hears of it, the server serves on
            log(f"a page message was not handled: {e!r}")
            page.send({"type": "error", "id": None,
                       "message": f"serve.py could not handle the message: {e!r}"[:2000]})
            return
        self.edits.submit(key, line, page, msg["id"])

    async def quit(self):
        if self.proc and self.proc.returncode is None:
            self.write_line("quit")
            for stop in (None, self.proc.terminate, self.proc.kill):
                if stop:
                    log(f"texrender does not end: {stop.__name__}")
                    stop()
                try:
                    await asyncio.wait_for(self.proc.wait(), 5)
                    return
                except asyncio.TimeoutError:
                    pass


def is_loopback(listen):
    try:
        return ipaddress.ip_address(listen).is_loopback
    except ValueError:
        return listen == "localhost"


def allowed_hosts(listen, port, extra):
    """The Host values this server answers to: its port on the loopback names, on the address
    it listens on, and on the names given with --allow-host. Anything else is DNS rebinding or
    a misdirected request."""
    names = {"localhost", "127.0.0.1", "[::1]"} | set(extra)
    if listen not in ("0.0.0.0", "::"):
        names.add(f"[{listen}]" if ":" in listen else listen)
    return {f"{n.lower()}:{port}" for n in names}


def make_app(server, hosts, token, idle_timeout):
    @web.middleware
    async def guard(request, handler):
        host = request.headers.get("Host", "").lower()
        origin = request.headers.get("Origin")
        if host not in hosts:
            log(f"refused a request for Host {host[:80]!r}")
            return web.Response(status=403, text="403: unknown Host\n")
        if origin is not None and origin.lower() not in {"http://" + h for h in hosts}:
            log(f"refused a request from Origin {origin[:80]!r}")
            return web.Response(status=403, text="403: foreign Origin\n")
        # Off loopback the page and its WebSocket need the token printed at the start (the
        # page's script and style sheet hold nothing of the session).
        if token is not None and request.path in ("/", "/ws") and not secrets.compare_digest(
                request.query.get("token", "").encode(), token.encode()):
            log(f"refused a request for {request.path} without the token")
            return web.Response(status=403, text="403: this preview needs its token "
                                                  "(?token=..., printed when it started)\n")
        response = await handler(request)
        if not isinstance(response, web.WebSocketResponse):
            response.headers["Content-Security-Policy"] = CSP.format(host=host)
            response.headers["X-Frame-Options"] = "DENY"
            response.headers["X-Content-Type-Options"] = "nosniff"
            response.headers["Cache-Control"] = "no-store"
            response.headers["Referrer-Policy"] = "no-referrer"
        return response

    async def static(request):
        name, kind = PAGE_FILES[request.path]
        with open(os.path.join(STATIC, name), "rb") as f:
            return web.Response(body=f.read(), content_type=kind, charset="utf-8")

    async def no_icon(request):
        return web.Response(status=204)

    async def websocket(request):
        # heartbeat: a page that answers no ping for idle_timeout seconds is closed.
        ws = web.WebSocketResponse(max_msg_size=WS_HARD_LIMIT, heartbeat=idle_timeout)
        await ws.prepare(request)
        await serve_page(server, ws)
        return ws

    app = web.Application(middlewares=[guard], client_max_size=MAX_MESSAGE)
    for path in PAGE_FILES:
        app.router.add_get(path, static)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/favicon.ico", no_icon)
    return app


async def serve_page(server, ws):
    page = Page(ws)
    server.pages.add(page)
    pump = asyncio.ensure_future(page.pump())
    if server.schema is not None:
        page.send(server.hello())
        if server.last_frame is not None:
            server.on_frame(server.last_frame)
    try:
        async for msg in ws:
            if msg.type == WSMsgType.TEXT:
                server.on_message(page, msg.data.encode("utf-8"))
                await page.backlog()
            elif msg.type == WSMsgType.BINARY:
                page.send({"type": "error", "id": None,
                           "message": "binary messages are not accepted"})
            elif msg.type == WSMsgType.ERROR:
                break
    except (ConnectionError, asyncio.CancelledError):
        pass
    finally:
        page.closed = True
        page.wake.set()
        server.pages.discard(page)
        server.edits.drop_page(page)
        pump.cancel()


class IdleGuard(asyncio.Protocol):
    """aiohttp's connection handler, closed once it has received nothing for IDLE seconds: a
    connection opened and left silent, a request never finished, a keep-alive connection
    forgotten. A page's WebSocket answers the server's pings (every idle_timeout seconds),
    which keeps it open while the page lives."""

    def __init__(self, inner, idle):
        self.inner, self.idle = inner, idle
        self.transport = self.timer = None

    def arm(self):
        if self.timer:
            self.timer.cancel()
        self.timer = asyncio.get_running_loop().call_later(self.idle, self.transport.close)

    def connection_made(self, transport):
        self.transport = transport
        self.inner.connection_made(transport)
        self.arm()

    def data_received(self, data):
        self.arm()
        self.inner.data_received(data)

    def eof_received(self):
        return self.inner.eof_received()

    def connection_lost(self, exc):
        if self.timer:
            self.timer.cancel()
        self.inner.connection_lost(exc)

    def pause_writing(self):
        self.inner.pause_writing()

    def resume_writing(self):
        self.inner.resume_writing()


def listening_socket(listen, port):
    family = socket.AF_INET6 if ":" in listen else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind((listen, port))
    sock.listen(64)
    sock.setblocking(False)
    return sock


async def run(opts):
    with tempfile.TemporaryDirectory(prefix="texrender-serve-") as tmpdir:
        server = Server(opts, tmpdir)
        sock = listening_socket(opts.listen, opts.port)
        port = sock.getsockname()[1]
        token = None if is_loopback(opts.listen) else secrets.token_urlsafe(24)
        app = make_app(server, allowed_hosts(opts.listen, port, opts.allow_host), token,
                       opts.idle_timeout)
        # keepalive_timeout: an HTTP connection idle this long between requests is closed;
        # IdleGuard: any connection that sends nothing for 3 ping intervals.
        runner = web.AppRunner(app, access_log=None, keepalive_timeout=opts.idle_timeout)
        await runner.setup()
        listener = await asyncio.get_running_loop().create_server(
            lambda: IdleGuard(runner.server(), 3 * opts.idle_timeout), sock=sock)
        host = f"[{opts.listen}]" if ":" in opts.listen else opts.listen
        if opts.listen in ("0.0.0.0", "::"):
            host = "127.0.0.1"
        if token is None:
            log(f"preview at http://{host}:{port}/ (Ctrl-C ends)")
        else:
            log(f"warning: listening on {opts.listen}, not loopback: anyone who can reach "
                f"port {port} and has the token can edit the graph and see the renders")
            log(f"preview at http://{host}:{port}/?token={token} (Ctrl-C ends; the page and "
                f"its WebSocket need this token)")
        await server.start()
        loop = asyncio.get_running_loop()
        stop = asyncio.Event()
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(sig, stop.set)
        waiters = [asyncio.ensure_future(stop.wait()), asyncio.ensure_future(server.done.wait())]
        await asyncio.wait(waiters, return_when=asyncio.FIRST_COMPLETED)
        await server.quit()
        # Open pages are told the server is going away; aiohttp's cleanup would otherwise wait
        # for their sockets (up to a minute).
        for page in list(server.pages):
            page.closed = True
            await page.ws.close(code=1001, message=b"the preview server ends")
        listener.close()
        await runner.cleanup()
        # Ctrl-C in a terminal reaches texrender too: it ends with 130 after writing its image.
        if stop.is_set() or server.exit_code in (0, 130, 143):
            return 0
        return 1


def parse_args(argv):
    if "--" not in argv:
        sys.exit("serve: usage: serve.py [--port P] [--listen ADDR] --texrender PATH -- SCENE "
                 "--textures DIR [texrender options]")
    cut = argv.index("--")
    p = argparse.ArgumentParser(prog="serve.py")
    p.add_argument("--port", type=int, default=8642, help="0: any free port")
    p.add_argument("--listen", default="127.0.0.1",
                   help="address to listen on (default loopback only; any other address needs "
                        "the token printed at the start)")
    p.add_argument("--allow-host", action="append", default=[],
                   help="another host name the page may be opened under (with --listen)")
    p.add_argument("--idle-timeout", type=float, default=30.0,
                   help="seconds after which an idle HTTP connection, or a page that answers "
                        "no WebSocket ping, is closed (default 30)")
    p.add_argument("--texrender", required=True)
    p.add_argument("--texcc", help="accepted for older callers; unused (texrender runs texcc)")
    opts = p.parse_args(argv[:cut])
    if not opts.idle_timeout > 0:
        p.error("--idle-timeout must be a positive number of seconds")
    opts.render_args = argv[cut + 1:]
    return opts


def main():
    opts = parse_args(sys.argv[1:])
    try:
        sys.exit(asyncio.run(run(opts)))
    except OSError as e:
        sys.exit(f"serve: error: {e}")


if __name__ == "__main__":
    main()
