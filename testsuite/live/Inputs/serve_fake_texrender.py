#!/usr/bin/env python3
"""A stand-in for `texrender ... --watch --control -o OUT` (docs/live.md, protocol B) for the
browser preview's safety tests, which need no renderer: it announces the graph of
--textures DIR/layout.json, accepts every control line (`ID set|rewire NODE.ARG=...`) with an
"applied" event (except a rewire onto node 'o', refused with an "error" event as texrender
refuses a type mismatch), and writes a tiny PNG frame every 50 ms.

Every control line it reads is appended to $SERVE_FAKE_LOG (the tests read what reached
"texrender"); $SERVE_FAKE_DELAY_MS delays each answer (so that a burst finds an edit in flight).
"""
import json
import os
import select
import struct
import sys
import time
import zlib


def png(rgb):
    """A 2x2 PNG of one colour."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    rows = b"".join(b"\0" + bytes(rgb) * 2 for _ in range(2))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def emit(event):
    sys.stdout.write(json.dumps(event) + "\n")
    sys.stdout.flush()


def main():
    args = sys.argv[1:]
    textures = args[args.index("--textures") + 1]
    out = args[args.index("-o") + 1]
    with open(os.path.join(textures, "layout.json")) as f:
        graph = json.load(f)["graph"]
    with open(graph) as f:
        sources = [os.path.join(os.path.dirname(graph), s) for s in json.load(f)["sources"]]
    log = os.environ.get("SERVE_FAKE_LOG")
    delay = float(os.environ.get("SERVE_FAKE_DELAY_MS", "0")) / 1000
    emit({"event": "ready", "graph": graph, "sources": sources, "width": 2, "height": 2})
    applied, spp = None, 0
    while True:
        ready, _, _ = select.select([sys.stdin], [], [], 0.05)
        if ready:
            line = sys.stdin.readline()
            if not line or line.strip() == "quit":
                return
            if log:
                with open(log, "a") as f:
                    f.write(line)
            sid, edit = line.strip().split(" ", 1)
            time.sleep(delay)
            if edit.endswith("=o"):  # as texrender refuses an edit its own checks reject
                emit({"event": "error", "id": int(sid),
                      "message": f"edit '{edit}': node 'o' returns float, not float3"})
                continue
            emit({"event": "applied", "id": int(sid), "ms": 0.1, "builds": 0})
            applied, spp = int(sid), 0
        spp += 1
        with open(out + ".tmp", "wb") as f:
            f.write(png(((applied or 0) % 256, spp % 256, 7)))
        os.replace(out + ".tmp", out)
        emit({"event": "frame", "path": out, "spp": spp, "tier": "interp", "builds": 0,
              "edit": applied, "latency_ms": 1.0 if spp == 1 and applied else None})


if __name__ == "__main__":
    main()
