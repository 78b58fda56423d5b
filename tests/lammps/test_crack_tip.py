# SPDX-License-Identifier: GPL-2.0-or-later
"""compute bbpd/crack/tip on a growing Mode-I crack, against the crack found in Python.

The scene: a glass plate 60 x 30 mm (1 mm grid, 1800 atoms, Gaussian kernel, horizon 3.015 mm)
with an edge notch along y = 0 to x = 20 mm, pulled apart at a uniform strain rate (the top
and bottom rows held at +-rate*y). The crack starts near step 100 and runs straight along the
notch line to x = 43.5 mm (7.5 horizons) by step 200, before it branches.

The damage and the positions of every atom are dumped every 20 steps (the step-0 positions are
the reference positions x0). From them the crack graph is built again in Python with SciPy
(a k-d tree for the edges, scipy.sparse.csgraph.dijkstra for the path lengths) and, as a
second, cruder reading, the farthest atom of the connected damaged set from the notch tip (a
breadth-first search on the same set, Euclidean distance). The compute must agree with the
first to round-off (tip, extension, atom count, direction) and with the second within one
grid spacing; its vector must have the same bits on 1, 2 and 4 ranks and with the atom IDs
permuted (a tie rule by ID fails there: the tip moves to the other face row at steps 120 and
170); the extension must never decrease on this straight crack.
"""
import math
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import breadth_first_order, dijkstra
from scipy.spatial import cKDTree

import refmodel
from bbpd.runner import run_lammps

DX = 1.0e-3
HORIZON = 3.015 * DX
NOTCH = 20.0 * DX          # notch tip x; the notch runs along y = 0 from the left edge
THRESHOLD = 0.3            # the compute's default
WINDOW = 1.5e-6            # speed window: the invocations every 10 steps, 20 steps back
DT = 1.0e-7
NSTEPS = 200
EVERY = 10                 # output of the compute's vector
DUMP_EVERY = 20
YOUNGS, DENSITY = 72.0e9, 2440.0    # soda-lime glass
RAYLEIGH = 0.9325 * math.sqrt(YOUNGS / (2.0 * (1.0 + 1.0 / 3.0)) / DENSITY)    # nu = 1/3
PATH_RTOL = 1.0e-12        # the same sums in another order
TIE = 1.0e-9               # the compute's tie width, in units of the link
ANGLE_ATOL = 1.0e-9        # degrees
COLUMNS = ["c_tip[1]", "c_tip[2]", "c_tip[3]", "c_tip[4]", "c_tip[5]", "c_tip[6]",
           "c_back[1]", "c_back[2]", "c_back[3]", "c_back[6]"]


def scene(nsteps=NSTEPS, dump=True, extra=""):
    lines = f"""plugin load bbpdplugin.so
units si
dimension 2
boundary s s p
atom_style peri
atom_modify map array
lattice sq {DX!r} origin 0.5 0.5 0.0
region plate block 0 0.06 -0.015 0.015 -0.5 0.5 units box
create_box 1 plate
create_atoms 1 region plate
set group all density {DENSITY!r}
set group all volume {DX**3!r}
pair_style bbpd/gaussian plane/stress thickness {DX!r}
pair_coeff * * {YOUNGS!r} 3.8 {HORIZON!r}
neighbor {DX!r} bin
fix notch all bbpd/notch segment {-DX!r} 0.0 {NOTCH + 1e-3 * DX!r} 0.0
region top block INF INF 0.014 INF INF INF units box
region bot block INF INF INF -0.014 INF INF units box
group top region top
group bot region bot
variable vy atom 8.0*y
velocity all set 0.0 v_vy 0.0 units box
fix hold top setforce 0.0 0.0 0.0
fix hold2 bot setforce 0.0 0.0 0.0
fix integrate all nve
fix 2d all enforce2d
compute phi all bbpd/damage/atom
compute tip all bbpd/crack/tip {NOTCH!r} 0.0 window {WINDOW!r}
compute back all bbpd/crack/tip {NOTCH!r} 0.0 direction -1 0
fix out all ave/time {EVERY} 1 {EVERY} {' '.join(COLUMNS)} file tip.dat format " %.17g"
{extra}
timestep {DT!r}
thermo 50
"""
    if dump:
        lines += f"dump d all custom {DUMP_EVERY} dump.crack id x y c_phi\n"
        lines += "dump_modify d format float %.17g\n"
    return lines + f"run {nsteps}\n"


def read_table(path):
    rows = [l.split() for l in path.read_text().splitlines() if l and not l.startswith("#")]
    return {int(r[0]): r[1:] for r in rows}    # step -> the values as printed


def read_dump(path):
    frames = {}
    for block in path.read_text().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        n = int(lines[2])
        data = np.array([[float(v) for v in l.split()] for l in lines[8:8 + n]])
        frames[int(lines[0])] = data[np.argsort(data[:, 0])]
    return frames


def python_tip(x0, damage, start, direction, link=HORIZON, threshold=THRESHOLD, span=None):
    """The crack graph of the doc page, built with SciPy: (tip x, y, extension, node count,
    direction in degrees)."""
    span = 2.0 * link if span is None else span
    none = (start[0], start[1], 0.0, 0, math.degrees(math.atan2(direction[1], direction[0])))
    ahead = (x0 - start) @ np.asarray(direction) >= 0.0
    nodes = np.flatnonzero((damage >= threshold) & ahead)
    p = x0[nodes]
    n = len(p)
    if n == 0:
        return none
    pairs = cKDTree(p).query_pairs(link, output_type="ndarray")
    seed = np.flatnonzero(np.hypot(*(p - start).T) <= link)
    # node n is S itself
    i = np.concatenate([pairs[:, 0], pairs[:, 1], np.full(len(seed), n)])
    j = np.concatenate([pairs[:, 1], pairs[:, 0], seed])
    w = np.hypot(*(np.vstack([p, start])[i] - np.vstack([p, start])[j]).T)
    graph = coo_matrix((w, (i, j)), shape=(n + 1, n + 1)).tocsr()
    length, pred = dijkstra(graph, indices=n, return_predecessors=True)
    length = length[:n]
    reached = np.isfinite(length)
    if not reached.any():
        return none
    tied = np.flatnonzero(reached & (length >= length[reached].max() - TIE * link))
    tip = min(tied, key=lambda k: (p[k, 1], p[k, 0]))    # smallest y, then x
    back = tip    # the first node on the path at least span behind the tip, or S
    while back != n and length[tip] - length[back] < span:
        back = pred[back]
    chord = p[tip] - np.vstack([p, start])[back]
    return (p[tip, 0], p[tip, 1], length[tip], int(reached.sum()),
            math.degrees(math.atan2(chord[1], chord[0])))


def farthest_connected(x0, damage, start, direction, link=HORIZON, threshold=THRESHOLD):
    """Cruder reading: breadth-first search of the damaged set, the atom farthest from S in a
    straight line (mirror ties: the compute's rule, smallest y, then x)."""
    ahead = (x0 - start) @ np.asarray(direction) >= 0.0
    p = x0[(damage >= threshold) & ahead]
    p = np.vstack([start, p])
    pairs = cKDTree(p).query_pairs(link, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(p),) * 2)
    order = breadth_first_order(graph, 0, directed=False, return_predecessors=False)
    dist = np.hypot(*(p[order] - start).T)
    tied = order[dist >= dist.max() - TIE * link]
    return min(p[tied], key=lambda q: (q[1], q[0]))    # the tie rule of the compute


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    work = tmp_path_factory.mktemp("crack_tip")
    run_lammps(scene(), workdir=work)
    return read_table(work / "tip.dat"), read_dump(work / "dump.crack")


def test_tip_agrees_with_the_crack_found_in_python(serial):
    table, frames = serial
    x0 = frames[0][:, 1:3]
    start = np.array([NOTCH, 0.0])
    grown = 0
    for step, frame in frames.items():
        damage = frame[:, 3]
        row = [float(v) for v in table[step]]
        for cols, direction in ((0, (1.0, 0.0)), (6, (-1.0, 0.0))):
            tx, ty, ext, count, angle = python_tip(x0, damage, start, direction)
            got_ext = row[cols + 2]
            got_count = row[cols + 5 if cols == 0 else cols + 3]
            assert (row[cols], row[cols + 1]) == (tx, ty), f"step {step} {direction}"
            assert got_ext == pytest.approx(ext, rel=PATH_RTOL, abs=1e-15), f"step {step}"
            assert got_count == count, f"step {step} {direction}"
            if cols == 0:
                # (two equally long paths summed in another order could pick another chord;
                # measured: the same to 1e-14 degrees at every dump of this scene)
                assert row[4] == pytest.approx(angle, abs=ANGLE_ATOL), f"step {step}"
            far = farthest_connected(x0, damage, start, direction)
            assert math.hypot(row[cols] - far[0], row[cols + 1] - far[1]) <= DX + 1e-12, \
                f"step {step} {direction}: tip {row[cols:cols + 2]} vs farthest {far}"
        grown = max(grown, row[2])
    # the scene is a test only if the crack grew, several horizons
    assert grown > 5.0 * HORIZON, grown
    # the backward instance follows the notch to the left edge
    assert float(table[0][6]) == 0.5 * DX


def test_extension_never_decreases_on_a_straight_mode1_crack(serial):
    table, _ = serial
    steps = sorted(table)
    t = np.array(steps) * DT
    ext = np.array([float(table[s][2]) for s in steps])
    y = np.array([float(table[s][1]) for s in steps])
    assert np.all(np.diff(ext) >= 0.0), ext
    assert np.all(np.abs(y) <= 1.5 * DX), y    # the crack stays on the notch line
    # the speed is the difference quotient over the window (the newest record at least WINDOW
    # old: two outputs back), and the crack runs below the Rayleigh speed on average
    speed = np.array([float(table[s][3]) for s in steps])
    back = [max(0, k - 2) if k > 0 else 0 for k in range(len(steps))]
    expected = [(ext[k] - ext[b]) / (t[k] - t[b]) if k > 0 else 0.0 for k, b in enumerate(back)]
    np.testing.assert_allclose(speed, expected, rtol=1e-12, atol=1e-9)
    moving = np.flatnonzero(ext > 0)
    mean_speed = (ext[-1] - ext[moving[0]]) / (t[-1] - t[moving[0]])
    assert 0.0 < mean_speed < RAYLEIGH, (mean_speed, RAYLEIGH)


@pytest.mark.parametrize("nprocs", [2, 4])
def test_same_bits_on_any_number_of_ranks(serial, tmp_path, nprocs):
    table, _ = serial
    run_lammps(scene(dump=False), workdir=tmp_path, nprocs=nprocs)
    assert read_table(tmp_path / "tip.dat") == table


def test_same_bits_whatever_the_atom_numbering(serial, tmp_path):
    """The plate read from a data file whose atom IDs are a random permutation of create_atoms'
    (ties between the two face rows would go elsewhere if the rule used IDs)."""
    table, frames = serial
    x0 = frames[0][:, 1:3]
    order = np.random.default_rng(2026).permutation(len(x0))
    positions = np.column_stack([x0[order], np.zeros(len(x0))])
    refmodel.write_data(tmp_path / "plate.data", positions, DX**3, DENSITY,
                   [(0.0, 0.06), (-0.015, 0.015), (-0.5, 0.5)])
    script = scene(dump=False)
    start, end = script.index("lattice "), script.index("set group all density")
    run_lammps(script[:start] + "read_data plate.data\n" + script[end:], workdir=tmp_path)
    assert read_table(tmp_path / "tip.dat") == table


def test_moving_tip_for_dsif_and_jintegral(tmp_path):
    """c_tip[1], c_tip[2] through equal-style variables as the tip of bbpd/dsif and
    bbpd/jintegral: the variables follow the compute, the moving computes equal the fixed
    ones while the tip stays at S, and give finite values once it moves."""
    moving = f"""variable tx equal c_tip[1]
variable ty equal c_tip[2]
compute km all bbpd/dsif tip v_tx 0.0 tolerance {0.8 * DX!r}
compute kf all bbpd/dsif tip {NOTCH!r} 0.0 tolerance {0.8 * DX!r}
compute jm all bbpd/jintegral tip v_tx v_ty rin {HORIZON!r} rout {3 * HORIZON!r}
compute jf all bbpd/jintegral tip {NOTCH!r} 0.0 rin {HORIZON!r} rout {3 * HORIZON!r}
fix k all ave/time {EVERY} 1 {EVERY} c_tip[1] c_tip[2] v_tx v_ty c_km[1] c_kf[1] c_jm[1] c_jf[1] &
    file k.dat format " %.17g"
"""
    run_lammps(scene(dump=False, extra=moving), workdir=tmp_path)
    rows = read_table(tmp_path / "k.dat")
    moved = 0
    for step, row in rows.items():
        tx, ty, vx, vy, km, kf, jm, jf = (float(v) for v in row)
        assert (vx, vy) == (tx, ty), step
        assert all(math.isfinite(v) for v in (km, jm)), step
        if (tx, ty) == (NOTCH, 0.0):
            assert (km, jm) == (kf, jf), step
        else:
            moved += 1
            assert km != kf and jm != jf, step
    assert moved >= 5, moved



def doc_damage_table():
    """(m, first row, second row, first atom ahead) of the table in the doc page"""
    text = (Path(__file__).resolve().parents[2] / "doc" / "compute_bbpd_crack_tip.rst").read_text()
    table = text[text.index("first atom ahead of the notch tip"):text.index("The first row has lost")]
    values = [float(v) for v in re.findall(r"^\s+[*-]?\s*-\s+([0-9.]+)$", table, re.M)]
    return [tuple(values[k:k + 4]) for k in range(0, len(values), 4)]


def test_default_threshold_separates_crack_faces_from_the_atoms_ahead(tmp_path):
    """The doc's table behind T = 0.3, measured: the damage beside a notch after run 0 (first
    and second row, away from the notch's ends, and the first atom ahead of its tip), for each
    horizon of the table; the first row lies above T, the atoms ahead below it."""
    rows = doc_damage_table()
    assert [r[0] for r in rows] == [2.015, 3.015, 5.015]
    script = "plugin load bbpdplugin.so\n"
    for n, (m, *_) in enumerate(rows):
        body = scene(nsteps=0, dump=False).split("\n", 1)[1]
        body = body.replace(f"{HORIZON!r}", f"{m * DX!r}").replace("file tip.dat", f"file t{n}.dat")
        script += "clear\n" + body.replace("run 0\n", f"dump d all custom 1 d{n}.dump id x y c_phi\n"
                                            "dump_modify d format float %.17g\nrun 0\n")
    run_lammps(script, workdir=tmp_path)
    for n, (m, first, second, ahead_doc) in enumerate(rows):
        frame = read_dump(tmp_path / f"d{n}.dump")[0]
        x, y, damage = frame[:, 1], frame[:, 2], frame[:, 3]
        away = (x > 6 * DX) & (x < NOTCH - 6 * DX)
        for dist, expected in ((0.5, first), (1.5, second)):
            row = away & (np.abs(np.abs(y) - dist * DX) < 1e-9)
            np.testing.assert_allclose(damage[row], expected, atol=5e-4, err_msg=f"m = {m}")
        ahead = (np.abs(np.abs(y) - 0.5 * DX) < 1e-9) & (np.abs(x - NOTCH - 0.5 * DX) < 1e-9)
        np.testing.assert_allclose(damage[ahead], ahead_doc, atol=5e-4, err_msg=f"m = {m}")
        assert damage[away & (np.abs(y) < DX)].min() >= THRESHOLD > damage[ahead].max()
        # no crack yet: the tip is S
        assert float(read_table(tmp_path / f"t{n}.dat")[0][2]) == 0.0
