# SPDX-License-Identifier: GPL-2.0-or-later
"""The numbers of the READMEs and docs agree with the result files they are generated from
(python -m bbpd.claims; no LAMMPS run): every generated block as rendered from the committed
reference CSVs, every speed ratio with its CPU; and the check reports a table edited by hand,
and data that changed under an unchanged text."""
import shutil
from pathlib import Path

import pytest

from bbpd import claims
from bbpd import markers
from bbpd.claims.blocks import BLOCKS, KW, MODE1, MODE2, README
from bbpd.claims.data import OTHERS, REFERENCES, STEP_TIMES, Data, import_report
from bbpd.csvfile import read_csv, write_csv

ROOT = Path(__file__).resolve().parents[1]

# a table per file whose body, with one number changed, the check must report
EDITED = {MODE1: "mode1-table3", MODE2: "mode2-jtable", KW: "kw-table", README: "zen5-readme"}


def text_of(rel):
    return (ROOT / rel).read_text(encoding="utf-8")


def with_block(rel, name, body):
    """The file's text with block `name` holding `body`."""
    return markers.replace(rel, text_of(rel), lambda kind, n: body if n == name else None)


def test_text_and_data_agree():
    problems = claims.check()
    assert not problems, ("README/doc numbers disagree with their data; regenerate with "
                          "tools/python -m bbpd.claims --write (or fix the data):\n"
                          + "\n".join(problems))


def test_every_block_is_in_its_file():
    for rel, blocks in BLOCKS.items():
        found = {name for _, name, _ in markers.blocks(rel, text_of(rel))}
        assert set(blocks) <= found, f"{rel}: blocks {sorted(set(blocks) - found)} missing"


@pytest.mark.parametrize("rel", sorted(EDITED))
def test_an_edited_table_is_reported(rel):
    """The negative control: a table with one number changed by hand fails the check."""
    name = EDITED[rel]
    body = dict((n, b) for _, n, b in markers.blocks(rel, text_of(rel)))[name]
    assert not [p for p in claims.check_text(rel, text_of(rel)) if name in p]
    digit = next(i for i, ch in enumerate(body) if ch.isdigit() and body[i - 1] in " |/")
    edited = body[:digit] + str((int(body[digit]) + 1) % 10) + body[digit + 1:]
    problems = claims.check_text(rel, with_block(rel, name, edited))
    assert any(f"block {name} disagrees with its data" in p for p in problems), problems


def test_old_headline_without_cpu_is_reported():
    text = text_of(README).replace(
        "## Two commands (Debian 12)\n",
        "## Two commands (Debian 12)\n\nThe plugin runs 17.6x faster than LAMMPS's own `peri/pmb`.\n")
    assert "17.6x" in text
    problems = claims.check_text(README, text)
    assert any("speed ratio '17.6x' without a CPU" in p for p in problems), problems


def test_removed_block_is_reported():
    text = text_of(MODE2)
    start = text.index("<!-- bbpd:table mode2-jtable -->")
    end = text.index("<!-- /bbpd:table -->", start) + len("<!-- /bbpd:table -->")
    problems = claims.check_text(MODE2, text[:start] + text[end:])
    assert any("block mode2-jtable is missing" in p for p in problems), problems


def test_changed_data_is_reported(tmp_path):
    """Unchanged text over changed data fails too: the Mode-II CSV with one ratio moved."""
    comments, rows = read_csv(REFERENCES["mode2"])
    rows[0]["ratio_end"] += 0.05
    changed = tmp_path / "mode2.csv"
    write_csv(changed, rows, comments)
    data = Data({**REFERENCES, "mode2": changed})
    problems = claims.check_text(MODE2, text_of(MODE2), data)
    assert any("block mode2-jtable disagrees" in p for p in problems), problems


def test_reference_files_name_command_and_cpu():
    for name, path in {**REFERENCES, **OTHERS, "quickstart_times": STEP_TIMES}.items():
        comments, rows = read_csv(path)
        assert rows, f"{path} has no rows"
        assert comments and comments[0].startswith("made by: "), path
        assert any(c.startswith("machine: ") or "CPU" in c for c in comments), \
            f"{path} names no CPU"


def test_import_takes_report_results(tmp_path, monkeypatch):
    """--from REPORT copies report/results/<benchmark>.csv over the references."""
    refs = {name: tmp_path / "refs" / path.name for name, path in REFERENCES.items()}
    monkeypatch.setattr("bbpd.claims.data.REFERENCES", refs)
    (tmp_path / "report" / "results").mkdir(parents=True)
    shutil.copyfile(REFERENCES["mode2"], tmp_path / "report" / "results" / "mode2.csv")
    written = import_report(tmp_path / "report")
    assert written == [refs["mode2"]]
    assert refs["mode2"].read_text() == REFERENCES["mode2"].read_text()


def test_the_verification_page_states_what_the_data_give():
    """doc/verification.md's list under the benchmark table, by hand: checked against the CSVs"""
    from bbpd.claims import paper
    data = Data()
    disp = {r["kernel"]: r["phase_kdx2.5"] for r in data.rows("dispersion")}
    assert max(disp, key=disp.get) == "gaussian" and min(disp, key=disp.get) == "constant"
    t3 = paper.mode1_bench.PAPER_TABLE3
    at = paper.at(data.rows(paper.MODE1), paper.TABLE3_DX)
    assert sorted(at, key=lambda k: at[k]["consistent_l2"]) == sorted(at, key=lambda k: t3[k][1])
    assert max(abs(at[k][c] - t3[k][i]) for k in ("constant", "triangular")
               for i, c in ((0, "consistent_peak"), (1, "consistent_l2"))) < 2.1
    t2 = paper.mode1_bench.PAPER_TABLE2
    g = [r["consistent_l2"] for r in paper.gauss(data.rows("mode1"))]
    assert g == sorted(g, reverse=True)
    assert all(r["consistent_l2"] < t2[round(r["dx_m"], 6)][1] for r in paper.gauss(data.rows("mode1")))
    assert max(r["j_peak"] for r in data.rows(paper.MODE1)) < 1.65
    assert paper.mode2_excess(data) == "12–29 %"
    ratio = {(r["kernel"], r["dx_m"]): r["ratio_end"] for r in data.rows(paper.MODE2)}
    grids = paper.grids(data.rows(paper.MODE2))
    assert all(ratio[k, grids[-1]] >= ratio[k, grids[0]] for k in ("constant", "triangular", "gaussian"))
    initiation, exp = paper.kw_bench.PAPER_INITIATION_US, paper.kw_bench.EXPERIMENT_ANGLE_DEG
    flat = [exp - r["angle_deg"] for r in paper.at(data.rows(paper.KW), 1.0e-3).values()]
    assert 8.5 <= min(flat) and max(flat) < 10.5
    band = {k: r["damage_band_us"] for k, r in paper.at(data.rows(paper.KW), 1.0e-3).items()}
    assert sorted(band, key=band.get) == sorted(initiation, key=initiation.get)


def test_the_mode2_readme_states_what_the_data_give():
    """examples/mode2-central-crack/README.md, by hand: the extrapolation's excess per grid and
    its kernel rankings; J's peak errors, its rankings and its ratio at the window end per
    kernel; the tips' antisymmetry"""
    rows = Data().rows("mode2")
    at = {dx: {r["kernel"]: r for r in rows if r["dx_m"] == dx} for dx in (1e-3, 5e-4, 2.5e-4)}

    def rng(dx, col, scale=1.0, off=0.0):
        v = [scale * (r[col] - off) for r in at[dx].values()]
        return round(min(v), 1), round(max(v), 1)

    def order(dx, col):
        return [k for k, _ in sorted(at[dx].items(), key=lambda kv: kv[1][col])]
    assert [rng(dx, "ratio_end", 100.0, 1.0) for dx in at] == [(11.9, 20.5), (16.8, 28.9), (20.1, 25.6)]
    assert order(1e-3, "l2") == ["gaussian", "triangular", "constant"]
    assert order(5e-4, "l2") == ["triangular", "constant", "gaussian"]
    assert order(2.5e-4, "l2") == ["constant", "triangular", "gaussian"]
    assert order(1e-3, "peak") == ["triangular", "constant", "gaussian"]
    assert order(2.5e-4, "peak") == ["constant", "gaussian", "triangular"]
    assert [rng(dx, "j_peak") for dx in at] == [(2.2, 7.5), (0.5, 4.7), (0.4, 2.6)]
    assert order(1e-3, "j_peak") == ["gaussian", "triangular", "constant"]
    assert order(5e-4, "j_peak") == ["triangular", "gaussian", "constant"]
    assert order(2.5e-4, "j_peak") == ["gaussian", "triangular", "constant"]
    assert [round(at[dx]["constant"]["j_ratio_end"], 3) for dx in at] == [0.925, 0.953, 0.974]
    assert [round(at[dx]["gaussian"]["j_ratio_end"], 3) for dx in at] == [0.978, 1.018, 1.004]
    assert max(r["left_right"] for r in rows) < 2.5e-10 and max(r["ki_over_kii"] for r in rows) < 1.4e-4


def test_the_mode1_readme_states_what_the_data_give():
    """examples/mode1-semi-infinite/README.md, by hand: rankings, the paper's numbers, the
    J-integral's errors, the symmetry checks and the tips table's reading"""
    import re
    from bbpd.claims import paper
    data = Data()
    rows = data.rows("mode1")
    t3 = paper.mode1_bench.PAPER_TABLE3
    at = paper.at(data.rows(paper.MODE1), paper.TABLE3_DX)

    def order(col, sel=at):
        return sorted(sel, key=lambda k: sel[k][col])
    assert order("consistent_l2") == order("consistent_peak") == order("paper_peak") == \
        ["gaussian", "triangular", "constant"]
    assert order("paper_l2") == ["triangular", "gaussian", "constant"]
    diffs = [abs(at[k][c] - t3[k][i]) for k in ("constant", "triangular")
             for i, c in ((0, "consistent_peak"), (1, "consistent_l2"))]
    assert (round(min(diffs), 1), round(max(diffs), 1)) == (0.2, 2.1)
    g = paper.gauss(data.rows("mode1"))
    assert [round(r["consistent_l2"], 2) for r in g] == [4.39, 2.33, 1.57]
    assert [round(r["consistent_peak"], 2) for r in g] == [1.19, 1.70, 0.83]
    assert round(100 * max(r["kii_over_ki"] for r in rows), 2) == 0.66 and round(100 * max(r["kii_j_over_k_j"] for r in rows), 2) == 0.72
    assert round(max(r["j_peak"] for r in rows), 1) == 1.6
    assert round(max(r["j_peak"] for r in rows if r["kernel"] == "gaussian"), 1) == 0.3
    assert (round(min(r["j_l2"] for r in rows), 1), round(max(r["j_l2"] for r in rows), 1)) == (0.1, 1.6)
    for dx, want in ((0.1, ["gaussian", "constant", "triangular"]), (0.05, ["gaussian", "triangular", "constant"]),
                     (0.025, ["gaussian", "triangular", "constant"])):
        assert order("j_peak", paper.at(data.rows(paper.MODE1), dx)) == want
    low = [100 * (1 - r["kmax_ratio_j"]) for r in rows if r["kernel"] == "constant"]
    assert (round(min(low), 1), round(max(low), 1)) == (0.5, 1.6)
    tips = data.rows("mode1_tips")
    end = [100 * (r["kmax_ratio"] - 1) for r in tips if r["tipshift_dx"] == 0.0]
    assert (round(min(end)), round(max(end))) == (14, 56)
    far = [r for r in tips if r["tipshift_dx"] == 0.5 and r["r1_dx"] >= 2]
    assert (round(min(r["consistent_peak"] for r in far), 2), round(max(r["consistent_peak"] for r in far), 2)) == (0.02, 0.13)
    # the tolerances the wrong-micromodulus paragraph quotes are the regression test's
    text = (ROOT / "tests" / "regression" / "test_mode1.py").read_text()
    assert re.search(r"^PEAK_TOL = 2.2\b", text, re.M) and re.search(r"^L2_TOL = 2.8\b", text, re.M)


def test_the_kalthoff_winkler_readme_states_what_the_data_give():
    """examples/kalthoff-winkler/README.md, 'Reading the table', by hand: initiation, angle,
    speed, symmetry and far-edge crack against results/kalthoff_winkler.csv"""
    from bbpd.claims import paper
    data = Data()
    rows = data.rows("kalthoff_winkler")
    initiation, exp = paper.kw_bench.PAPER_INITIATION_US, paper.kw_bench.EXPERIMENT_ANGLE_DEG
    g = {round(r["dx_m"] * 1e3, 2): r for r in rows if r["kernel"] == "gaussian"}
    assert [round(g[dx]["first_bond_us"], 1) for dx in (2.0, 1.0, 0.5)] == [12.0, 12.4, 12.3]
    assert [round(g[dx]["damage_band_us"], 1) for dx in (2.0, 1.0, 0.5)] == [23.0, 20.0, 17.4]
    assert [round(g[dx]["angle_deg"], 1) for dx in (2.0, 1.0, 0.5)] == [58.8, 61.1, 62.3]
    main = [r for r in rows if r["dx_m"] >= 1e-3]
    assert (round(min(r["first_bond_us"] for r in main), 1), round(max(r["first_bond_us"] for r in main), 1)) == (10.8, 12.4)
    at = paper.at(data.rows(paper.KW), 1.0e-3)
    late = [initiation[k] - r["first_bond_us"] for k, r in at.items()]
    assert (round(min(late), 1), round(max(late), 1)) == (8.7, 9.3)
    early = [initiation[k] - r["damage_band_us"] for k, r in at.items()]
    assert (round(min(early), 1), round(max(early), 1)) == (1.7, 1.9)
    ang = {k: r["angle_deg"] for k, r in at.items()}
    assert round(max(ang.values()) - min(ang.values()), 1) == 1.2
    two = paper.at(data.rows(paper.KW), 2.0e-3)
    moved = [ang[k] - two[k]["angle_deg"] for k in ang]
    assert (round(min(moved), 1), round(max(moved), 1)) == (2.3, 3.8)
    speed = [r["speed_m_s"] / 1e3 for r in main]
    assert (round(min(speed), 1), round(max(speed), 1)) == (1.6, 1.9)
    assert max(r["symmetry_tip_mm"] for r in rows) < 1e-9
    far = {dx: [r["far_edge_crack_us"] for r in rows if round(r["dx_m"] * 1e3, 2) == dx] for dx in (2.0, 1.0, 0.5)}
    assert (round(min(far[2.0])), round(max(far[2.0]))) == (26, 27)
    assert (round(min(far[1.0])), round(max(far[1.0]))) == (41, 45)
    assert far[0.5] == [None]
