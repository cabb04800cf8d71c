"""make_tile.py OUT.exr WxH SEED: a WxH EXR of uniform random values (as texexr writes them;
random, so that ZIP does not shrink it: the farm tests need outputs of a known size)."""
import sys

import numpy as np

from texcc_tools import exr as texexr

out, size, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
w, h = (int(v) for v in size.split("x"))
image = np.random.default_rng(seed).random((h, w, 3), dtype=np.float32)
with open(out, "wb") as f:
    f.write(texexr.write_exr(image))
