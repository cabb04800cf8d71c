"""The custom-node tutorial (examples/custom-node/README.md) followed step by step in the browser
preview, in real headless Chromium against the real texrender:

  serve_tutorial.py --renderer TEXRENDER --texcc TEXCC --work DIR --readme README.md
                    --final GRAPH.json -- [texrender options with --spp S]

DIR holds dots.cl, scene.json and its meshes. 2: graph.json is the README's first JSON block
(the graph of step 2), compiled (3) and opened in the page: an image, a control per constant
argument of polkaDots (its vector defaults as colour pickers), no error. 4: scale=8 and
blur=0.05 typed into the page's number fields: the refined image equals the README's batch
command `--set dots.scale=8 --set dots.blur=0.05` bit for bit. 5: the committed graph (--final)
saved over graph.json: the page gets three nodes and radius shows its link. 6: the README's
misspelt attribute saved into dots.cl: the page shows texcc's error with file:line:col; the fix
clears it. Prints one fact a line.
"""
import json
import os
import re
import signal
import subprocess
import sys

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from serve_browser import Page, batch_equal, complete, start_server
from waits import WAIT_S  # noqa: E402


def readme_graph(readme):
    """The JSON block of the README's step 2."""
    with open(readme) as f:
        text = f.read()
    step = text[text.index("## 2."):]
    return json.loads(re.search(r"```json\n(.*?)```", step, re.S).group(1))


def retype(page, element_id, text):
    box = page.driver.find_element(By.ID, element_id)
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(text, Keys.TAB)
    return page.last_sent()


def controls(page, node):
    schema = page.js("return window.preview.schema;")
    inputs = next(n for n in schema["nodes"] if n["id"] == node)["inputs"]
    shown = []
    for put in inputs:
        e = page.driver.find_element(By.ID, f"ctl-{node}-{put['name']}")
        kind = e.get_attribute("type") or e.tag_name
        if kind == "span" and page.driver.find_elements(By.ID, f"ctl-{node}-{put['name']}-colour"):
            kind = "3 fields + colour picker"
        elif kind == "span":
            kind = e.text
        shown.append(f"{put['name']} {kind}")
    return shown


def main():
    cut = sys.argv.index("--")
    head, render_args = sys.argv[1:cut], sys.argv[cut + 1:]
    opts = {head[i][2:]: head[i + 1] for i in range(0, len(head), 2)}
    work, spp = opts["work"], int(render_args[render_args.index("--spp") + 1])
    graph_path, tex = os.path.join(work, "graph.json"), os.path.join(work, "tex")
    with open(graph_path, "w") as f:
        json.dump(readme_graph(opts["readme"]), f, indent=2)
    subprocess.run([opts["texcc"], "--graph", graph_path, "-o", tex], check=True)
    args = [os.path.join(work, "scene.json"), "--textures", tex] + render_args
    server, url = start_server(opts, args)
    page = None
    try:
        page = Page(url, server)
        s = page.wait("the first complete frame", complete(spp), timeout=WAIT_S)
        print(f"3: an image ({s['meta']['width']}x{s['meta']['height']}), errors panel: "
              f"{page.text('errors')}")
        print("3: controls of dots: " + "; ".join(controls(page, "dots")))
        # 4. Change a parameter without rebuilding.
        retype(page, "ctl-dots-scale-value", "8")
        sent = retype(page, "ctl-dots-blur-value", "0.05")
        s = page.wait("the refined frame", complete(spp, edit=sent["id"]), timeout=WAIT_S)
        builds = s["meta"]["builds"]
        png = page.png()
        print(f"4: scale=8, blur=0.05 typed in: equals the README's batch command bit for bit: "
              f"{batch_equal(opts, args, 'dots.scale=8', png, ['--set', 'dots.blur=0.05'])}")
        # 5. Feed a parameter from another node: the committed graph saved over graph.json.
        with open(opts["final"]) as f:
            final = json.load(f)
        # The library's files where the repository has them; dots.cl stays the copy in DIR.
        final["sources"] = [x if x == "dots.cl" else
                            os.path.normpath(os.path.join(os.path.dirname(opts["final"]), x))
                            for x in final["sources"]]
        hellos = page.state()["hellos"]
        with open(graph_path, "w") as f:
            json.dump(final, f, indent=2)
        page.wait("the new graph", lambda s: s["hellos"] > hellos and complete(spp)(s),
                  timeout=WAIT_S)
        nodes = [n["id"] for n in page.js("return window.preview.schema.nodes;")]
        radius = page.driver.find_element(By.ID, "ctl-dots-radius").text
        print(f"5: nodes {nodes}; radius: {radius}; image changed: {page.png() != png}")
        # 6. When something is wrong: the README's misspelt attribute, then the fix.
        dots = os.path.join(work, "dots.cl")
        with open(dots) as f:
            good = f.read()
        bad = good.replace("  float dx = cellOffset(p.x * scale);",
                           '  float3 q = readAttr("Position");\n'
                           "  float dx = cellOffset(p.x * scale);")
        assert bad != good
        with open(dots, "w") as f:
            f.write(bad)
        page.wait("the error in the page", lambda s: "error:" in page.text("errors"),
                  timeout=WAIT_S)
        line = next(x for x in page.text("errors").splitlines() if "error:" in x)
        print("6: the page shows: " + line[line.rindex("/") + 1:])
        hellos = page.state()["hellos"]
        with open(dots, "w") as f:
            f.write(good)
        page.wait("the fix", lambda s: s["hellos"] > hellos and page.text("errors") == "none",
                  timeout=WAIT_S)
        print(f"6: fixed: errors panel: {page.text('errors')}")
    finally:
        if page:
            page.driver.quit()
        server.send_signal(signal.SIGTERM)
        print(f"server exit {server.wait(timeout=WAIT_S)}")


if __name__ == "__main__":
    main()
