"""region_means.py: mean linear RGB per block of an image, against expected means.

    region_means.py IMAGE.exr EXPECTED.json [--write]

EXPECTED.json: {"blocks": [COLS, ROWS], "tolerance": T, "means": [[r, g, b], ...]} (row-major,
top row first), optionally "edges": [block index, ...]. Prints one line per block and PASS when
every channel of every block not in "edges" is within T (relative, of max(expected, 0.05)) of the
expected mean; else FAIL and exit 1. --write replaces "means" with IMAGE's (how the expected file
was made from the Cycles reference; see the test), and with --edges also "edges": the blocks
where IMAGE's alpha (coverage) is not the same everywhere, i.e. on an object's silhouette.
IMAGE may also be a .npy array (height, width, channels), as the Cycles script saves it.
"""
import json
import os
import sys

import numpy as np

from texcc_tools import exr as texexr


def load(path, channels=3):
    if path.endswith(".npy"):
        return np.load(path)[..., :channels].astype(np.float64)
    with open(path, "rb") as f:
        image = texexr.read_exr(f.read())
    image = image[0] if isinstance(image, tuple) else image
    return np.asarray(image, np.float64)[..., :3]


def block_means(image, cols, rows):
    h, w = image.shape[:2]
    return [image[r * h // rows:(r + 1) * h // rows, c * w // cols:(c + 1) * w // cols]
            .mean((0, 1)).tolist() for r in range(rows) for c in range(cols)]


def main():
    image_path, expected_path = sys.argv[1], sys.argv[2]
    with open(expected_path) as f:
        expected = json.load(f)
    cols, rows = expected["blocks"]
    means = block_means(load(image_path), cols, rows)
    if "--write" in sys.argv:
        expected["means"] = [[round(v, 6) for v in m] for m in means]
        if "--edges" in sys.argv:
            alpha = load(image_path, 4)[..., 3]
            h, w = alpha.shape
            expected["edges"] = [
                r * cols + c for r in range(rows) for c in range(cols)
                if np.ptp(alpha[r * h // rows:(r + 1) * h // rows,
                                c * w // cols:(c + 1) * w // cols]) > 0]
        with open(expected_path, "w") as f:
            json.dump(expected, f, indent=1)
            f.write("\n")
        return
    tol, worst, failed = expected["tolerance"], 0.0, 0
    edges = set(expected.get("edges", []))
    for i, (got, want) in enumerate(zip(means, expected["means"])):
        if i in edges:
            continue
        err = max(abs(g - e) / max(e, 0.05) for g, e in zip(got, want))
        worst = max(worst, err)
        bad = err > tol
        failed += bad
        print("block %d,%d: %s expected %s rel. error %.4f%s" % (
            i % cols, i // cols, " ".join("%.4f" % g for g in got),
            " ".join("%.4f" % e for e in want), err, "  FAIL" if bad else ""))
    print("worst relative error %.4f (tolerance %.4f), %d of %d blocks outside, %d on edges "
          "not compared" % (worst, tol, failed, len(means) - len(edges), len(edges)))
    print("PASS" if not failed else "FAIL")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
