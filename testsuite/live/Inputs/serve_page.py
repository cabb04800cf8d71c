"""The preview page's controls in headless Chromium, against the fake texrender (no renderer,
no OpenCL): what the page builds from the edit schema (types, ranges and defaults as texcc
reads them from the sources' parameter tables), and what each control sends (read back from
the fake's log of control lines).

  serve_page.py --texcc TEXCC --work DIR -- SCENE --textures TEX     (the rust example's graph)
"""
import json
import os
import sys
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from serve_browser import Page, start_server
from waits import WAIT_S  # noqa: E402

FAKE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "serve_fake_texrender.py")


def control_lines(log, n, timeout=WAIT_S):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if os.path.exists(log):
            with open(log) as f:
                lines = f.read().splitlines()
            if len(lines) >= n:
                return lines
        time.sleep(0.05)
    raise SystemExit(f"serve_page.py: {n} control lines did not arrive")


def main():
    cut = sys.argv.index("--")
    head, render_args = sys.argv[1:cut], sys.argv[cut + 1:]
    opts = {head[i][2:]: head[i + 1] for i in range(0, len(head), 2)}
    log = os.path.join(opts["work"], "control.log")
    os.environ["SERVE_FAKE_LOG"] = log
    os.environ["SERVE_FAKE_TEXCC"] = opts["texcc"]
    server, url = start_server(dict(opts, renderer=FAKE), render_args)
    page = None
    try:
        page = Page(url, server)
        page.wait("the hello", lambda s: s["hellos"] > 0 and s["frames"] > 0)
        find = page.driver.find_element
        for ctl in ("patches-scale", "patches-gain", "mask-threshold"):
            e = find(By.ID, "ctl-" + ctl)
            print(f"{ctl}: {e.get_attribute('type')} {e.get_attribute('min')}..{e.get_attribute('max')} "
                  f"value {e.get_attribute('value')}")
        e = find(By.ID, "ctl-patches-octaves")
        print(f"patches-octaves: {e.get_attribute('type')} {e.get_attribute('min')}..{e.get_attribute('max')}")
        rows = find(By.ID, "ctl-rustColor-stops").find_elements(By.CLASS_NAME, "row")
        pickers = [r.find_elements(By.CSS_SELECTOR, "input[type=color]") for r in rows]
        print(f"rustColor-stops: {len(rows)} rows, {sum(len(p) for p in pickers)} colour pickers")
        menu = Select(find(By.ID, "rewire-mask-noise"))
        print(f"rewire-mask-noise: {[o.text for o in menu.options]}")
        print(f"graph: {len(page.driver.find_elements(By.CSS_SELECTOR, '#graph rect'))} nodes, "
              f"{len(page.driver.find_elements(By.CSS_SELECTOR, '#graph path'))} links")
        find(By.ID, "ctl-mask-threshold").send_keys(Keys.ARROW_LEFT)
        print("sent: " + control_lines(log, 1)[-1])
        stops = find(By.ID, "ctl-rustColor-stops")
        stops.find_element(By.XPATH, "./button[text()='add stop']").click()
        target, value = control_lines(log, 2)[-1].split("=", 1)
        rows = json.loads(value)
        print(f"sent: {target}= {len(rows)} rows, the new one {rows[-1]}")
        stops = find(By.ID, "ctl-rustColor-stops")
        print(f"rustColor-stops now: {len(stops.find_elements(By.CLASS_NAME, 'row'))} rows")
        octaves = find(By.ID, "ctl-patches-octaves")
        octaves.clear()
        octaves.send_keys("7", Keys.TAB)
        print("sent: " + control_lines(log, 3)[-1])
        menu.select_by_value("grain")
        print("sent: " + control_lines(log, 4)[-1])
    finally:
        if page:
            page.driver.quit()
        server.terminate()
        print(f"server exit {server.wait(timeout=WAIT_S)}")


if __name__ == "__main__":
    main()
