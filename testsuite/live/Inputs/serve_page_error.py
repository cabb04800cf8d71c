"""A failure of the page's own script is shown in its errors panel, never "none": the fake
texrender sends a schema whose first node's inputs are a number ($SERVE_FAKE_BROKEN_SCHEMA), the
page's hello handler throws, and the panel says so; frames still arrive.

  serve_page_error.py --texcc TEXCC --work DIR -- SCENE --textures TEX
"""
import os
import sys

from serve_browser import Page, start_server
from waits import WAIT_S  # noqa: E402

FAKE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "serve_fake_texrender.py")


def main():
    cut = sys.argv.index("--")
    head, render_args = sys.argv[1:cut], sys.argv[cut + 1:]
    opts = {head[i][2:]: head[i + 1] for i in range(0, len(head), 2)}
    os.environ["SERVE_FAKE_BROKEN_SCHEMA"] = "1"
    server, url = start_server(dict(opts, renderer=FAKE), render_args)
    page = None
    try:
        page = Page(url, server)
        page.wait("the page's error", lambda s: s["frames"] > 0
                  and page.text("errors").startswith("page error"), timeout=WAIT_S)
        print("errors panel: " + page.text("errors").splitlines()[0])
        print(f"frames keep coming: {page.state()['frames'] > 0}")
    finally:
        if page:
            page.driver.quit()
        server.terminate()
        print(f"server exit {server.wait(timeout=WAIT_S)}")


if __name__ == "__main__":
    main()
