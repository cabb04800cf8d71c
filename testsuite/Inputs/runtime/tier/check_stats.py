"""check_stats.py STATS.json EXPR...: every EXPR (Python, over `stats`, the stats.json object,
and `frames`, its "frames" list) must be true; prints each check, and the frames' tiers and
builds when one fails. For the tier tests: one assertion per argument keeps RUN lines readable."""
import json
import sys


def main():
    with open(sys.argv[1]) as f:
        stats = json.load(f)
    frames = stats["frames"]
    failed = []
    for expr in sys.argv[2:]:
        ok = bool(eval(expr, {}, {"stats": stats, "frames": frames}))
        print("%s: %s" % ("ok" if ok else "FAILED", expr))
        if not ok:
            failed.append(expr)
    if failed:
        for fr in frames:
            print("frame %d %r: tier %s, builds %d (+%d background), waited %.3f s" % (
                fr["index"], fr["edit"], fr["tier"], fr["kernelBuilds"], fr["backgroundBuilds"],
                fr["buildWaitSeconds"]))
        for e in stats.get("textureBuilds", []):
            print("build: %r" % e)
        sys.exit(1)


if __name__ == "__main__":
    main()
