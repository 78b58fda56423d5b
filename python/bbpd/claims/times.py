# SPDX-License-Identifier: GPL-2.0-or-later
"""The step times that tools/reproduce and tools/test print ('== STEP ready (N s)'), read from
their output into doc/results/quickstart_times.csv."""
import re

from bbpd.csvfile import read_csv, write_csv

STEP = re.compile(r"^== (?P<step>.+?) (?:ready|passed|FAILED) \((?P<s>\d+) s\)$"
                  r"|^== (?P<total>.+?) done in (?P<t>\d+) s$", re.M)


def steps(output):
    """[(step, seconds)] of one command's output, its total last."""
    out = []
    for m in STEP.finditer(output):
        if m.group("step"):    # without the machine's cache path
            out.append((re.sub(r" \(in /[^)]*\)", "", m.group("step")), int(m.group("s"))))
        else:
            out.append(("total (" + m.group("total") + ")", int(m.group("t"))))
    return out


def add(path, command, output, notes=()):
    """Replace command's rows of the CSV at path by the steps of its output; notes (the CPU,
    the conditions) become the file's comment lines when given."""
    comments, rows = read_csv(path) if path.is_file() else ([], [])
    rows = [r for r in rows if r["command"] != command]
    rows += [{"command": command, "step": s, "wall_s": t} for s, t in steps(output)]
    path.parent.mkdir(parents=True, exist_ok=True)
    write_csv(path, rows, list(notes) or comments)
    return rows
