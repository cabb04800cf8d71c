"""match.py TEXCC TEXRENDER SRC WORK: every example scene (SRC/examples/*/scene*.json, its textures compiled from
the example's graph.json, its generated geometry made by scripts/make_scenes.py --out WORK/geo) rendered by texrender in lanes (--lanes on, the default) and whole
(--lanes off), under several thread counts, film sizes and regions (odd row counts, more lanes
than cores, a region off the film's corner): the image and the variance must be the same bytes,
and stats.json must say the lanes rendered (threads.lanes) or why they did not. Prints one line
per case and 'FAILED' for each mismatch; exit 1 if any."""
import glob
import json
import os
import subprocess
import sys

# (name, texrender options, lanes expected)
CASES = [
    ("2 threads 24x17", ["--threads", "2", "--size", "24x17"], 2),
    ("3 threads region", ["--threads", "3", "--size", "31x23", "--region", "5,3,13,10"], 3),
    ("4 threads 9x5", ["--threads", "4", "--size", "9x5"], 4),
]


def render(texrender, tex, scene, out, extra, cache):
    cmd = [texrender, scene, "--textures", tex, "-o", out + ".exr", "--variance",
           out + ".var.exr", "--stats", out + ".json", "--quiet", "--spp", "3", "--max-depth",
           "3", "--cache-dir", cache] + extra
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        raise SystemExit("FAILED: %s\n%s" % (" ".join(cmd), p.stdout.decode()[-2000:]))
    with open(out + ".json") as f:
        return json.load(f)["threads"]


def scene_copy(src, scene, work):
    """(a copy of scene with each mesh's OBJ found: the example's own, else the one make_scenes.py
    wrote under WORK/geo (the examples' generated/ folders are git-ignored), None); (None, the
    OBJ path) when an OBJ is neither (../shared/assets absent)."""
    with open(scene) as f:
        s = json.load(f)
    ex = os.path.dirname(scene)
    for mesh in s["meshes"]:
        own = os.path.join(ex, mesh["obj"])
        made = os.path.join(work, "geo", os.path.relpath(ex, os.path.join(src, "examples")), mesh["obj"])
        found = [p for p in (own, made) if os.path.exists(p)]
        if not found:  # test geometry made by others (../shared/assets), absent here
            return None, own
        mesh["obj"] = os.path.abspath(found[0])
    out = os.path.join(work, "%s-%s" % (os.path.basename(ex), os.path.basename(scene)))
    with open(out, "w") as f:
        json.dump(s, f)
    return out, None


def same(a, b):
    with open(a, "rb") as f, open(b, "rb") as g:
        return f.read() == g.read()


def main():
    texcc, texrender, src, work = sys.argv[1:5]
    if os.environ.get("TEXRENDER_FIRST_BUILD") != "optimised":
        raise SystemExit("FAILED: run with TEXRENDER_FIRST_BUILD=optimised (a quick first build "
                         "renders whole)")
    cache = os.path.join(work, "cache")
    failed = 0
    subprocess.run([sys.executable, os.path.join(src, "scripts", "make_scenes.py"), "--out",
                    os.path.join(work, "geo")], check=True, stdout=subprocess.DEVNULL)
    scenes = sorted(glob.glob(os.path.join(src, "examples", "*", "scene*.json")))
    rendered = 0
    for original in scenes:
        scene, absent = scene_copy(src, original, work)
        if scene is None:
            print("skipped: %s: %s is absent" % (os.path.relpath(original, src), absent))
            continue
        rendered += 1
        with open(scene) as f:
            name = os.path.basename(json.load(f)["textures"])
        tex = os.path.join(work, "tex-" + name)
        if not os.path.isdir(tex):
            subprocess.run([texcc, "--graph", os.path.join(src, "examples", name, "graph.json"),
                            "-o", tex], check=True, stderr=subprocess.DEVNULL)
        for case, extra, lanes in CASES:
            base = os.path.join(work, "%s-%s" % (os.path.basename(scene)[:-5], case.replace(" ", "_")))
            on = render(texrender, tex, scene, base + "-on", extra, cache)
            off = render(texrender, tex, scene, base + "-off", extra + ["--lanes", "off"], cache)
            ok = (same(base + "-on.exr", base + "-off.exr")
                  and same(base + "-on.var.exr", base + "-off.var.exr")
                  and on["lanes"] == lanes and on.get("laneMemoryBytes", 0) > 0
                  and off["lanes"] == 1 and off["lanesWhyNot"] == "--lanes off")
            failed += not ok
            print("%s: %s %s: lanes %s (%s), whole %s: %s" % (
                "ok" if ok else "FAILED", os.path.relpath(original, src), case, on["lanes"],
                on.get("lanesWhyNot", "rendered in lanes"), off["lanes"],
                "same image and variance" if ok else "MISMATCH"))
    print("%d scenes x %d cases, %d failed" % (rendered, len(CASES), failed))
    sys.exit(1 if failed or not rendered else 0)


if __name__ == "__main__":
    main()
