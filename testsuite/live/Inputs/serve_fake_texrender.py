#!/usr/bin/env python3
"""A stand-in for `texrender ... --watch --control -o OUT` (docs/live.md, protocol B) for the
browser preview's framing and safety tests, which need no renderer: it announces an edit
schema of the graph next to the scene (graph.json: its nodes and arguments; each parameter's
type, default, range and doc from `$SERVE_FAKE_TEXCC --list-nodes --json` on its sources when
that is set, else guessed from the values; the real texrender takes them from layout.json), accepts every control line
(`ID set|rewire NODE.ARG=...`, split as texrender's parseEdit splits it: NODE.ARG at the last
dot) with an "applied" event carrying node, arg and the value or source (except a rewire onto
node 'o', refused with an "error" event as texrender refuses a type mismatch), and writes a
tiny PNG frame every 50 ms. $SERVE_FAKE_BROKEN_SCHEMA makes the first node's inputs a number;
$SERVE_FAKE_HUGE_LINES writes a 10 MiB line to stderr and a 10 MiB error event first.

Every control line it reads is appended to $SERVE_FAKE_LOG (the tests read what reached
"texrender"); $SERVE_FAKE_HOLD names a file: each answer waits until it exists (so that a burst finds an
edit in flight, whatever the machine's speed).
"""
import json
import os
import select
import struct
import subprocess
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


def documented(graph, folder):
    """{fn: {param: texcc's --list-nodes --json entry}} of the graph's sources, when
    $SERVE_FAKE_TEXCC names texcc (the real texrender has these from layout.json)."""
    texcc = os.environ.get("SERVE_FAKE_TEXCC")
    if not texcc:
        return {}
    files = [os.path.join(folder, s) for s in graph["sources"]]
    out = subprocess.run([texcc, "--list-nodes", "--json"] + files, stdout=subprocess.PIPE,
                         check=True, text=True).stdout
    return {fn["name"]: {p["name"]: p for p in fn["params"]}
            for entry in json.loads(out)["files"] for fn in entry["functions"]}


def schema_of(graph, folder):
    """A schema of the shape texrender sends (WatchSchema.cpp) for GRAPH's nodes."""
    docs = documented(graph, folder)
    def input_of(fn, name, arg):
        put = {"name": name}
        if isinstance(arg, dict):
            put.update({k: arg[k] for k in ("node", "attr", "image") if k in arg})
            put["type"] = "float3"
        elif isinstance(arg, list):
            put.update(value=arg, type=f"float{len(arg)}" if len(arg) > 1 else "float")
        else:
            put.update(value=arg, type="int" if name == "octaves" else "float")
        doc = docs.get(fn, {}).get(name, {})
        put.update({k: v for k, v in doc.items() if k != "text"})
        if "text" in doc:
            put["doc"] = doc["text"]
        return put
    nodes = [{"id": n["id"], "fn": n["fn"], "file": "tex.cl",
              "inputs": [input_of(n["fn"], k, v) for k, v in n.get("args", {}).items()]}
             for n in graph["nodes"]]
    if os.environ.get("SERVE_FAKE_BROKEN_SCHEMA"):  # a schema the page's script chokes on
        nodes[0]["inputs"] = 7
    return {"nodes": nodes, "materials": {}}


def main():
    args = sys.argv[1:]
    scene = args[0]
    folder = os.path.dirname(os.path.abspath(scene))
    with open(os.path.join(folder, "graph.json")) as f:
        graph = json.load(f)
    out = args[args.index("-o") + 1]
    log = os.environ.get("SERVE_FAKE_LOG")
    hold = os.environ.get("SERVE_FAKE_HOLD")
    schema = schema_of(graph, folder)
    emit({"event": "ready", "graph": "graph.json", "sources": graph["sources"], "width": 2,
          "height": 2, "schema": schema})
    if os.environ.get("SERVE_FAKE_HUGE_LINES"):  # as texrender once quoted a 10 MB graph
        sys.stderr.write("texrender: error: " + "x" * (10 << 20) + "\n")
        sys.stderr.flush()
        emit({"event": "error", "message": "graph.json: error: " + "y" * (10 << 20)})
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
            while hold and not os.path.exists(hold):  # the client says when to answer
                time.sleep(0.005)
            if edit.endswith("=o"):  # as texrender refuses an edit its own checks reject
                emit({"event": "error", "id": int(sid),
                      "message": f"edit '{edit}': node 'o' returns float, not float3"})
                continue
            try:
                verb, rest = edit.split(" ", 1)
                target, value = rest.split("=", 1)
                node, arg = target.rsplit(".", 1)
                change = {"source": value} if verb == "rewire" else {"value": json.loads(value)}
            except ValueError as e:  # texrender answers a line it cannot read with an error
                emit({"event": "error", "id": int(sid), "message": f"bad edit '{edit}': {e}"})
                continue
            # The input's new schema entry, as texrender's 'applied' event carries it.
            entry = None
            for n in schema["nodes"] if isinstance(schema["nodes"], list) else []:
                for put in n["inputs"] if n["id"] == node and isinstance(n["inputs"], list) else []:
                    if put["name"] == arg:
                        entry = {k: v for k, v in put.items()
                                 if k not in ("value", "node", "attr", "image")}
                        entry.update({"node": value} if verb == "rewire" else change)
            emit(dict({"event": "applied", "id": int(sid), "ms": 0.1, "builds": 0,
                       "node": node, "arg": arg, "input": entry}, **change))
            applied, spp = int(sid), 0
        spp += 1
        with open(out + ".tmp", "wb") as f:
            f.write(png(((applied or 0) % 256, spp % 256, 7)))
        os.replace(out + ".tmp", out)
        emit({"event": "frame", "path": out, "spp": spp, "tier": "interp", "builds": 0,
              "edit": applied, "latency_ms": 1.0 if spp == 1 and applied else None})


if __name__ == "__main__":
    main()
