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
