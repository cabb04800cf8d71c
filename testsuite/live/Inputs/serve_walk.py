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
of the edit schema finds its control in the page and drives one edit through it (the slider
with the arrow keys, a number field retyped, a vector's first field, a ramp's first cell),
and waits for texrender's 'applied' answer to that message, with the value sent. Prints one
line per session and, last, whether every constant input had a working control; timings go to
DIR/timing.txt.
"""
import argparse
import json
import os
import subprocess
import sys
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from serve_browser import Page, start_server

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


def retype(box, text):
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(text, Keys.TAB)


def drive(page, node, put):
    """Drives one edit of constant input PUT of NODE through its control; returns the message
    sent, or a reason why there is no working control."""
    find = page.driver.find_elements
    base = f"ctl-{node}-{put['name']}"
    t, value = put["type"], put["value"]
    if t == "float":
        slider = find(By.ID, base)
        if not slider or slider[0].get_attribute("type") != "range":
            return "no slider"
        at_max = float(slider[0].get_attribute("value")) >= float(slider[0].get_attribute("max"))
        slider[0].send_keys(Keys.ARROW_LEFT if at_max else Keys.ARROW_RIGHT)
    elif t == "int":
        box = find(By.ID, base)
        if not box or box[0].get_attribute("type") != "number":
            return "no number field"
        top = put.get("max")
        retype(box[0], str(value + 1 if top is None or value + 1 <= top else value - 1))
    elif t in ("float2", "float3", "float4"):
        box = find(By.ID, base + "-0")
        if not box:
            return "no vector fields"
        retype(box[0], repr(0.25 if value[0] != 0.25 else 0.75))
    elif t.startswith("__global"):
        table = find(By.ID, base)
        cells = table[0].find_elements(By.CSS_SELECTOR, "input[type=number]") if table else []
        if not cells:
            return "no rows"
        first = value[0][0] if isinstance(value[0], list) else value[0]
        retype(cells[0], repr(0.25 if first != 0.25 else 0.75))
    else:
        return f"no control for type {t}"
    return None


def walk_session(page, name, server, url, timing):
    t0 = time.monotonic()
    page.server = server
    page.driver.get(url)
    page.wait("the first image", lambda s: s["hellos"] > 0 and s["frames"] > 0
              and s["meta"] and s["meta"].get("width"), timeout=600)
    t_image = time.monotonic() - t0
    schema = page.js("return window.preview.schema;")
    meta = page.state()["meta"]
    errors = page.text("errors")
    constants = [(n["id"], put) for n in schema["nodes"] for put in n["inputs"] if "value" in put]
    failures, applied = [], 0
    for node, put in constants:
        sent_before = page.js("return window.preview.sent.length;")
        why = drive(page, node, put)
        if why is None:
            try:
                page.wait(f"the message of {node}.{put['name']}",
                          lambda s: s["sent"] > sent_before, timeout=20)
            except SystemExit:
                why = "the control sent nothing"
        if why is None:
            sent = page.last_sent()
            look = ("const id = arguments[0]; const p = window.preview;"
                    " const a = p.applied.find((m) => m.id === id);"
                    " const e = p.errors.find((m) => m.id === id);"
                    " return a ? {applied: a} : (e ? {error: e} : null);")
            try:
                page.wait(f"texrender's answer to {node}.{put['name']}",
                          lambda s: page.js(look, sent["id"]) is not None, timeout=120)
                answer = page.js(look, sent["id"])
            except SystemExit as e:
                answer = {"error": {"message": f"no answer: {e}"}}
            if "error" in answer:
                why = "refused: " + answer["error"]["message"]
            elif (answer["applied"].get("node"), answer["applied"].get("arg"),
                  answer["applied"].get("value")) != (node, put["name"], sent["value"]):
                why = f"applied something else: {answer['applied']}"
            else:
                applied += 1
        if why:
            failures.append(f"{name}: {node}.{put['name']} ({put['type']}): {why}")
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
                server.wait(timeout=60)
    finally:
        if page:
            page.driver.quit()
        timing.write(f"all: {time.monotonic() - t0:.1f} s\n")
        timing.close()
    print(f"walked {len(sessions)} sessions: every constant input has a working control and "
          f"the errors panel says none: {ok}")


if __name__ == "__main__":
    main()
