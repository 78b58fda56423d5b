# SPDX-License-Identifier: GPL-2.0-or-later
"""The per-CPU tables of the run-time SIMD choice (doc/performance.md), rendered from the
committed CSVs of perf/pair_vs_pmb.py and perf/row_floor.py. The Intel CSVs were typed into
that page by hand before the renderer existed: the renderer must give the same figures."""
import shutil

from bbpd.claims import perf


def test_the_simd_table_gives_the_intel_figures_typed_before():
    table = perf.simd_table("spr")
    # the hand table of "One plugin, three paths: Intel Xeon": plate / block per simd value
    assert "| auto | 5.35 / 86.40 | 16.2 | 80.99 / 805.0 | 9.9 | avx512, avx2 |" in table
    assert "| avx512 | 4.89 / 80.99 | **16.6** | 80.15 / 812.1 | 10.1 | avx512, avx512 |" in table
    assert "| avx2 | 4.72 / 72.68 | 15.4 | 77.32 / 803.4 | **10.4** | avx2, avx2 |" in table
    assert "| portable | 7.50 / 84.31 | 11.2 | 140.5 / 774.3 | 5.5 |" in table
    floor = perf.floor_table("spr")
    assert "| avx512 | 56.40 | 50.06 | 1.13 |" in floor and "| avx2 | 71.40 | 52.93 | 1.35 |" in floor


def test_the_findings_name_autos_choice_and_the_fastest_forced_path():
    text = perf.simd_findings("spr")
    # by ratio avx512 on the plate, though avx2's own loop time was the shorter (peri/pmb's time
    # moved between the invocations)
    assert ("Plate: auto ran avx512 (16.2× `peri/pmb`, 5.35 ms/step); the fastest forced path is "
            "avx512 by ratio (16.6×) and avx2 by our own loop time (4.72 ms/step), the portable "
            "loop 11.2×.") in text
    assert ("Block: auto ran avx2 (9.9× `peri/pmb`, 80.99 ms/step); the fastest forced path is "
            "avx2 by ratio (10.4×) and avx2 by our own loop time (77.32 ms/step)") in text
    assert "plate 72.68-86.40 ms/step (19 % apart)" in text
    assert "avx512 1.13×, avx2 1.35×, portable 1.02×" in text
    assert "LAMMPS's benchmark scene 1.18 / 37.74 ms/step, 31.9× (auto: avx512)" in text
    assert "memory 17.9 bytes per bond at the margin" in text


def test_the_bold_ratio_follows_the_data(tmp_path, monkeypatch):
    # make the portable loop the fastest on the plate: the bold moves to it
    for path in perf.RESULTS.glob("spr-*"):
        shutil.copy(path, tmp_path / path.name)
    src = tmp_path / "spr-simd-portable.csv"
    text = src.read_text()
    assert ",7.5033," in text
    src.write_text(text.replace(",7.5033,", ",1.0000,", 1))
    monkeypatch.setattr(perf, "RESULTS", tmp_path)
    table = perf.simd_table("spr")
    assert "| portable | 1.00 / 84.31 | **84.3** |" in table
    assert "**16.6**" not in table


def test_a_kernel_measured_again_keeps_its_earlier_row(tmp_path, monkeypatch):
    for path in perf.RESULTS.glob("spr-*"):
        shutil.copy(path, tmp_path / path.name)
    # the avx512 kernel's earlier measurement: its portable figures, say
    shutil.copy(tmp_path / "spr-simd-portable.csv", tmp_path / f"spr-simd-avx512-{perf.BEFORE}.csv")
    shutil.copy(tmp_path / "spr-row-floor-portable.csv", tmp_path / f"spr-row-floor-avx512-{perf.BEFORE}.csv")
    monkeypatch.setattr(perf, "RESULTS", tmp_path)
    table = perf.simd_table("spr")
    assert f"| avx512 ({perf.BEFORE_LABEL}) | 7.50 / 84.31 | 11.2 |" in table
    assert "**16.6**" in table    # the earlier row is never the best
    assert f"| avx512 ({perf.BEFORE_LABEL}) | 138.53 | 136.23 | 1.02 |" in perf.floor_table("spr")
    assert ("plate 7.50 → 4.89 ms/step, block 140.5 → 80.15 ms/step with plain loads."
            in perf.simd_findings("spr"))
