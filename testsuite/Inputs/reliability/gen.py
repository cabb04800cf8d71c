"""Generates the large or pathological inputs of the reliability corpus in a test's RUN line,
so that no huge file is committed. Graphs use the textures of tex.cl.

  gen.py chain N OUT.json     a chain of N add nodes, each reading the previous one
  gen.py tree N OUT.json      about N add nodes: a balanced binary sum tree
  gen.py lattice D OUT.json   D levels of two nodes, each reading both nodes of the level below
                              (2^D paths from the top: catches traversals without memoization)
  gen.py cycle N OUT.json     a cycle of N nodes
  gen.py params N DIR         DIR/params.cl (a texture with N float parameters), DIR/graph.json
  gen.py macro-deep N OUT.cl  a macro defined through N levels of other macros
  gen.py macro-huge N OUT.cl  a macro whose expansion doubles N times (2^N tokens)
  gen.py nested N OUT.json    a graph whose "nodes" value is N nested arrays
  gen.py node FN OUT.json     one node calling FN(x = 1), the color of material m
  gen.py functions N DIR      DIR/funcs.cl (N helpers, each calling the one before, about 50 bytes
                              each) and DIR/graph.json (one node calling the texture 'top')
  gen.py materials N OUT.json N materials, each a diffuse BSDF whose color is its own add node
"""
import json
import os
import sys

# The chain is the stack-sizing tests' own (same add(a, b) signature as tex.cl's).
from texcc_tools.testing.gen_graph import chain


def material(root):
    return {"m": {"bsdf": "emission", "color": 1.0, "strength": {"node": root}}}


def write_graph(path, nodes, root):
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"texcc": 1, "nodes": nodes, "materials": material(root)}, f, indent=0)


def tree(n):
    # Leaves first, then each level sums pairs of the level below (an odd one is carried up).
    level = [f"l{i}" for i in range((n + 1) // 2)]
    nodes = [{"id": l, "fn": "add", "args": {"a": float(i), "b": 0.0}} for i, l in enumerate(level)]
    while len(level) > 1:
        up = []
        for i in range(0, len(level) - 1, 2):
            ident = f"s{len(nodes)}"
            nodes.append({"id": ident, "fn": "add",
                          "args": {"a": {"node": level[i]}, "b": {"node": level[i + 1]}}})
            up.append(ident)
        if len(level) % 2:
            up.append(level[-1])
        level = up
    return nodes, level[0]


def lattice(depth):
    nodes = [{"id": "a0", "fn": "add", "args": {"a": 1.0, "b": 0.0}},
             {"id": "b0", "fn": "add", "args": {"a": 0.0, "b": 1.0}}]
    for d in range(1, depth):
        below = {"a": {"node": f"a{d-1}"}, "b": {"node": f"b{d-1}"}}
        nodes.append({"id": f"a{d}", "fn": "add", "args": dict(below)})
        nodes.append({"id": f"b{d}", "fn": "add", "args": {"a": below["b"], "b": below["a"]}})
    return nodes, f"a{depth-1}"


def cycle(n):
    nodes = [{"id": f"c{i}", "fn": "add", "args": {"a": {"node": f"c{(i + 1) % n}"}, "b": 1.0}}
             for i in range(n)]
    return nodes, "c0"


def params(n, folder):
    os.makedirs(folder, exist_ok=True)
    names = [f"p{i}" for i in range(n)]
    with open(os.path.join(folder, "params.cl"), "w") as f:
        f.write(f"/* params.cl: a texture with {n} float parameters, their sum. */\n")
        f.write("float wide(" + ", ".join(f"float {p}" for p in names) + ") {\n")
        f.write("  return " + " + ".join(names) + ";\n}\n")
    nodes = [{"id": "w", "fn": "wide", "args": {p: 0.01 for p in names}}]
    with open(os.path.join(folder, "graph.json"), "w") as f:
        json.dump({"texcc": 1, "sources": ["params.cl"], "nodes": nodes,
                   "materials": material("w")}, f, indent=1)


def macro_deep(n):
    lines = ["#define M0(x) (x)"]
    lines += [f"#define M{i}(x) M{i-1}(x)" for i in range(1, n)]
    return "\n".join(lines) + f"\nfloat deep(float x) {{ return M{n-1}(x); }}\n"


def macro_huge(n):
    lines = ["#define E0 1.0f"]
    lines += [f"#define E{i} E{i-1} + E{i-1}" for i in range(1, n + 1)]
    return "\n".join(lines) + f"\nfloat huge(float x) {{ return x + E{n}; }}\n"


def nested(n):
    return '{"texcc": 1, "nodes": ' + "[" * n + "]" * n + ', "materials": {}}\n'


def node(fn):
    return json.dumps({"texcc": 1, "nodes": [{"id": "a", "fn": fn, "args": {"x": 1}}],
                       "materials": {"m": {"bsdf": "diffuse", "color": {"node": "a"}}}}) + "\n"


def functions(n, folder):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "funcs.cl"), "w") as f:
        f.write(f"/* funcs.cl: {n} helper functions, each calling the one before. */\n")
        f.write("float h0(float x) { return x; }\n")
        for i in range(1, n):
            f.write(f"float h{i}(float x) {{ return h{i - 1}(x) * 0.5f; }}\n")
        f.write(f"float top(float x) {{ return h{n - 1}(x); }}\n")
    nodes = [{"id": "t", "fn": "top", "args": {"x": 1.0}}]
    with open(os.path.join(folder, "graph.json"), "w") as f:
        json.dump({"texcc": 1, "sources": ["funcs.cl"], "nodes": nodes,
                   "materials": material("t")}, f, indent=1)


def materials(n):
    nodes = [{"id": f"n{i}", "fn": "add", "args": {"a": float(i), "b": 0.5}}
             for i in range(n)]
    mats = {f"m{i}": {"bsdf": "diffuse", "color": {"node": f"n{i}"}} for i in range(n)}
    return {"texcc": 1, "nodes": nodes, "materials": mats}


def main():
    kind, size, out = sys.argv[1], sys.argv[2], sys.argv[3]
    if kind == "node":
        with open(out, "w") as f:
            f.write(node(size))
        return
    size = int(size)
    if kind == "functions":
        functions(size, out)
        return
    if kind == "materials":
        with open(out, "w", encoding="utf-8") as f:
            json.dump(materials(size), f, indent=0)
        return
    graphs = {"chain": chain, "tree": tree, "lattice": lattice, "cycle": cycle}
    if kind in graphs:
        write_graph(out, *graphs[kind](size))
    elif kind == "params":
        params(size, out)
    elif kind == "nested":
        with open(out, "w") as f:
            f.write(nested(size))
    elif kind in ("macro-deep", "macro-huge"):
        with open(out, "w") as f:
            f.write((macro_deep if kind == "macro-deep" else macro_huge)(size))
    else:
        sys.exit(f"gen.py: unknown kind '{kind}'")


if __name__ == "__main__":
    main()
