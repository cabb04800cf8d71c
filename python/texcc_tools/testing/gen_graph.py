"""Writes large graph.json files for the stack-sizing tests (signatures: sigs.json).

  gen_graph.py chain N    a chain of N nodes: leaf <- neg <- neg ...   (needs 1 slot)
  gen_graph.py tree D     a balanced binary tree of add nodes, depth D  (needs D+1 slots)
"""
import json
import sys


def chain(n):
    nodes = [{"id": "n0", "fn": "add", "args": {"a": 0.0, "b": 1.0}}]
    for i in range(1, n):
        nodes.append({"id": f"n{i}", "fn": "add", "args": {"a": {"node": f"n{i-1}"}, "b": 1.0}})
    return nodes, f"n{n-1}"


def tree(depth):
    nodes, leaves = [], [0]

    def build(level, ident):
        if level == depth:
            nodes.append({"id": ident, "fn": "add", "args": {"a": float(leaves[0]), "b": 0.0}})
            leaves[0] += 1
        else:
            build(level + 1, ident + "a")
            build(level + 1, ident + "b")
            nodes.append({"id": ident, "fn": "add",
                          "args": {"a": {"node": ident + "a"}, "b": {"node": ident + "b"}}})
        return ident

    return nodes, build(0, "t")


def main():
    kind, size = sys.argv[1], int(sys.argv[2])
    nodes, root = chain(size) if kind == "chain" else tree(size)
    graph = {"texcc": 1, "nodes": nodes,
             "materials": {"m": {"bsdf": "emission", "color": 1.0, "strength": {"node": root}}}}
    json.dump(graph, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
