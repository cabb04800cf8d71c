"""bench_tools.py DIR both|one: makes DIR/bin with executable stand-ins for both binaries (or
for texcc alone) and builds texcc_tools.bench.common.Tools over it. Prints the binaries'
names, or the BenchError it raises."""
import os
import sys

from texcc_tools.bench.common import BenchError, Tools

folder, which = sys.argv[1], sys.argv[2]
os.makedirs(os.path.join(folder, "bin"), exist_ok=True)
os.makedirs(os.path.join(folder, "work"), exist_ok=True)
for name in ("texcc", "texrender") if which == "both" else ("texcc",):
    path = os.path.join(folder, "bin", name)
    open(path, "w").close()
    os.chmod(path, 0o755)
try:
    t = Tools(folder, os.path.join(folder, "work"))
    print("tools", os.path.basename(t.texcc), os.path.basename(t.texrender))
except BenchError as e:
    print("error", e)
