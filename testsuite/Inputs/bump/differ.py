"""differ.py A.exr B.exr MIN: the mean absolute difference of the two images relative to B's
mean must exceed MIN (the bump visibly changes the shading, not just the rounding)."""
import sys

from texcc_tools.exr import read_exr

a, b = (read_exr(open(p, "rb").read()) for p in sys.argv[1:3])
rel = float(abs(a - b).mean() / abs(b).mean())
print("relative mean |difference| %.4g" % rel)
assert rel > float(sys.argv[3]), "the images differ by %g only" % rel
print("PASS")
