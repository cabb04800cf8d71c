"""Every texture opens in the browser preview (issue 36), in real headless Chromium against the
real texrender (docs/live.md, "Browser preview"):

  serve_walk.py --renderer TEXRENDER --texcc TEXCC --work DIR --quad OBJ --image PNG
                [--files F.cl ...] [--graphs GRAPH.json ...] -- [texrender options]

--files: one graph is generated for all the files together (one preview session, one kernel
build): a node per documented texture function (`texcc --list-nodes --json`), with an id that
holds a dot and a slash as the Blender exporter's do ("noise.cl/fbm3.0"), each constant
parameter at the default of the file's parameter table (0.5, 1, two rows or the image where
the table has none, float2/float3 inputs without a default fed from TexCoord0/ObjectPos), and
a material per node that makes it live. --graphs: each graph as it is (a session each). Every
session renders a grid of quads, one per material of the graph (OBJ copies of --quad).

Per session: waits for an image; checks the errors panel says "none"; for every constant input
of the edit schema finds its control in the page and drives one edit through it, in the page
(a slider stepped, a number field changed, a vector's first field, a ramp's first cell: the
control's own handler sends the message), and waits for texrender's 'applied' answer to each
message, with the node, argument and value sent. Prints one
line per session and, last, whether every constant input had a working control; timings go to
DIR/timing.txt.
"""
import argparse
import json
import os
import subprocess
import sys
import time

from serve_browser import Page, start_server
from waits import WAIT_S  # noqa: E402

ATTR_FOR = {"float3": "ObjectPos", "float2": "TexCoord0"}
ROWS = {"float4": [[0.0, 0.1, 0.2, 0.3], [1.0, 0.9, 0.8, 0.7]],
        "float2": [[0.0, 0.2], [1.0, 0.8]], "float": [0.0, 1.0]}


def argument(param, images):
    """A graph argument for PARAM (a --list-nodes --json parameter)."""
    t = param["type"]
    if t == "sam2D":
        return {"image": images}
    if t.startswith("__global"):
        return ROWS[t.split()[-1].rstrip("*")]
    if "default" in param:
        d = param["default"]
        return int(d[0]) if t == "int" else (d[0] if t == "float" else d)
    if t in ATTR_FOR:
        return {"attr": ATTR_FOR[t]}
    return {"int": 1, "float": 0.5, "float4": [0.5, 0.5, 0.5, 1.0]}[t]


def material(node, ret):
    if ret == "float":
        return {"bsdf": "blend", "mask": {"node": node},
                "a": {"bsdf": "diffuse", "color": [0.2, 0.2, 0.2]},
                "b": {"bsdf": "diffuse", "color": [0.9, 0.9, 0.9]}}
    return {"bsdf": "diffuse", "color": {"node": node}}


def generated_graph(texcc, files, image, path):
    out = subprocess.run([texcc, "--list-nodes", "--json"] + files, check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    nodes, materials = [], {}
    for entry in json.loads(out)["files"]:
        stem = os.path.basename(entry["file"])
        for fn in entry["functions"]:
            node = f"{stem}/{fn['name']}.0"
            nodes.append({"id": node, "fn": fn["name"],
                          "args": {p["name"]: argument(p, "img") for p in fn["params"]}})
            if fn["return"] in ("float", "float3"):
                materials[f"m{len(materials)}"] = material(node, fn["return"])
    graph = {"texcc": 1, "sources": [os.path.abspath(f) for f in files],
             "images": {"img": os.path.abspath(image)}, "nodes": nodes, "materials": materials}
    with open(path, "w") as f:
        json.dump(graph, f, indent=1)
    return graph


def grid_scene(graph, quad, folder):
    """scene.json in FOLDER: one quad per material of GRAPH, in a grid facing the camera."""
    with open(quad) as f:
        text = f.read()
    names = sorted(graph["materials"])
    side = max(1, int(len(names) ** 0.5 + 0.999))
    meshes = []
    for i, name in enumerate(names):
        dx, dy = 2.2 * (i % side - (side - 1) / 2), 2.2 * (i // side - (side - 1) / 2)
        lines = []
        for line in text.splitlines():
            if line.startswith("v "):
                x, y, z = (float(v) for v in line.split()[1:4])
                line = f"v {x + dx} {y + dy} {z}"
            lines.append(line)
        obj = os.path.join(folder, f"quad{i}.obj")
        with open(obj, "w") as f:
            f.write("\n".join(lines) + "\n")
        meshes.append({"obj": os.path.basename(obj), "material": name})
    scene = {"texrender": 1,
             "camera": {"position": [0, 0, 3 * side], "target": [0, 0, 0], "fov": 45},
             "film": {"width": 16, "height": 16}, "render": {"spp": 1, "maxDepth": 2, "seed": 1},
             "lights": [{"type": "sky", "radiance": [1, 1, 1]}], "meshes": meshes}
    path = os.path.join(folder, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


# Drives one edit through the control of each constant input, in the page (one script, no
# WebDriver round trip per control): the control's own event handler sends the message, as a
# user's change would. Returns, per input, the id of the message it sent or why none was sent.
DRIVE = """
const [inputs] = arguments;
const p = window.preview;
const byId = (id) => document.getElementById(id);
const fire = (el, kind) => el.dispatchEvent(new Event(kind, { bubbles: true }));
const other = (v) => (v === 0.25 ? 0.75 : 0.25);
return inputs.map(([node, put]) => {
  const base = `ctl-${node}-${put.name}`;
  const before = p.sent.length;
  const t = put.type;
  let el = null;
  if (t === "float") {
    el = byId(base);
    if (!el || el.type !== "range") return { why: "no slider" };
    if (Number(el.value) >= Number(el.max)) el.stepDown(); else el.stepUp();
    fire(el, "input");
  } else if (t === "int") {
    el = byId(base);
    if (!el || el.type !== "number") return { why: "no number field" };
    const v = put.value;
    el.value = put.max == null || v + 1 <= put.max ? v + 1 : v - 1;
    fire(el, "change");
  } else if (/^float[234]$/.test(t)) {
    el = byId(base + "-0");
    if (!el) return { why: "no vector fields" };
    el.value = other(put.value[0]);
    fire(el, "change");
  } else if (t.startsWith("__global")) {
    const table = byId(base);
    el = table && table.querySelector("input[type=number]");
    if (!el) return { why: "no rows" };
    const first = Array.isArray(put.value[0]) ? put.value[0][0] : put.value[0];
    el.value = other(first);
    fire(el, "change");
  } else {
    return { why: `no control for type ${t}` };
  }
  if (p.sent.length !== before + 1) return { why: "the control sent nothing" };
  return { id: p.sent[p.sent.length - 1].id, value: p.sent[p.sent.length - 1].value };
});
"""

ANSWERS = """
const p = window.preview;
const ids = new Set(arguments[0]);
const out = {};
for (const m of p.applied) if (ids.has(m.id)) out[m.id] = { applied: m };
for (const m of p.errors) if (ids.has(m.id)) out[m.id] = { error: m };
return out;
"""


def walk_session(page, name, server, url, timing):
    t0 = time.monotonic()
    page.server = server
    page.driver.get(url)
    page.wait("the first image", lambda s: s["hellos"] > 0 and s["frames"] > 0
              and s["meta"] and s["meta"].get("width"), timeout=WAIT_S)
    t_image = time.monotonic() - t0
    schema = page.js("return window.preview.schema;")
    meta = page.state()["meta"]
    errors = page.text("errors")
    constants = [(n["id"], put) for n in schema["nodes"] for put in n["inputs"] if "value" in put]
    failures, applied = [], 0
    driven = page.js(DRIVE, constants)
    ids = [d["id"] for d in driven if "id" in d]
    try:
        page.wait("texrender's answers", lambda s: len(page.js(ANSWERS, ids)) == len(ids),
                  timeout=WAIT_S)
    except SystemExit:
        pass
    answers = {int(k): v for k, v in page.js(ANSWERS, ids).items()}
    for (node, put), d in zip(constants, driven):
        why = d.get("why")
        answer = answers.get(d.get("id"))
        if why is None and answer is None:
            why = "no answer from texrender"
        elif why is None and "error" in answer:
            why = "refused: " + answer["error"]["message"]
        elif why is None and (answer["applied"].get("node"), answer["applied"].get("arg"),
                              answer["applied"].get("value")) != (node, put["name"], d["value"]):
            why = f"applied something else: {answer['applied']}"
        if why:
            failures.append(f"{name}: {node}.{put['name']} ({put['type']}): {why}")
        else:
            applied += 1
    took = time.monotonic() - t0
    timing.write(f"{name}: first image {t_image:.1f} s, {len(constants)} edits, "
                 f"session {took:.1f} s\n")
    print(f"{name}: image {meta['width']}x{meta['height']}, errors panel: {errors}; "
          f"{len(schema['nodes'])} nodes, {len(constants)} constant inputs, "
          f"{applied} edits applied through their controls")
    for f in failures:
        print("FAIL " + f)
    return not failures and errors == "none"


def main():
    cut = sys.argv.index("--")
    p = argparse.ArgumentParser()
    for a in ("--renderer", "--texcc", "--work", "--quad", "--image"):
        p.add_argument(a, required=True)
    p.add_argument("--files", nargs="*", default=[], action="append",
                   help="texture files opened in one session (repeatable: a session each)")
    p.add_argument("--graphs", nargs="*", default=[])
    opts = p.parse_args(sys.argv[1:cut])
    render_args = sys.argv[cut + 1:]
    sessions = []
    for k, files in enumerate(f for f in opts.files if f):
        folder = os.path.join(opts.work, f"files{k}")
        os.makedirs(folder, exist_ok=True)
        graph_path = os.path.join(folder, "graph.json")
        graph = generated_graph(opts.texcc, files, opts.image, graph_path)
        common = os.path.commonpath([os.path.abspath(f) for f in files])
        name = (os.path.basename(files[0]) if len(files) == 1 else
                f"{len(files)} texture files in {os.path.basename(common)}/")
        sessions.append((name, graph_path, graph, folder))
    for g in opts.graphs:
        folder = os.path.join(opts.work, os.path.basename(os.path.dirname(os.path.abspath(g))))
        os.makedirs(folder, exist_ok=True)
        with open(g) as f:
            sessions.append((os.path.relpath(g), os.path.abspath(g), json.load(f), folder))
    ok, page, t0 = True, None, time.monotonic()
    timing = open(os.path.join(opts.work, "timing.txt"), "w")
    try:
        for name, graph_path, graph, folder in sessions:
            tex = os.path.join(folder, "tex")
            subprocess.run([opts.texcc, "--graph", graph_path, "-o", tex], check=True)
            scene = grid_scene(graph, opts.quad, folder)
            server, url = start_server(dict(vars(opts), work=folder),
                                       [scene, "--textures", tex] + render_args)
            try:
                if page is None:
                    page = Page(url, server)
                ok &= walk_session(page, name, server, url, timing)
            finally:
                if page:  # the page lets go of the server's socket
                    page.driver.get("about:blank")
                server.terminate()
                server.wait(timeout=WAIT_S)
    finally:
        if page:
            page.driver.quit()
        timing.write(f"all: {time.monotonic() - t0:.1f} s\n")
        timing.close()
    print(f"walked {len(sessions)} sessions: every constant input has a working control and "
          f"the errors panel says none: {ok}")


if __name__ == "__main__":
    main()
