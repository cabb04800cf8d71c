import sys, zlib
import numpy as np
from texcc_tools import exr as texexr  # (argv[1], the scripts folder, is no longer needed)
data = open(sys.argv[2], "rb").read()
pos, idat = 8, b""
while pos < len(data):
    n = int.from_bytes(data[pos:pos + 4], "big")
    kind = data[pos + 4:pos + 8]
    if kind == b"IHDR":
        w, h = int.from_bytes(data[pos + 8:pos + 12], "big"), int.from_bytes(data[pos + 12:pos + 16], "big")
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + 3 * w)
assert (raw[:, 0] == 0).all(), "the preview's rows are not filter 0"
preview = raw[:, 1:].reshape(h, w, 3).astype(int)
lin = texexr.read_exr(open(sys.argv[3], "rb").read()).astype(np.float64)
def srgb(v):
    v = np.clip(v, 0, 1)
    return np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055)
def byte(v):
    return np.where(v <= 0, 0, np.where(v > 1 - 0.5 / 255, 255, np.floor(255 * v + 0.5))).astype(int)
view = byte(srgb(4 * lin) ** (1 / 1.5))
plain = byte(srgb(lin))
print("preview through the view: max difference 0 or 1 steps:", "yes" if np.abs(preview - view).max() <= 1 else "no %d" % np.abs(preview - view).max())
print("plain sRGB would differ by more than 1 step:", "yes" if np.abs(preview - plain).max() > 1 else "no")
