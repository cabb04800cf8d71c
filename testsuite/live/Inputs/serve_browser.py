"""The browser preview in real headless Chromium (selenium + Debian's chromium-driver), as a
user would use it on the rust example (docs/live.md, "Browser preview"):

  serve_browser.py --renderer TEXRENDER --texcc TEXCC --work DIR --shot PNG -- SCENE --textures TEX
                   --spp S [other texrender options]

1. opens the page and waits for a complete frame (S samples);
2. moves the patches.scale slider with the keyboard: the image changes, no kernel is built,
   and the refined image equals a batch `texrender --set patches.scale=V` render bit for bit
   (decoded PNG pixels);
3. rewires mask.noise to grain from the node's menu: applied, no kernel build, a new image;
4. saves a syntax error into the watched rust.cl (DIR/rust.cl): the page shows the error with
   file:line:col and the frames that follow still show the old texture;
5. saves a fix: the error goes, the new texture renders;
then saves a screenshot. Prints one fact a line for FileCheck.
"""
import base64
import os
import re
import signal
import subprocess
import sys
import time
import zlib

import numpy as np
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from waits import WAIT_S  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SERVE = os.path.join(HERE, "..", "..", "..", "scripts", "serve.py")


def decode_png(data):
    """The pixels of an 8-bit, non-interlaced greyscale/RGB/RGBA PNG as a numpy array."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h = int.from_bytes(body[0:4], "big"), int.from_bytes(body[4:8], "big")
            depth, colour, interlace = body[8], body[9], body[12]
            assert depth == 8 and interlace == 0, "only 8-bit non-interlaced PNGs"
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * channels
    out = np.zeros((h, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = line.copy()
        if f == 2:
            cur = (line + prev) & 255
        elif f in (1, 3, 4):
            for x in range(stride):
                a = cur[x - channels] if x >= channels else 0
                b, c = prev[x], prev[x - channels] if x >= channels else 0
                if f == 1:
                    pred = a
                elif f == 3:
                    pred = (a + b) >> 1
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[x] = (line[x] + pred) & 255
        out[y], prev = cur, cur
    return out.reshape(h, w, channels)


class Page:
    def __init__(self, url, server):
        self.server = server
        opts = webdriver.ChromeOptions()
        opts.binary_location = "/usr/bin/chromium"
        for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                  "--window-size=1180,860"):
            opts.add_argument(a)
        self.driver = webdriver.Chrome(options=opts, service=Service("/usr/bin/chromedriver"))
        self.driver.get(url)

    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    def state(self):
        return self.js("const p = window.preview; return p ? {frames: p.frames, meta: p.lastMeta,"
                       " sent: p.sent.length, hellos: p.hellos || 0} : null;")

    def png(self):
        b64 = self.driver.execute_async_script(
            "const done = arguments[0]; const r = new FileReader();"
            "r.onload = () => done(r.result.split(',')[1]); r.readAsDataURL(window.preview.lastPng);")
        return base64.b64decode(b64)

    def wait(self, what, test, timeout=WAIT_S):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.server.poll() is not None:
                raise SystemExit(f"serve_browser.py: the server ended (exit {self.server.poll()}) "
                                 f"while waiting for {what}")
            s = self.state()
            if s and test(s):
                return s
            time.sleep(0.05)
        raise SystemExit(f"serve_browser.py: timed out waiting for {what}; state {self.state()}")

    def last_sent(self):
        return self.js("return window.preview.sent[window.preview.sent.length - 1];")

    def text(self, element_id):
        return self.driver.find_element(By.ID, element_id).text


def start_server(opts, render_args):
    proc = subprocess.Popen([sys.executable, SERVE, "--port", "0", "--texrender", opts["renderer"],
                             "--texcc", opts["texcc"], "--"] + render_args,
                            stderr=subprocess.PIPE, text=True)
    log = open(os.path.join(opts["work"], "server.log"), "w")
    for line in proc.stderr:
        log.write(line)
        m = re.search(r"preview at (http://127\.0\.0\.1:\d+/)", line)
        if m:
            break
    else:
        raise SystemExit("serve_browser.py: the server ended before listening")
    # The rest of the server's log goes to the file (a pipe left unread would block it).
    subprocess.Popen(["cat"], stdin=proc.stderr, stdout=log)
    return proc, m.group(1)


def complete(spp, after_frames=0, edit=None):
    return lambda s: (s["meta"] and s["meta"].get("spp") == spp and s["frames"] > after_frames
                      and (edit is None or s["meta"].get("edit") == edit))


def batch_equal(opts, render_args, setting, png, extra=()):
    out = os.path.join(opts["work"], "batch.png")
    subprocess.run([opts["renderer"]] + render_args + ["--quiet", "--set", setting] + list(extra)
                   + ["-o", out], check=True)
    with open(out, "rb") as f:
        batch = decode_png(f.read())
    mine = decode_png(png)
    return mine.shape == batch.shape and bool((mine == batch).all())


def slider_step(page, spp, opts, render_args, first):
    slider = page.driver.find_element(By.ID, "ctl-patches-scale")
    slider.send_keys(Keys.ARROW_RIGHT)
    sent = page.last_sent()
    s = page.wait("the refined frame after the slider move", complete(spp, edit=sent["id"]))
    png = page.png()
    setting = f"patches.scale={sent['value']!r}"
    print(f"slider: set {setting}; kernel builds during the edit: {s['meta']['builds'] - first['builds']}")
    print(f"slider: image changed: {png != first['png']}")
    print(f"slider: equals a batch render at {spp} spp bit for bit: "
          f"{batch_equal(opts, render_args, setting, png)}")
    print(f"slider: edit log: {page.text('edits').splitlines()[0].split(':')[0]}")
    return png, s


def rewire_step(page, spp, before, builds):
    Select(page.driver.find_element(By.ID, "rewire-mask-noise")).select_by_value("grain")
    sent = page.last_sent()
    s = page.wait("the refined frame after the rewiring", complete(spp, edit=sent["id"]))
    png = page.png()
    print(f"rewire: {sent['node']}.{sent['arg']} <- {sent['source']}; kernel builds: "
          f"{s['meta']['builds'] - builds}; image changed: {png != before}")
    return png


def source_steps(page, spp, work, before):
    path = os.path.join(work, "rust.cl")
    with open(path) as f:
        good = f.read()
    hellos, saved_at = page.state()["hellos"], page.state()["frames"]
    with open(path, "w") as f:
        f.write(good.replace("return smoothstep(threshold - s, threshold + s, c);",
                             "return smoothstep(threshold - s, threshold + s, c)"))
    page.wait("the error in the page", lambda s: re.search(r"rust\.cl:\d+:\d+: error",
                                                           page.text("errors")), timeout=WAIT_S)
    error = next(l for l in page.text("errors").splitlines() if re.search(r"rust\.cl:\d+:\d+:", l))
    print("syntax error shown: " + error[error.rindex("/") + 1:])
    # The save restarted accumulation with the old kernel; the frames since (before or after the
    # error, depending on how fast texcc fails) must show the old texture.
    page.wait("a complete frame since the save", complete(spp, after_frames=saved_at), timeout=WAIT_S)
    print(f"after the error: frames keep coming, the old texture: {page.png() == before}")
    with open(path, "w") as f:
        f.write(good.replace("return smoothstep(threshold - s, threshold + s, c);",
                             "return 1.0f - smoothstep(threshold - s, threshold + s, c);"))
    page.wait("the new texture", lambda s: page.text("errors") == "none"
              and s["hellos"] > hellos and complete(spp)(s) and page.png() != before, timeout=WAIT_S)
    print(f"fixed: errors panel: {page.text('errors')}; the new texture renders: True")


def main():
    cut = sys.argv.index("--")
    head, render_args = sys.argv[1:cut], sys.argv[cut + 1:]
    opts = {head[i][2:]: head[i + 1] for i in range(0, len(head), 2)}
    spp = int(render_args[render_args.index("--spp") + 1])
    server, url = start_server(opts, render_args)
    page = None
    try:
        page = Page(url, server)
        s = page.wait("the first complete frame", complete(spp), timeout=WAIT_S)
        first = {"builds": s["meta"]["builds"], "png": page.png()}
        print(f"first frame: {spp} spp, tier {s['meta']['tier']}")
        png, s = slider_step(page, spp, opts, render_args, first)
        png = rewire_step(page, spp, png, first["builds"])
        source_steps(page, spp, opts["work"], png)
        page.js("window.scrollTo(0, 0);")
        page.driver.save_screenshot(opts["shot"])
        print(f"screenshot: {os.path.basename(opts['shot'])}")
    finally:
        if page:
            page.driver.quit()
        server.send_signal(signal.SIGTERM)
        print(f"server exit {server.wait(timeout=WAIT_S)}")


if __name__ == "__main__":
    main()
