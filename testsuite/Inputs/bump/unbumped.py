"""unbumped.py GRAPH OUT: writes to OUT the graph GRAPH without the BSDFs' "normal" inputs (the
same materials unbumped) and with its sources made absolute, for a test to show that the bump
changes the picture."""
import json
import os
import sys


def strip(bsdf):
    bsdf.pop("normal", None)
    for key in ("a", "b"):
        if isinstance(bsdf.get(key), dict):
            strip(bsdf[key])


graph_path, out = sys.argv[1:3]
with open(graph_path) as f:
    graph = json.load(f)
folder = os.path.dirname(os.path.abspath(graph_path))
graph["sources"] = [os.path.normpath(os.path.join(folder, s)) for s in graph["sources"]]
for m in graph["materials"].values():
    strip(m)
with open(out, "w") as f:
    json.dump(graph, f, indent=1)
