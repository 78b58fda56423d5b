# SPDX-License-Identifier: GPL-2.0-or-later
"""The timing probes of doc/performance.md still fit the kernel they alter.

Each patch of perf/probes is a probe whose timing the page gives (perf/row_floor.py builds the
plugin with row_floor.patch applied); a change to the source that a patch no longer fits would
leave the documented figure unreproducible.
"""
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PATCH = ROOT / "perf" / "probes" / "row_floor.patch"


@pytest.mark.skipif(shutil.which("git") is None or not (ROOT / ".git").exists(),
                    reason="needs git and a clone")
@pytest.mark.parametrize("patch", sorted((ROOT / "perf" / "probes").glob("*.patch")), ids=lambda p: p.name)
def test_every_probe_patch_applies(patch):
    """every probe doc/performance.md times still fits the source it alters"""
    r = subprocess.run(["git", "apply", "--check", str(patch)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, f"update {patch.relative_to(ROOT)}: {r.stderr}"


def test_every_probe_switch_is_in_the_patch():
    text = PATCH.read_text()
    src = (ROOT / "perf" / "row_floor.py").read_text()
    for switch in ("NO_SQRT_DIV", "NO_MEMORY", "RSQRT14_FMA", "FLOAT_GUESS"):
        assert f"BBPD_PROBE_{switch}" in text
        assert f'"{switch}"' in src
