# SPDX-License-Identifier: GPL-2.0-or-later
"""The numbers of the READMEs and docs agree with the result files they are generated from
(python -m bbpd.claims; no LAMMPS run): every generated block as rendered from the committed
reference CSVs, every speed ratio with its CPU; and the check reports a README edited back to
the old wording, and data that changed under an unchanged text."""
import shutil
from pathlib import Path

import pytest

from bbpd import claims
from bbpd import markers
from bbpd.claims.blocks import BLOCKS, JDOC, KW, MODE1, MODE2, README
from bbpd.claims.data import OTHERS, REFERENCES, STEP_TIMES, Data, import_report
from bbpd.csvfile import read_csv, write_csv

ROOT = Path(__file__).resolve().parents[1]

# the wording the READMEs had before their numbers were generated (the mismatches found by
# reading them against their own tables)
OLD = {
    MODE2: ("mode2-findings",
            "- BBPD with the paper's extraction (tip on the first intact column, r1 = dx, "
            "r2 = 2 dx) **overestimates K_II by 20-30 %** for all\n  three kernels, and the "
            "excess does not shrink with dx."),
    JDOC: ("jintegral-benchmarks",
           "On the benchmarks: Mode-I :math:`K_I(t)` within about 0.3 % of Freund's solution, "
           "and Mode-II\n:math:`K_{II}(t)` close to the reference where the displacement "
           "extrapolation is 15-30 % high."),
    KW: ("kw-angle",
         "- **Angle.** The Gaussian gives 58.8 / 61.1 / 62.3° at 2 / 1 / 0.5 mm. But the spread "
         "between kernels\n  (1.1° at 1 mm) is smaller than the change from 2 to 1 mm "
         "(2.3–3.2°)."),
    MODE1: ("mode1-wrong-micromodulus",
            "With `mode1.run` patched to `efactor=1.1`, `test_gaussian_dx005_matches_freund` "
            "fails (tolerances 3.0 / 3.2 %)."),
}


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


@pytest.mark.parametrize("rel", sorted(OLD))
def test_old_wording_is_reported(rel):
    """The negative control: each README/doc edited back to its old wording fails the check."""
    name, old = OLD[rel]
    assert not [p for p in claims.check_text(rel, text_of(rel)) if name in p]
    problems = claims.check_text(rel, with_block(rel, name, old))
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
    start = text.index("<!-- bbpd:text mode2-symmetry -->")
    end = text.index("<!-- /bbpd:text -->", start) + len("<!-- /bbpd:text -->")
    problems = claims.check_text(MODE2, text[:start] + text[end:])
    assert any("block mode2-symmetry is missing" in p for p in problems), problems


def test_changed_data_is_reported(tmp_path):
    """Unchanged text over changed data fails too: the Mode-II CSV with one ratio moved."""
    comments, rows = read_csv(REFERENCES["mode2"])
    rows[0]["ratio_end"] += 0.05
    changed = tmp_path / "mode2.csv"
    write_csv(changed, rows, comments)
    data = Data({**REFERENCES, "mode2": changed})
    problems = claims.check_text(MODE2, text_of(MODE2), data)
    assert any("block mode2-findings disagrees" in p for p in problems), problems
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
