# SPDX-License-Identifier: GPL-2.0-or-later
"""Result CSV files: '#' comment lines saying what made them (command, date, builds, machine),
then a header and one row per run. The report writes them and the READMEs are generated from
them (bbpd.claims)."""
import csv
import math
from pathlib import Path

import numpy as np

from bbpd.markdown import table


def _num(v, digits=6):
    """A cell: numbers to `digits` significant digits, None and NaN as empty."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ""
    if isinstance(v, (bool, str)):
        return str(v)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return f"{float(v):.{digits}g}"


def write_csv(path, rows, comments=(), columns=None):
    """rows (dicts) in columns (default: the first row's keys), the comments first"""
    columns = list(columns or rows[0])
    with open(path, "w", newline="") as fh:
        for line in comments:
            fh.write(f"# {line}\n")
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(columns)
        for r in rows:
            w.writerow([_num(r.get(c)) for c in columns])


def read_csv(path):
    """(comment lines, [row dict of floats / strings / None])"""
    comments, body = [], []
    for line in Path(path).read_text().splitlines():
        (comments if line.startswith("#") else body).append(line.lstrip("# ") if
                                                            line.startswith("#") else line)
    rows = []
    for r in csv.DictReader(body):
        rows.append({k: _value(v) for k, v in r.items()})
    return comments, rows


def _value(text):
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        return text


# --------------------------------------------------------------------------- benchmark tables
# The benchmarks' own tables (strip, strip_closure, branching): fixed columns, '#' lines first,
# text cells as they are, True/False for flags, numbers to 6 significant digits.

def write_table(path, rows, columns, comments=(), text=()):
    """rows (dicts) in the given columns; a cell of a `text` column, or a str or bool, is kept"""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        for line in comments:
            f.write(f"# {line}\n")
        w = csv.writer(f)
        w.writerow(columns)
        for r in rows:
            w.writerow([r[c] if c in text or isinstance(r[c], (str, bool)) else f"{r[c]:.6g}"
                        for c in columns])


def read_table(path, text=(), flags=()):
    """The rows of write_table as dicts: `text` columns strings, `flags` columns bools, the
    rest floats"""
    lines = [ln for ln in Path(path).read_text().splitlines() if ln and not ln.startswith("#")]
    table = list(csv.reader(lines))    # a text cell may hold a comma (quoted by write_table)
    names = table[0]

    def cell(n, v):
        return v if n in text else (v == "True") if n in flags else float(v)
    return [{n: cell(n, v) for n, v in zip(names, cells)} for cells in table[1:]]


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


def continue_csv(path, command):
    """(earlier provenance lines, rows so far, this command's line) for a run that adds to the
    results CSV at path (None: it starts one): an added run keeps the rows and the commands
    that made them, and names itself 'rows added by'."""
    if path is None or not Path(path).is_file():
        return [], [], f"made by: {command}"
    return provenance(path), read_csv(path)[1], f"rows added by: {command}"


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
