# SPDX-License-Identifier: GPL-2.0-or-later
# Sphinx configuration of the BBPD documentation.
# Build (Debian's python3-sphinx 5.3; MathJax from Debian's libjs-mathjax, no network):
#   /usr/bin/python3 -m sphinx -W -b html doc /tmp/docbuild
import importlib.util
import os
import re

from docutils import nodes
from pygments.lexer import RegexLexer, bygroups
from pygments.token import Comment, Keyword, Name, Number, String, Text, Whitespace

here = os.path.dirname(os.path.abspath(__file__))


def local_extension(name):
    """A Sphinx extension of doc/_ext, loaded from its file, not through the import path."""
    spec = importlib.util.spec_from_file_location(f"bbpd_doc_{name}",
                                                  os.path.join(here, "_ext", f"{name}.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def plugin_version():
    """The project version from CMakeLists.txt (the plugin's BBPD_VERSION)."""
    with open(os.path.join(here, "..", "CMakeLists.txt"), encoding="utf-8") as fh:
        m = re.search(r"project\(bbpd VERSION ([0-9.]+)", fh.read())
    return m.group(1) if m else "unknown"


project = "BBPD"
author = "BBPD developers"
copyright = "2026, BBPD developers"
version = release = plugin_version()

extensions = ["sphinx.ext.mathjax"]    # plus doc/_ext/mathjax_local.py and mdinclude.py (setup)
exclude_patterns = ["_ext"]
source_suffix = {".rst": "restructuredtext"}
master_doc = "index"
highlight_language = "none"
html_theme = "alabaster"
html_title = f"BBPD {release}"
html_show_sourcelink = False
html_sidebars = {"**": ["about.html", "navigation.html", "searchbox.html"]}
numfig = False

# Markdown pages written beside the RST ones (benchmarks.rst renders them; the
# raw files are copied too so that they can be linked)
html_extra_path = [f for f in ("performance.md", "stability.md", "verification.md") if os.path.isfile(os.path.join(here, f))]


class LAMMPSLexer(RegexLexer):
    """LAMMPS input scripts: command word, comments, numbers, variables, strings.
    A catch-all rule keeps it from ever failing (Sphinx -W would turn that into an error)."""

    name = "LAMMPS"
    aliases = ["lammps"]
    tokens = {
        "root": [
            (r"^(\s*)([a-z_][\w/]*)", bygroups(Whitespace, Keyword)),
            (r"#.*$", Comment),
            (r"\$\{[^}]*\}|\$\([^)]*\)|\$\w|\bv_\w+|\b[cf]_\w+(\[\d+\])?", Name.Variable),
            (r'"[^"]*"|\'[^\']*\'', String),
            (r"-?\b\d+(\.\d*)?([eE][-+]?\d+)?\b|-?\.\d+([eE][-+]?\d+)?", Number),
            (r"\s+", Whitespace),
            (r"[^\s#$\"']+", Text),
            (r".", Text),
        ]
    }


LAMMPS_DOCS = "https://docs.lammps.org/"


def lammps_doc_link(app, env, node, contnode):
    """:doc:`fix nve <fix_nve>` that names no page of ours is a LAMMPS manual page:
    link it to docs.lammps.org instead of warning (the LAMMPS page names are stable)."""
    if node.get("reftype") != "doc":
        return None
    target = node["reftarget"]
    # our own pages (bbpd in the name) must exist: a broken link to them stays a warning
    if target in env.found_docs or "bbpd" in target or not re.fullmatch(r"[A-Za-z0-9_]+", target):
        return None
    ref = nodes.reference("", "", internal=False, refuri=f"{LAMMPS_DOCS}{target}.html")
    ref += contnode
    return ref


def setup(app):
    local_extension("mathjax_local").setup(app)
    local_extension("mdinclude").setup(app)
    app.add_lexer("LAMMPS", LAMMPSLexer)
    app.connect("missing-reference", lammps_doc_link)
