"""edited_graph.py GRAPH OUT EDITS: writes to OUT the graph GRAPH with the lines of the edit
script EDITS applied (`set NODE.ARG=VALUE`, `rewire NODE.ARG=SOURCE`; `wait` and `#` comments
skipped) and its sources made absolute: the graph a live-edit session ends with, for a fresh
render to compare the session's last frame with."""
import json
import os
import sys


def main():
    graph_path, out, edits = sys.argv[1:4]
    with open(graph_path) as f:
        graph = json.load(f)
    folder = os.path.dirname(os.path.abspath(graph_path))
    graph["sources"] = [os.path.join(folder, s) for s in graph["sources"]]
    nodes = {n["id"]: n for n in graph["nodes"]}
    with open(edits) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line == "wait":
                continue
            kind, _, rest = line.partition(" ")
            target, _, value = rest.partition("=")
            node, _, arg = target.strip().rpartition(".")
            if kind == "rewire":
                nodes[node]["args"][arg] = {"node": value.strip()}
            elif kind == "set":
                nodes[node]["args"][arg] = json.loads(value)
            else:
                sys.exit("edited_graph.py: cannot apply '%s'" % line)
    with open(out, "w") as f:
        json.dump(graph, f, indent=1)


if __name__ == "__main__":
    main()
