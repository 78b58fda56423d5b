# SPDX-License-Identifier: GPL-2.0-or-later
"""Readers of what LAMMPS and the plugin write: logs (versions, loop time, thermo tables),
text dumps, the examples' fix print files (k.dat, tips.dat) and CSV tables of the tools."""
import re

import numpy as np

# --------------------------------------------------------------------------- logs

def build_versions(log_text):
    """LAMMPS version and plugin version a log.lammps reports (None where it does not)."""
    lmp = re.search(r"^LAMMPS \((.*)\)", log_text, re.M)
    plug = re.search(r"^Loading plugin: BBPD .* v(\S+) by", log_text, re.M)
    return {"lammps_version": lmp[1] if lmp else None,
            "plugin_version": plug[1] if plug else None}


def loop_time(output):
    """(seconds, ranks) of the first 'Loop time of ... on N procs' line; (None, None) if none."""
    loop = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", output)
    return (float(loop[1]), int(loop[2])) if loop else (None, None)


def pair_setup(output):
    """What the pair style's setup report prints (None where the log lacks it): the critical
    stretch s0, the velocity-Verlet limit of the time step (s) and the time step's fraction
    of it."""
    s0 = re.search(r"critical_stretch s0 = (\S+)", output)
    bound = re.search(r"velocity-Verlet limit (\S+);", output)
    fraction = re.search(r"timestep = \S+ \(([0-9.eE+-]+) of the limit\)", output)
    return {"critical_stretch": float(s0[1]) if s0 else None,
            "dt_bound": float(bound[1]) if bound else None,
            "dt_fraction": float(fraction[1]) if fraction else None}


def thermo_tables(output):
    """Every thermo table of a LAMMPS log: list (one per run) of {column: array}."""
    tables, cols, rows = [], None, []
    for line in output.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            cols, rows = words, []
        elif cols and line.startswith("Loop time"):
            data = np.array(rows, dtype=float).reshape(-1, len(cols))
            tables.append({c: data[:, k] for k, c in enumerate(cols)})
            cols = None
        elif cols and len(words) == len(cols):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                pass    # a warning printed inside the table
    return tables


# --------------------------------------------------------------------------- dumps

def dump_snapshots(path):
    """Snapshots of a LAMMPS text dump: list of (step, {column: array})."""
    snaps = []
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if not lines[i].startswith("ITEM: TIMESTEP"):
            i += 1
            continue
        step = int(lines[i + 1])
        n = int(lines[i + 3])
        cols = lines[i + 8].split()[2:]
        body = " ".join(lines[i + 9:i + 9 + n])
        data = np.fromstring(body, sep=" ").reshape(n, len(cols)) if n else np.zeros((0, len(cols)))
        snaps.append((step, {c: data[:, k] for k, c in enumerate(cols)}))
        i += 9 + n
    return snaps


def read_dump(path):
    """Last snapshot of a text dump as {column: array}, rows sorted by id."""
    cols = dump_snapshots(path)[-1][1]
    order = np.argsort(cols["id"])
    return {c: v[order] for c, v in cols.items()}


# --------------------------------------------------------------------------- fix print files

def k_history(path, dt):
    """k.dat of in.mode1 / in.mode2 (step and three K columns, compute bbpd/dsif) ->
    t, and the three K columns; the examples' READMEs name the columns."""
    d = np.loadtxt(path, comments="#", ndmin=2)
    return d[:, 0] * dt, d[:, 1], d[:, 2], d[:, 3]


def j_history(path):
    """J columns of k.dat (compute bbpd/jintegral): J, K_I, K_II; None if the run had none."""
    d = np.loadtxt(path, comments="#", ndmin=2)
    return None if d.shape[1] < 7 else (d[:, 4], d[:, 5], d[:, 6])


def tips(path):
    """tips.dat of in.kalthoff_winkler: step, damage sums near the lower tip, the upper tip and
    over the plate, and the largest damage in the outer quarter of each tip disk ahead of the
    tip (lower, upper)."""
    d = np.loadtxt(path, comments="#")
    return d[:, 0].astype(int), d[:, 1], d[:, 2], d[:, 3], d[:, 4], d[:, 5]
