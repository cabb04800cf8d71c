"""The browser preview's model of the graph (scripts/serve.py): what the page may edit, and the
strict check of every page message before it becomes a control line for texrender.

The argument types and defaults come from `texcc --list-nodes` (texcc's own reading of the
sources); slider ranges from the "range" column of the parameter table in each source's
header comment (docs/textures.md), where one is given.
"""
import json
import math
import re
import subprocess

MAX_ROWS = 256  # rows of a __global array (ramp stops) a page may send
ID_LIMIT = 2 ** 53
INT_LIMIT = 2 ** 31
VECTOR = {"float2": 2, "float3": 3, "float4": 4}
COLOUR_NAMES = re.compile(r"colou?r|tint|albedo|rgb", re.I)


class Invalid(Exception):
    """A page message that is refused; its text goes back to the page."""


def _no_constant(name):
    raise Invalid(f"'{name}' is not a number JSON allows")


def parse_message(data):
    """The JSON object of one page message (bytes), or Invalid. NaN and Infinity (which
    Python's json accepts) are refused, as are duplicate keys."""
    def pairs(items):
        keys = [k for k, _ in items]
        if len(set(keys)) != len(keys):
            raise Invalid("duplicate key in message")
        return dict(items)
    try:
        msg = json.loads(data.decode("utf-8"), parse_constant=_no_constant,
                         object_pairs_hook=pairs)
    except (UnicodeDecodeError, ValueError) as e:
        if isinstance(e, Invalid):
            raise
        raise Invalid(f"malformed JSON: {e}") from None
    if not isinstance(msg, dict):
        raise Invalid("a message must be a JSON object")
    kind = msg.get("type")
    fields = {"set": {"type", "id", "node", "arg", "value"},
              "rewire": {"type", "id", "node", "arg", "source"}}
    if kind not in fields:
        raise Invalid(f"unknown message type {kind!r}; expected 'set' or 'rewire'")
    if set(msg) != fields[kind]:
        missing, extra = fields[kind] - set(msg), set(msg) - fields[kind]
        raise Invalid(f"'{kind}' message: missing {sorted(missing)}, unknown {sorted(extra)}")
    if not is_int(msg["id"]) or not 0 <= msg["id"] < ID_LIMIT:
        raise Invalid("'id' must be an integer in [0, 2^53)")
    for key in ("node", "arg") + (("source",) if kind == "rewire" else ()):
        if not isinstance(msg[key], str):
            raise Invalid(f"'{key}' must be a string")
    return msg


def is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def is_number(v):
    return (is_int(v) or isinstance(v, float)) and math.isfinite(v)


def number_text(v):
    """VALUE as texrender's --set reads it: the shortest text that reads back as the same
    double (so a batch `--set` with this text renders the same image)."""
    return str(v) if is_int(v) else repr(float(v))


def parse_range(text):
    """'0..1' -> (0, 1); '> 0' -> (0, None); '0, 1, 2' -> (0, 2); anything else None."""
    t = text.strip().replace(" ", "")
    m = re.fullmatch(r"(-?\d+(?:\.\d*)?)\.\.(-?\d+(?:\.\d*)?)", t)
    if m:
        return float(m.group(1)), float(m.group(2))
    m = re.fullmatch(r">=?(-?\d+(?:\.\d*)?)", t)
    if m:
        return float(m.group(1)), None
    if re.fullmatch(r"-?\d+(,-?\d+)+", t):
        vals = [int(x) for x in t.split(",")]
        return float(min(vals)), float(max(vals))
    return None


def read_ranges(path):
    """{parameter name: (lo, hi)} from the parameter tables in PATH's comments."""
    ranges = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return ranges
    columns = None
    for line in lines:
        cells = [c.strip() for c in line.strip().lstrip("*/ ").strip().split("|")]
        if len(cells) < 3 or not line.strip().lstrip("*/ ").startswith("|"):
            columns = None
            continue
        cells = cells[1:-1]
        names = [c.lower() for c in cells]
        if "name" in names and "range" in names:
            columns = (names.index("name"), names.index("range"))
            continue
        if columns and max(columns) < len(cells) and not set(cells[0]) <= set("-: "):
            r = parse_range(cells[columns[1]])
            if r:
                ranges.setdefault(cells[columns[0]], r)
    return ranges


SIGNATURE = re.compile(r"^\s+(\S+)\s+(\w+)\((.*)\)\s*$")
PARAM = re.compile(r"^(.*?[\s*])(\w+)(?:\s*=\s*(\S+))?$")


def list_nodes(texcc, sources):
    """{fn: (file, [(name, type, default or None)])} from `texcc --list-nodes SOURCES`."""
    out = subprocess.run([texcc, "--list-nodes"] + list(sources), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, timeout=60)
    if out.returncode != 0:
        raise RuntimeError("texcc --list-nodes failed: " + out.stderr.strip())
    fns, current = {}, None
    for line in out.stdout.splitlines():
        if line and not line[0].isspace() and line.endswith(":"):
            current = line[:-1]
            continue
        m = SIGNATURE.match(line)
        if not m:
            continue
        params = []
        for p in filter(None, (x.strip() for x in m.group(3).split(","))):
            pm = PARAM.match(p)
            if pm:
                default = json.loads(pm.group(3)) if pm.group(3) else None
                params.append((pm.group(2), " ".join(pm.group(1).split()), default))
        fns[m.group(2)] = (current, params)
    return fns


def slider_range(rng, value):
    """(min, max) of a float slider: the documented range, else one around the value."""
    lo, hi = rng if rng else (None, None)
    v = value if is_number(value) else 0.0
    if lo is None:
        lo = 0.0 if v >= 0 else 2.0 * v
    if hi is None:
        hi = max(lo + 1.0, 2.0 * abs(v), 1.0)
    return min(lo, v), max(hi, v)


class Model:
    """The graph texrender renders, as the page sees it: nodes, their arguments' types and
    current values (the graph file with the edits texrender applied since)."""

    def __init__(self, graph_path, sources, texcc):
        self.graph_path, self.sources, self.texcc = graph_path, list(sources), texcc
        with open(graph_path, encoding="utf-8") as f:
            graph = json.load(f)
        self.nodes = {n["id"]: {"fn": n["fn"], "args": dict(n.get("args", {}))}
                      for n in graph.get("nodes", [])}
        self.materials = graph.get("materials", {})
        self.read_signatures()

    @classmethod
    def load(cls, graph_path, sources, texcc):
        return cls(graph_path, sources, texcc)

    def read_signatures(self):
        """Reads the sources' signatures and ranges; on an error (a source that does not
        compile) the previous ones stay and the error is raised."""
        functions = list_nodes(self.texcc, self.sources)
        ranges = {}
        for path, _ in functions.values():
            if path not in ranges:
                ranges[path] = read_ranges(path)
        self.functions, self.ranges = functions, ranges

    def param(self, node, arg):
        if node not in self.nodes:
            raise Invalid(f"unknown node '{node}'; the graph has {sorted(self.nodes)}")
        fn = self.nodes[node]["fn"]
        if fn not in self.functions:
            raise Invalid(f"node '{node}': function '{fn}' is not in the sources")
        params = self.functions[fn][1]
        for name, kind, default in params:
            if name == arg:
                return kind, default
        raise Invalid(f"node '{node}' ({fn}) has no argument '{arg}'; its arguments are "
                      f"{[p[0] for p in params]}")

    def check(self, msg):
        """(key, control line) for a parsed page message, or Invalid: the same rules as
        texrender's --set, checked here so that nothing refused reaches texrender."""
        node, arg = msg["node"], msg["arg"]
        kind, _ = self.param(node, arg)
        if msg["type"] == "rewire":
            src = msg["source"]
            if src not in self.nodes:
                raise Invalid(f"unknown source node '{src}'; the graph has {sorted(self.nodes)}")
            if src == node:
                raise Invalid(f"node '{node}' cannot feed itself")
            if kind == "sam2D" or kind.startswith("__global"):
                raise Invalid(f"argument '{arg}' ({kind}) cannot take a node")
            return (node, arg), f"rewire {node}.{arg}={src}"
        return (node, arg), f"set {node}.{arg}={self.value_text(arg, kind, msg['value'])}"

    def value_text(self, arg, kind, v):
        if kind == "float":
            if not is_number(v):
                raise Invalid(f"argument '{arg}' expects a finite number, got {json.dumps(v)[:40]}")
            return number_text(float(v))
        if kind == "int":
            if not is_int(v) or not -INT_LIMIT <= v < INT_LIMIT:
                raise Invalid(f"argument '{arg}' expects a 32-bit integer, got {json.dumps(v)[:40]}")
            return str(v)
        if kind in VECTOR:
            return self.row_text(arg, kind, v, VECTOR[kind])
        m = re.fullmatch(r"__global const (float[234]?)\*", kind)
        if m:
            width = VECTOR.get(m.group(1), 1)
            if not isinstance(v, list) or not 1 <= len(v) <= MAX_ROWS:
                raise Invalid(f"argument '{arg}' expects 1..{MAX_ROWS} rows")
            rows = [self.row_text(arg, m.group(1), r, width) if width > 1 else
                    self.value_text(arg, "float", r) for r in v]
            return "[" + ",".join(rows) + "]"
        raise Invalid(f"argument '{arg}' ({kind}) cannot be set from the page")

    def row_text(self, arg, kind, v, n):
        if not isinstance(v, list) or len(v) != n or not all(is_number(x) for x in v):
            raise Invalid(f"argument '{arg}' expects {kind}: {n} finite numbers")
        return "[" + ",".join(number_text(float(x)) for x in v) + "]"

    def applied(self, line):
        """Records an edit texrender applied; returns what changed, for the pages."""
        verb, rest = line.split(" ", 1)
        target, text = rest.split("=", 1)
        node, arg = target.split(".", 1)
        if verb == "rewire":
            self.nodes[node]["args"][arg] = {"node": text}
            return {"node": node, "arg": arg, "source": text}
        value = json.loads(text)
        self.nodes[node]["args"][arg] = value
        return {"node": node, "arg": arg, "value": value}

    def controls(self):
        """One entry per node: each argument with its type, its current value or link, and
        for floats the slider's range."""
        out = []
        for node_id, node in self.nodes.items():
            fn = node["fn"]
            path, params = self.functions.get(fn, (None, []))
            inputs = []
            for name, kind, default in params:
                inputs.append(self.control(name, kind, node["args"].get(name, default),
                                           self.ranges.get(path, {}).get(name)))
            out.append({"node": node_id, "fn": fn, "file": path, "inputs": inputs})
        return out

    def control(self, name, kind, value, rng):
        c = {"arg": name, "type": kind}
        if isinstance(value, dict) and "value" in value:
            value = value["value"]
        if isinstance(value, dict):
            for key in ("node", "attr", "image"):
                if key in value:
                    c.update(kind=key, source=value[key])
            return c
        c["value"] = value
        if kind == "float":
            c["kind"] = "float"
            c["min"], c["max"] = slider_range(rng, value)
        elif kind == "int":
            c["kind"] = "int"
            if rng:
                c["min"], c["max"] = rng[0], rng[1]
        elif kind == "float3" and COLOUR_NAMES.search(name) and isinstance(value, list) \
                and all(is_number(x) and 0 <= x <= 1 for x in value):
            c["kind"] = "color"
        elif kind in VECTOR:
            c["kind"] = "vector"
        elif kind.startswith("__global"):
            c["kind"] = "rows"
        else:
            c["kind"] = "fixed"
        return c

    def graph_for_page(self):
        nodes = [{"id": i, "fn": n["fn"],
                  "links": {a: v["node"] for a, v in n["args"].items()
                            if isinstance(v, dict) and "node" in v}}
                 for i, n in self.nodes.items()]
        used = {}
        for name, mat in self.materials.items():
            used[name] = sorted(set(re.findall(r'"node":\s*"([^"]+)"', json.dumps(mat))))
        return {"nodes": nodes, "materials": used}
