"""The documentation in doc/ builds with Debian's Sphinx without a single warning,
and it documents what the plugin registers and parses.

The style, keyword and default lists are read from the C++ sources, so a style or
keyword added to src/ without a doc entry fails here.
"""
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "doc"
SRC = ROOT / "src"
PYTHON = "/usr/bin/python3"    # Debian's python3-sphinx lives there

# LAMMPS index-entry prefix of each plugin style kind
INDEX_PREFIX = {"pair": "pair_style", "fix": "fix", "compute": "compute"}


def registered_styles():
    """(kind, name, info) of every style bbpdplugin.cpp registers."""
    text = (SRC / "bbpdplugin.cpp").read_text()
    styles, kind, name = [], None, None
    for line in text.splitlines():
        m = re.search(r'plugin\.(style|name|info)\s*=\s*"([^"]*)"', line)
        if not m:
            continue
        if m.group(1) == "style":
            kind = m.group(2)
        elif m.group(1) == "name":
            name = m.group(2)
        else:
            styles.append((kind, name, m.group(2)))
    return styles


def doc_pages():
    return {p.name: p.read_text() for p in DOC.glob("*.rst")}


def section(text, title):
    """The body of a LAMMPS-style section ('Title' underlined with double quotes)."""
    m = re.search(rf'^{re.escape(title)}\n"+\n(.*?)(?=^\S[^\n]*\n"{{3,}}\n|\Z)', text, re.S | re.M)
    assert m, f"no section '{title}'"
    return m.group(1)


def test_docs_build_without_warnings(tmp_path):
    try:
        subprocess.run([PYTHON, "-c", "import sphinx"], check=True, capture_output=True)
    except (OSError, subprocess.CalledProcessError):
        pytest.fail("Sphinx is missing: install Debian's python3-sphinx (tools/bootstrap does)")
    out = subprocess.run(
        [PYTHON, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         "-d", str(tmp_path / "doctrees"), str(DOC), str(tmp_path / "html")],
        capture_output=True, text=True)
    assert out.returncode == 0 and not out.stderr.strip(), \
        f"sphinx failed (rc {out.returncode}):\n{out.stderr}{out.stdout}"
    for page in DOC.glob("*.rst"):
        assert (tmp_path / "html" / (page.stem + ".html")).is_file(), page.name


def test_registered_styles_are_found():
    # guard against a parser that silently finds nothing
    names = {(k, n) for k, n, _ in registered_styles()}
    assert ("pair", "bbpd/gaussian") in names and ("compute", "bbpd/damage/atom") in names


@pytest.mark.parametrize("kind,name,info", registered_styles(),
                         ids=[f"{k} {n}" for k, n, _ in registered_styles()])
def test_every_registered_style_has_a_page(kind, name, info):
    entry = f"{INDEX_PREFIX[kind]} {name}"
    pages = [p for p, text in doc_pages().items()
             if re.search(rf"^\.\. index:: {re.escape(entry)}\s*$", text, re.M)]
    assert pages, f"no doc page has '.. index:: {entry}'"
    if "internal" in info:
        return    # created by another style, documented on that style's page
    text = doc_pages()[pages[0]]
    title = f"{entry} command"
    assert re.search(rf"^{re.escape(title)}\n=+\n", text, re.M), f"{pages[0]} has no title '{title}'"
    for heading in ("Syntax", "Examples", "Description", "Restrictions", "Related commands",
                    "Default"):
        section(text, heading)
    if kind == "compute":
        section(text, "Output info")


def keywords(source, function):
    """String literals a parsing function compares its arguments with."""
    text = (SRC / source).read_text()
    m = re.search(rf"::{function}\(.*?\n\}}\n", text, re.S)
    assert m, f"no {function} in {source}"
    body = m.group(0)
    words = set(re.findall(r'\b(?:key|m|g)\s*==\s*"([^"]+)"', body))
    words |= set(re.findall(r'strcmp\(arg\[[^\]]+\],\s*"([^"]+)"\)', body))
    return words


@pytest.mark.parametrize("source,function,page", [
    ("pair_bbpd.cpp", "settings", "pair_bbpd.rst"),
    ("pair_bbpd.cpp", "coeff", "pair_bbpd.rst"),
    ("fix_bbpd_notch.cpp", "FixBBPDNotch", "fix_bbpd_notch.rst"),
])
def test_every_keyword_is_in_the_syntax(source, function, page):
    words = keywords(source, function)
    assert words, f"found no keywords in {source}:{function}"
    syntax = section(doc_pages()[page], "Syntax")
    missing = sorted(w for w in words if f"*{w}*" not in syntax)
    assert not missing, f"{page} Syntax does not list {missing} (parsed in {source}:{function})"


def test_pair_defaults_match_the_source():
    text = (SRC / "pair_bbpd.cpp").read_text()
    default = section(doc_pages()["pair_bbpd.rst"], "Default")
    for keyword, constant in (("dt/safety", "DT_SAFETY_DEFAULT"),
                              ("contact/distance", "CONTACT_FACTOR_DEFAULT")):
        value = float(re.search(rf"{constant}\s*=\s*([0-9.eE+-]+);", text).group(1))
        m = re.search(rf"{re.escape(keyword)} = ([0-9.]+)", default)
        assert m and float(m.group(1)) == value, \
            f"pair_bbpd.rst Default: '{keyword} = {value}' expected (src {constant})"


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
