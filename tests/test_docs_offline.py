"""The HTML documentation works on a machine without a network: no page loads a script or
style sheet from elsewhere, and MathJax (Debian's, copied into the build) typesets every
formula of the main pages in a headless Chromium, leaving no raw TeX in the rendered text."""
import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PYTHON = "/usr/bin/python3"
MAIN_PAGES = ("pair_bbpd", "compute_bbpd_dsif", "theory", "benchmarks")
RAW_TEX = (r"\(", r"\)", r"\[", r"\]", "$$")
# long enough of virtual time for MathJax to load and typeset a page (it is not wall time)
VIRTUAL_TIME_MS = 20000
CHROMIUM_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                  "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync")


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    out = tmp_path_factory.mktemp("doc")
    proc = subprocess.run([PYTHON, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                           "-d", str(out / "doctrees"), str(ROOT / "doc"), str(out / "html")],
                          capture_output=True, text=True)
    assert proc.returncode == 0, f"sphinx failed:\n{proc.stderr}{proc.stdout}"
    return out / "html"


class Assets(HTMLParser):
    """Every script, style sheet, image and frame a page loads."""

    def __init__(self):
        super().__init__()
        self.urls = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in ("script", "img", "iframe", "embed", "source") and a.get("src"):
            self.urls.append(a["src"])
        elif tag == "link" and a.get("href") and a.get("rel") != "canonical" \
                and not {"next", "prev", "index", "search"} & set((a.get("rel") or "").split()):
            self.urls.append(a["href"])


class VisibleText(HTMLParser):
    """The text a reader sees: everything outside <script> and <style>."""

    def __init__(self):
        super().__init__()
        self.hidden = 0
        self.parts = []

    def handle_starttag(self, tag, attrs):
        self.hidden += tag in ("script", "style")

    def handle_endtag(self, tag):
        self.hidden -= tag in ("script", "style")

    def handle_data(self, data):
        if not self.hidden:
            self.parts.append(data)


def remote(url):
    return bool(re.match(r"^([a-z][a-z0-9+.-]*:)?//", url, re.I)) and not url.startswith("file:")


def test_no_page_loads_from_the_network(html):
    pages = sorted(html.rglob("*.html"))
    assert len(pages) >= len(MAIN_PAGES)
    for page in pages:
        parser = Assets()
        parser.feed(page.read_text(encoding="utf-8"))
        loaded = [u for u in parser.urls if remote(u)]
        assert not loaded, f"{page.name} loads from the network: {loaded}"
        for url in parser.urls:    # and what it loads is in the build
            local = (page.parent / url.split("?")[0].split("#")[0]).resolve()
            assert local.is_file(), f"{page.name} loads {url}, which the build lacks"
    for css in html.rglob("*.css"):
        imports = re.findall(r"""(?:@import|url\()\s*["']?((?:[a-z]+:)?//[^"')\s]+)""",
                             css.read_text(encoding="utf-8", errors="replace"), re.I)
        assert not imports, f"{css.name} loads from the network: {imports}"


def test_mathjax_is_served_from_the_build(html):
    text = (html / "theory.html").read_text(encoding="utf-8")
    m = re.search(r'<script[^>]*src="(_static/mathjax/MathJax\.js[^"]*)"', text)
    assert m, "theory.html does not load MathJax from _static/mathjax"
    assert (html / "_static" / "mathjax" / "MathJax.js").is_file()


def offline(cmd):
    """cmd in a network namespace of its own when the system allows it (root on Linux)."""
    unshare = shutil.which("unshare")
    if unshare and subprocess.run([unshare, "-n", "true"], capture_output=True).returncode == 0:
        return [unshare, "-n"] + cmd
    return cmd


def rendered_dom(page, profile):
    chromium = shutil.which("chromium")
    if chromium is None:
        pytest.fail("chromium is missing: install Debian's chromium (tools/bootstrap does)")
    cmd = offline([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}",
                   f"--virtual-time-budget={VIRTUAL_TIME_MS}", "--dump-dom", page.as_uri()])
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    assert proc.returncode == 0 and "</html>" in proc.stdout, \
        f"chromium failed on {page.name} (rc {proc.returncode}):\n{proc.stderr[-2000:]}"
    return proc.stdout


@pytest.mark.parametrize("name", MAIN_PAGES)
def test_math_is_typeset_offline(html, name, tmp_path):
    page = html / f"{name}.html"
    source = page.read_text(encoding="utf-8")
    formulas = source.count('class="math notranslate nohighlight"')
    assert formulas > 0, f"{name}.html has no formula: the check below would prove nothing"
    dom = rendered_dom(page, tmp_path / "chromium-profile")
    visible = VisibleText()
    visible.feed(dom)
    text = "".join(visible.parts)
    raw = {d: text.count(d) for d in RAW_TEX if d in text}
    assert not raw, f"{name}.html shows raw TeX after rendering: {raw}"
    assert "Math Processing Error" not in text
    typeset = len(re.findall(r'class="mjx-chtml[ "]', dom))
    assert typeset >= formulas, f"{name}.html: {typeset} typeset formulas of {formulas}"
