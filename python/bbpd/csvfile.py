# SPDX-License-Identifier: GPL-2.0-or-later
"""Result CSV files: '#' comment lines saying what made them (command, date, builds, machine),
then a header and one row per run. The report writes them and the READMEs are generated from
them (bbpd.claims)."""
import csv
import math
from pathlib import Path

import numpy as np

from bbpd.markdown import table


def _num(v, nan="", digits=6):
    """A cell: numbers to `digits` significant digits, None as empty, NaN as `nan`."""
    if v is None:
        return ""
    if isinstance(v, float) and math.isnan(v):
        return nan
    if isinstance(v, (bool, str)):
        return str(v)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return f"{float(v):.{digits}g}"


def write_csv(path, rows, comments=(), columns=None, text=(), nan="", digits=6):
    """rows (dicts) in columns (default: the first row's keys), the comments first; a cell of
    a `text` column is written as it is, a number to `digits` significant digits"""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    columns = list(columns or rows[0])
    with open(path, "w", newline="") as fh:
        for line in comments:
            fh.write(f"# {line}\n")
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(columns)
        for r in rows:
            w.writerow([r.get(c) if c in text else _num(r.get(c), nan, digits) for c in columns])


def read_csv(path, text=(), flags=()):
    """(comment lines, [row dict]): a cell of a `text` column a string, of a `flags` column a
    bool, any other a float, a string where it is none, or None where it is empty"""
    comments, body = [], []
    for line in Path(path).read_text().splitlines():
        (comments if line.startswith("#") else body).append(line.lstrip("# ") if
                                                            line.startswith("#") else line)

    def cell(name, v):
        return v if name in text else (v == "True") if name in flags else _value(v)
    return comments, [{k: cell(k, v) for k, v in r.items()} for r in csv.DictReader(body)]


def columns(path):
    """{column: array of floats} of a numeric CSV"""
    rows = read_csv(path)[1]
    return {c: np.array([r[c] for r in rows], dtype=float) for c in rows[0]}


def _value(text):
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        return text


def comment(source, key):
    """The text after 'key:' on the first such comment line of source (a CSV's path, or the
    comment lines of read_csv), or None."""
    lines = read_csv(source)[0] if isinstance(source, (str, Path)) else source
    return next((c.split(":", 1)[1].strip() for c in lines if c.startswith(key + ":")), None)


def provenance(path):
    """The 'made by' and 'rows added by' comment lines of a results CSV, in order: every
    command that wrote rows to it."""
    return [ln[2:] for ln in Path(path).read_text().splitlines()
            if ln.startswith(("# made by: ", "# rows added by: "))]


def continue_csv(path, command, read=lambda path: read_csv(path)[1]):
    """(earlier provenance lines, rows so far (read(path)), this command's line) for a run that
    adds to the results CSV at path (None: it starts one): an added run keeps the rows and the
    commands that made them, and names itself 'rows added by'."""
    if path is None or not Path(path).is_file():
        return [], [], f"made by: {command}"
    return provenance(path), read(path), f"rows added by: {command}"


def loop_times_note(rows, key, case):
    """Which machine (row[key]: CPU, ranks) timed which runs, as a table under a benchmark's
    table: the most common one for every other run, each other one with the runs case(row)
    names (appended runs may come from another machine)."""
    by = {}
    for r in rows:
        by.setdefault(r[key], []).append(r)
    main = max(by, key=lambda t: len(by[t]))
    others = [[t, ", ".join(case(r) for r in rs)] for t, rs in by.items() if t != main]
    return table(["loop times measured on", "runs"],
                 [[main, "every other run" if others else "all"]] + others)
