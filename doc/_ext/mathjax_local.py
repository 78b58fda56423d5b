# SPDX-License-Identifier: GPL-2.0-or-later
"""Serve MathJax from the built HTML itself, so that formulas render without a network.

Sphinx's mathjax extension loads MathJax from a CDN by default.  This extension points
``mathjax_path`` at ``_static/mathjax/`` and copies there the part of Debian's MathJax 2
(packages ``libjs-mathjax`` and ``fonts-mathjax``, installed by ``tools/test``) that the
TeX input and CommonHTML output need.  ``BBPD_MATHJAX_DIR`` selects another MathJax 2 tree.
"""

import os
import shutil

from sphinx.errors import ConfigError

DEBIAN_MATHJAX = "/usr/share/javascript/mathjax"
COMBINED_CONFIG = "TeX-AMS_CHTML"    # TeX input, AMS macros, CommonHTML output (web fonts)
# what COMBINED_CONFIG loads on demand (files, or folders copied whole)
NEEDED = ("MathJax.js", f"config/{COMBINED_CONFIG}.js", "extensions", "jax/input/TeX",
          "jax/output/CommonHTML", "jax/element", "fonts/HTML-CSS/TeX/woff",
          "localization/en")


def source_dir():
    path = os.environ.get("BBPD_MATHJAX_DIR", DEBIAN_MATHJAX)
    if not os.path.isfile(os.path.join(path, "MathJax.js")):
        raise ConfigError(f"MathJax 2 not found in {path}: install Debian's libjs-mathjax and "
                          "fonts-mathjax (tools/test does), or set BBPD_MATHJAX_DIR")
    return path


def copy_mathjax(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    src, dest = source_dir(), os.path.join(app.outdir, "_static", "mathjax")
    for rel in NEEDED:
        origin = os.path.join(src, rel)
        if not os.path.exists(origin):
            raise ConfigError(f"MathJax in {src} lacks {rel}: install Debian's fonts-mathjax")
        target = os.path.join(dest, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if os.path.isdir(origin):    # Debian links the fonts in: copy the files themselves
            shutil.copytree(origin, target, symlinks=False, dirs_exist_ok=True)
        else:
            shutil.copyfile(origin, target)


def use_local_mathjax(app, config):
    source_dir()    # fail at configuration time, not after the whole build
    config.mathjax_path = f"mathjax/MathJax.js?config={COMBINED_CONFIG}"    # under _static/


def setup(app):
    app.connect("config-inited", use_local_mathjax)
    app.connect("build-finished", copy_mathjax)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
