#!/usr/bin/env python3
"""Compares two texcc-eval dumps: lines "<hit> <material> <output> <x> <y> <z> <w>".

Fails (exit 1) when the two dumps do not hold the same (hit, material, output) keys, or when the
largest absolute difference of any component exceeds --tol (default 1e-5); prints the worst case
either way. NaN equals NaN; a NaN against a number is a mismatch.

usage: compare.py REFERENCE.txt OTHER.txt [--tol 1e-5] [--label NAME]
"""
import argparse
import math
import sys


def load(path):
    values = {}
    with open(path) as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            if not fields:
                continue
            if len(fields) != 7:
                sys.exit(f"{path}:{number}: expected 7 fields, found {len(fields)}")
            values[tuple(int(x) for x in fields[:3])] = [float(x) for x in fields[3:]]
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference")
    parser.add_argument("other")
    parser.add_argument("--tol", type=float, default=1e-5)
    parser.add_argument("--label", default="")
    args = parser.parse_args()
    ref, other = load(args.reference), load(args.other)
    label = f"{args.label}: " if args.label else ""
    if ref.keys() != other.keys():
        only_ref = sorted(ref.keys() - other.keys())[:5]
        only_other = sorted(other.keys() - ref.keys())[:5]
        print(f"{label}FAIL: different (hit, material, output) sets; only in reference: "
              f"{only_ref}, only in other: {only_other}")
        return 1
    if not ref:
        print(f"{label}FAIL: no values to compare")
        return 1
    worst, worst_key, worst_comp = -1.0, None, 0
    for key, a in ref.items():
        b = other[key]
        for c in range(4):
            if math.isnan(a[c]) and math.isnan(b[c]):
                d = 0.0
            elif math.isnan(a[c]) or math.isnan(b[c]):
                d = math.inf
            else:
                d = abs(a[c] - b[c])
            if d > worst:
                worst, worst_key, worst_comp = d, key, c
    hit, mat, out = worst_key
    detail = (f"hit {hit} material {mat} output {out} component {'xyzw'[worst_comp]}: "
              f"{ref[worst_key][worst_comp]!r} vs {other[worst_key][worst_comp]!r}")
    if worst > args.tol:
        print(f"{label}FAIL: max abs diff {worst:.3g} > {args.tol:g} over {len(ref)} outputs; "
              f"worst at {detail}")
        return 1
    print(f"{label}OK: max abs diff {worst:.3g} <= {args.tol:g} over {len(ref)} outputs "
          f"(worst at {detail})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
