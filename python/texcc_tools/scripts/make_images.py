"""make_images.py: the two small images of examples/image-multiply, made deterministically.

  examples/image-multiply/images/tiles.png   128x128 RGB: a 4x4 grid of coloured tiles, each a
                                             soft diagonal gradient, with dark grout lines
  examples/image-multiply/images/dots.png    128x128 RGB (gray): light ground with a hexagonal
                                             pattern of soft dark dots

Both tile seamlessly (tex2D wraps), so the example can repeat them. Pure Python (zlib, no
packages); the same bytes on every run with the same zlib. The committed PNGs are this script's
output:

  python3 scripts/make_images.py            # rewrite both
  python3 scripts/make_images.py --check    # exit 1 if the committed files differ
"""

import math
import os
import struct
import sys
import zlib

from texcc_tools.paths import ROOT
OUT = os.path.join(ROOT, "examples", "image-multiply", "images")
SIZE = 128


def png_bytes(width, height, rgb_rows):
    """An 8-bit RGB PNG from rows of (r, g, b) tuples (0..255)."""
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rgb_rows)

    def chunk(tag, body):
        return (struct.pack(">I", len(body)) + tag + body +
                struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def to_byte(x):
    return max(0, min(255, int(round(x * 255.0))))


def tiles():
    palette = [(0.85, 0.35, 0.20), (0.95, 0.75, 0.25), (0.30, 0.60, 0.80), (0.40, 0.70, 0.35),
               (0.75, 0.40, 0.65), (0.95, 0.55, 0.30), (0.25, 0.45, 0.70), (0.80, 0.80, 0.70)]
    tile = SIZE // 4
    rows = []
    for y in range(SIZE):
        row = []
        for x in range(SIZE):
            tx, ty = x // tile, y // tile
            u, v = (x % tile + 0.5) / tile, (y % tile + 0.5) / tile
            base = palette[(tx * 3 + ty * 5 + tx * ty) % len(palette)]
            shade = 0.75 + 0.35 * (1.0 - 0.5 * (u + v))
            grout = min(u, v, 1.0 - u, 1.0 - v) < 0.06
            c = (0.12, 0.10, 0.09) if grout else tuple(min(1.0, ch * shade) for ch in base)
            row.append(tuple(to_byte(ch) for ch in c))
        rows.append(row)
    return rows


def dots():
    # Dot centres on a lattice that is periodic in 128 x 128: 8 columns, 8 rows, odd rows
    # shifted by half a column (a hexagon-like packing that still wraps exactly).
    step = SIZE / 8.0
    centres = []
    for j in range(-1, 9):
        for i in range(-1, 9):
            centres.append(((i + 0.5 * (j % 2)) * step + step / 4, (j + 0.5) * step))
    radius = step * 0.32
    rows = []
    for y in range(SIZE):
        row = []
        for x in range(SIZE):
            d = min(math.hypot(x + 0.5 - cx, y + 0.5 - cy) for cx, cy in centres)
            t = max(0.0, min(1.0, (d - radius) / (0.35 * radius)))  # 0 inside, 1 outside
            t = t * t * (3.0 - 2.0 * t)
            g = 0.18 + (0.95 - 0.18) * t
            row.append((to_byte(g),) * 3)
        rows.append(row)
    return rows


def main(argv):
    check = "--check" in argv
    images = {"tiles.png": tiles(), "dots.png": dots()}
    status = 0
    os.makedirs(OUT, exist_ok=True)
    for name, rows in images.items():
        data = png_bytes(SIZE, SIZE, rows)
        path = os.path.join(OUT, name)
        if check:
            with open(path, "rb") as f:
                if f.read() != data:
                    print("make_images: %s differs from the script's output" % path)
                    status = 1
        else:
            with open(path, "wb") as f:
                f.write(data)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
