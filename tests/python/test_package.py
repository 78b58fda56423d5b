# SPDX-License-Identifier: GPL-2.0-or-later
"""python/ is an installable package: pip installs it offline with Debian's setuptools, and
nothing in the repository edits the import path to find it."""
import re
import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PYTHON = "/usr/bin/python3"


def test_editable_install_offline_into_a_venv(tmp_path):
    # a copy of python/, so that the install's metadata is not written into the checkout
    src = tmp_path / "python"
    shutil.copytree(ROOT / "python", src,
                    ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    venv = tmp_path / "venv"
    subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    pip = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-index",
                          "--no-build-isolation", "-e", str(src)],
                         capture_output=True, text=True, timeout=300)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    out = subprocess.run([str(venv / "bin" / "python"), "-c",
                          "import bbpd, bbpd.freund, bbpd.benchmarks.mode1; print(bbpd.__file__)"],
                         cwd=tmp_path, capture_output=True, text=True, check=True)
    assert Path(out.stdout.strip()).resolve() == (src / "bbpd" / "__init__.py").resolve()


def test_package_version_is_the_plugin_version():
    project = (ROOT / "python" / "pyproject.toml").read_text()
    cmake = (ROOT / "CMakeLists.txt").read_text()
    ours = re.search(r'^version = "([0-9.]+)"', project, re.M).group(1)
    plugin = re.search(r"project\(bbpd VERSION ([0-9.]+)", cmake).group(1)
    assert ours == plugin


def test_nothing_patches_sys_path():
    tracked = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                             cwd=ROOT, capture_output=True, text=True,
                             check=True).stdout.split()
    needle = "sys." + "path"    # not written out whole, so that this file passes its own check
    offenders = [f for f in tracked if f.endswith(".py") and (ROOT / f).is_file()
                 and needle in (ROOT / f).read_text(encoding="utf-8")]
    assert not offenders, f"{needle} edited in {offenders}: use tools/python or pip install -e"
