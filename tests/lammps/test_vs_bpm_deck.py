# SPDX-License-Identifier: GPL-2.0-or-later
"""perf/vs_bpm.py runs as its docs say: one round of the LPS deck, the thermo check against
peri/lps, and with --forced a variant per path forced by the simd keyword (the portable loop
here: every CPU has it), whose CSV rows name the path the setup report gave."""
import csv
import subprocess

from bbpd.runner import ROOT


def test_a_forced_variant_runs_the_path_it_names(tmp_path):
    out = tmp_path / "run.csv"
    proc = subprocess.run([str(ROOT / "tools" / "python"), "perf/vs_bpm.py", "--models", "lps", "--rounds", "1",
                           "--ranks", "1", "--forced", "portable", "--csv", str(out)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert "check lps: pe, ke at steps 0 and 200" in proc.stdout and "(ok)" in proc.stdout
    rows = {r["variant"]: r for r in csv.DictReader(open(out))}
    assert set(rows) == {"legacy", "ours", "ours-portable"}
    assert rows["ours-portable"]["path"] == "portable"
    assert rows["ours"]["path"] in ("portable", "avx2", "avx512")
    assert all(float(r["loop_s"]) > 0.0 for r in rows.values())
