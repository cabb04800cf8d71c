#!/usr/bin/env python3
"""Writes graph.json with one rewiring applied (NODE.ARG=SOURCE), its sources made absolute, to
OUT: the graph a live edit should render, for a fresh texcc run to compare with."""
import json
import os
import sys

graph, edit, out = sys.argv[1:4]
with open(graph) as f:
    g = json.load(f)
here = os.path.dirname(os.path.abspath(graph))
g["sources"] = [os.path.normpath(os.path.join(here, s)) for s in g["sources"]]
lhs, source = edit.split("=")
node, arg = lhs.rsplit(".", 1)
for n in g["nodes"]:
    if n["id"] == node:
        n["args"][arg] = {"node": source}
with open(out, "w") as f:
    json.dump(g, f, indent=1)
