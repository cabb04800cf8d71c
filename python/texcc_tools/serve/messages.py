"""The browser preview's message framing (scripts/serve.py, docs/live.md "Browser preview").

A page message is checked for its shape only: a JSON object of at most MAX_MESSAGE bytes, a
known type with exactly its keys, an integer id, strings that fit texrender's edit grammar. It
then becomes one control line for texrender (`ID set NODE.ARG=<JSON value>` or
`ID rewire NODE.ARG=SOURCE`); whether the node, the argument and the value are right is
texrender's to say (its live editor validates each edit once, as it applies it): this module
knows no graph and no types.
"""
import json

MAX_MESSAGE = 64 * 1024
# texrender ends its control session at a line over 64 KiB (docs/live.md, "Control channel");
# a value re-serialised can be longer than the message it came in ("1e15" -> 1000000000000000.0).
MAX_LINE = 60 * 1024
# How deep a value may nest: a ramp's stops are two levels; more is no edit texrender takes.
MAX_DEPTH = 8
ID_LIMIT = 2 ** 53
FIELDS = {"set": ("type", "id", "node", "arg", "value"),
          "rewire": ("type", "id", "node", "arg", "source")}


class Invalid(Exception):
    """A page message that is refused; its text goes back to the page."""


def _no_constant(name):
    raise Invalid(f"'{name}' is not a number JSON allows")


def _finite(text):
    v = float(text)
    if v in (float("inf"), float("-inf")):
        raise Invalid(f"'{text[:40]}' is out of the range of a double")
    return v


def _pairs(items):
    keys = [k for k, _ in items]
    if len(set(keys)) != len(keys):
        raise Invalid("duplicate key in message")
    return dict(items)


def _shown(value, limit=40):
    """A bounded excerpt of a JSON value, for messages."""
    text = json.dumps(value, ensure_ascii=True, default=str)
    return text if len(text) <= limit else text[:limit] + "..."


def depth(value):
    """How deeply VALUE nests (a number: 0, [] and [1, 2]: 1, [[1]]: 2), without recursion."""
    deepest, todo = 0, [(value, 0)]
    while todo:
        v, d = todo.pop()
        if isinstance(v, (list, dict)):
            deepest = max(deepest, d + 1)
            todo.extend((x, d + 1) for x in (v.values() if isinstance(v, dict) else v))
    return deepest


def _name(msg, key, dots):
    """A node id, argument or source name as texrender's edit grammar can carry it: a string of
    printable characters, no '=' (the grammar splits at the first) and, for an argument, no '.'
    (it splits NODE.ARG at the last dot, so a node id may hold dots)."""
    v = msg[key]
    if not isinstance(v, str):
        raise Invalid(f"'{key}' must be a string, not {type(v).__name__}")
    if not v or len(v) > 1024 or v != v.strip():
        raise Invalid(f"'{key}' must be 1 to 1024 characters without leading or trailing blanks")
    if any(ord(c) < 32 or ord(c) == 127 for c in v):
        raise Invalid(f"'{key}' holds a control character")
    if "=" in v or (not dots and "." in v):
        raise Invalid(f"'{key}' {_shown(v)} cannot hold {'=' if '=' in v else '.'}")
    return v


def parse_message(data):
    """The checked message (a dict) of one page message DATA (bytes), or Invalid."""
    if len(data) > MAX_MESSAGE:
        raise Invalid(f"message of {len(data)} bytes; at most {MAX_MESSAGE}")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise Invalid(f"message is not UTF-8 (byte {e.start})") from None
    try:
        msg = json.loads(text, parse_constant=_no_constant, parse_float=_finite,
                         object_pairs_hook=_pairs)
    except Invalid:
        raise
    except RecursionError:
        raise Invalid("malformed JSON: nested too deeply") from None
    except ValueError as e:  # JSONDecodeError, an integer of over 4300 digits
        if "digits" in str(e):
            raise Invalid("malformed JSON: an integer of more than 4300 digits") from None
        raise Invalid(f"malformed JSON: {str(e)[:120]}") from None
    if not isinstance(msg, dict):
        raise Invalid("a message must be a JSON object")
    kind = msg.get("type")
    if not isinstance(kind, str) or kind not in FIELDS:
        raise Invalid(f"unknown message type {_shown(kind)}; expected 'set' or 'rewire'")
    if set(msg) != set(FIELDS[kind]):
        missing, extra = set(FIELDS[kind]) - set(msg), set(msg) - set(FIELDS[kind])
        raise Invalid(f"'{kind}' message: missing {sorted(missing)}, unknown "
                      f"{sorted(k[:40] for k in extra)}")
    ident = msg["id"]
    if not isinstance(ident, int) or isinstance(ident, bool) or not 0 <= ident < ID_LIMIT:
        raise Invalid("'id' must be an integer in [0, 2^53)")
    _name(msg, "node", dots=True)
    _name(msg, "arg", dots=False)
    if kind == "rewire":
        _name(msg, "source", dots=True)
    elif depth(msg["value"]) > MAX_DEPTH:
        raise Invalid(f"'value' nests deeper than {MAX_DEPTH} levels")
    return msg


def control_line(msg):
    """(key, line) for texrender: KEY (node, arg) coalesces waiting edits of one argument;
    LINE is the edit without its id. The value is written as compact JSON, numbers as the
    shortest text that reads back as the same double."""
    target = f"{msg['node']}.{msg['arg']}"
    if msg["type"] == "rewire":
        line = f"rewire {target}={msg['source']}"
    else:
        line = f"set {target}=" + json.dumps(msg["value"], separators=(",", ":"),
                                             ensure_ascii=False, allow_nan=False)
    try:
        size = len(line.encode("utf-8"))
    except UnicodeEncodeError:
        raise Invalid("message holds a lone UTF-16 surrogate (not valid Unicode)") from None
    if size > MAX_LINE:
        raise Invalid(f"edit of {size} bytes as a control line; at most {MAX_LINE}")
    return (msg["node"], msg["arg"]), line
