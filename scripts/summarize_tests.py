"""Summarizes lit's xUnit XML output per test tier (docs/testing.md).

    summarize_tests.py RESULTS.xml [--tests DIR]

One line per tier ('default tier: N passed, N failed, N skipped'; the slow tier's tests are
those whose file says `REQUIRES: slow-tier`, looked up under DIR, default testsuite/ beside
this script), one line per reason a test was skipped, then the closing line over both tiers,
'N passed, N failed, N skipped'. Exits 1 if a test failed or none passed.
"""
import argparse
import collections
import os
import re
import sys
import xml.etree.ElementTree as ET

# What to do about a missing lit feature (testsuite/lit.cfg.py and lit.local.cfg files).
HINTS = {
    "slow-tier": "slow tier: run scripts/test.sh --slow",
    "opencl": "no OpenCL device answered (texcc-cl-probe)",
    "shared-assets": "../shared/assets is absent beside the checkout",
    "bpy": "bpy is not in .venv/ (pip install -r scripts/requirements-blender.txt)",
    "ray": "Ray is not in .venv/ (pip install -r scripts/requirements-farm.txt)",
    "aiohttp": "aiohttp is not installed (scripts/serve.sh --install)",
    "chromium": "chromium, chromium-driver (apt) or selenium (scripts/serve.sh --install) missing",
    "non-root": "runs as root, who can read a chmod 000 file",
}
MISSING = "Missing required feature(s): "
NOT_SELECTED = "Test not selected"
SLOW_MARK = re.compile(r"^\W*REQUIRES:.*\bslow-tier\b", re.M)


def source_of(tests_dir, classname, name):
    """The test file of an xUnit test case of the 'texcc' suite, or None (unit tests)."""
    suite, _, folder = classname.partition(".")
    if suite != "texcc":
        return None
    for rel in (os.path.join(folder, name), name):  # a top-level test's classname repeats the suite
        path = os.path.join(tests_dir, rel)
        if os.path.isfile(path):
            return path
    return None


def is_slow(path, cache={}):
    if path is None:
        return False
    if path not in cache:
        with open(path, errors="replace") as f:
            cache[path] = bool(SLOW_MARK.search(f.read()))
    return cache[path]


def reason_of(message):
    if message.startswith(MISSING):
        features = [f.strip() for f in message[len(MISSING):].split(",")]
        if "slow-tier" in features:
            features = ["slow-tier"]  # what a default run lacks; the rest shows in a --slow run
        return "; ".join(HINTS.get(f, "needs " + f) for f in features)
    return message or "skipped"


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("xml")
    p.add_argument("--tests", default=os.path.join(here, "..", "testsuite"))
    a = p.parse_args()
    counts = {"default": collections.Counter(), "slow": collections.Counter()}
    reasons = collections.Counter()
    not_selected = 0
    for case in ET.parse(a.xml).iter("testcase"):
        tier = "slow" if is_slow(source_of(a.tests, case.get("classname", ""),
                                           case.get("name", ""))) else "default"
        skipped = case.find("skipped")
        if case.find("failure") is not None or case.find("error") is not None:
            counts[tier]["failed"] += 1
        elif skipped is not None and skipped.get("message", "").startswith(NOT_SELECTED):
            not_selected += 1  # --filter or --max-tests left it out: in no tier's counts
        elif skipped is not None:
            counts[tier]["skipped"] += 1
            reasons[reason_of(skipped.get("message", ""))] += 1
        else:
            counts[tier]["passed"] += 1
    for tier in ("default", "slow"):
        c = counts[tier]
        if tier == "slow" and c["skipped"] and not c["passed"] and not c["failed"]:
            print(f"slow tier: {c['skipped']} not run (slow tier: run scripts/test.sh --slow)")
        else:
            print(f"{tier} tier: {c['passed']} passed, {c['failed']} failed, {c['skipped']} skipped")
    for reason, n in sorted(reasons.items(), key=lambda r: -r[1]):
        print(f"  skipped: {n} ({reason})")
    if not_selected:
        print(f"  not selected: {not_selected} (--filter, --max-tests)")
    total = counts["default"] + counts["slow"]
    print(f"{total['passed']} passed, {total['failed']} failed, {total['skipped']} skipped")
    return 1 if total["failed"] or not total["passed"] else 0


if __name__ == "__main__":
    sys.exit(main())
