# SPDX-License-Identifier: GPL-2.0-or-later
"""Licence and source hygiene: a GPL-2.0-compatible LICENSE, an SPDX line in every source
file, LAMMPS's .clang-format, and comments that cite no tracker numbers and hold no timings."""
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SPDX = "SPDX-License-Identifier: GPL-2.0-or-later"
SPDX_DIRS = ("src", "tests/unit", "python", "tools", "perf", "examples/python")
SOURCE = (".cpp", ".h", ".py", ".toml", ".txt", ".sh", "")    # "" = the scripts in tools/
HYGIENE_DIRS = ("src", "tests", "python", "tools", "perf", "doc/conf.py", "doc/_ext",
                "examples/python", "CMakeLists.txt")


def tracked(*paths):
    out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard",
                          "--", *paths], cwd=ROOT, capture_output=True, text=True, check=True)
    return [ROOT / f for f in out.stdout.split() if (ROOT / f).is_file()]


def test_licence_is_gpl2_or_later():
    text = (ROOT / "LICENSE").read_text()
    assert "GNU GENERAL PUBLIC LICENSE" in text and "Version 2, June 1991" in text
    assert "either version 2\nof the License, or (at your option) any later version" in text
    project = (ROOT / "python" / "pyproject.toml").read_text()
    assert 'license = {text = "GPL-2.0-or-later"}' in project


def test_every_source_file_has_an_spdx_line():
    files = [f for f in tracked(*SPDX_DIRS) if f.suffix in SOURCE and f.name != "README.md"]
    assert len(files) > 30
    missing = [str(f.relative_to(ROOT)) for f in files
               if SPDX not in "\n".join(f.read_text(encoding="utf-8").splitlines()[:3])]
    assert not missing, f"no '{SPDX}' in the first lines of {missing}"


def test_clang_format_is_lammps_style():
    ours = (ROOT / ".clang-format").read_text()
    env = ROOT / "build" / "lammps-20260704" / "bbpd-env.sh"
    if env.is_file():    # compare with the LAMMPS source tree tools/bootstrap fetched
        prefix = re.search(r"^BBPD_LAMMPS_PREFIX=(.*)$", env.read_text(), re.M).group(1)
        theirs = Path(prefix) / "source" / "src" / ".clang-format"
        if theirs.is_file():
            assert ours == theirs.read_text()
            return
    for key, value in (("BasedOnStyle", "LLVM"), ("ColumnLimit", "100"), ("IndentWidth", "2")):
        assert re.search(rf"^{key}:\s+{value}$", ours, re.M), key


COMMENT = {".py": r"#.*|\"\"\"[\s\S]*?\"\"\"", ".cpp": r"//.*|/\*[\s\S]*?\*/",
           ".h": r"//.*|/\*[\s\S]*?\*/", "": r"#.*", ".sh": r"#.*", ".txt": r"#.*"}
TRACKER = re.compile(r"\b(issue|ticket|bug)s?\s*#?\d+|(?<![\w$&{])#\d+\b", re.I)
TIMING = re.compile(r"(~|\babout |\bmeasured[^.\n]*?)\d[\d.,]*\s*(ms|min|minutes|seconds|s)\b"
                    r"|\d\s*ms/step|\bon (one|\d) cores?\b.*\d\s*(s|min)\b", re.I)


@pytest.mark.parametrize("pattern,what", [(TRACKER, "a tracker number"),
                                          (TIMING, "a measured timing")])
def test_comments_cite_no_tracker_numbers_and_hold_no_timings(pattern, what):
    offenders = []
    for f in tracked(*HYGIENE_DIRS):
        if f.suffix not in COMMENT or f == Path(__file__):
            continue
        for comment in re.finditer(COMMENT[f.suffix], f.read_text(encoding="utf-8")):
            m = pattern.search(comment.group(0))
            if m:
                offenders.append(f"{f.relative_to(ROOT)}: ...{m.group(0)}...")
    assert not offenders, f"comments with {what} (they belong in doc/ or the README):\n" + \
        "\n".join(offenders)


RUN_OUTPUTS = (".dump", ".dat", ".lammpstrj", ".restart", ".png", ".jpg")    # what a run writes


def test_no_run_outputs_at_the_repository_root():
    # an example run from the root writes its dumps there; they belong to no one
    out = subprocess.run(["git", "ls-files", "--cached"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout.split()
    root = [p for p in out if "/" not in p and p.endswith(RUN_OUTPUTS)]
    assert root == [], f"run outputs tracked at the repository root: {root}"
