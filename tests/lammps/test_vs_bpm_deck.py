# SPDX-License-Identifier: GPL-2.0-or-later
"""perf/vs_bpm.py's inputs run as they say: ours with auto's path, and with --forced a path
forced by the simd keyword (the portable loop here: every CPU has it)."""
import importlib
import sys

from bbpd.runner import LMP, ROOT


def vs_bpm():
    sys.path.insert(0, str(ROOT / "perf"))
    try:
        return importlib.import_module("vs_bpm")
    finally:
        sys.path.pop(0)


def test_a_forced_variant_runs_the_path_it_names(tmp_path):
    mod = vs_bpm()
    for variant, said in (("ours", "(auto:"), ("ours-portable", "portable path (forced by the simd keyword)")):
        script = mod.deck("lps", variant).replace(f"run {mod.STEPS}", "run 2")
        assert ("simd" in script) == (variant != "ours")
        out = mod.run(LMP, script, 1, tmp_path / variant)
        assert said in out
        if variant != "ours":
            assert mod.timing(out)["path"] == "portable"
