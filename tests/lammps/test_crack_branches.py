# SPDX-License-Identifier: GPL-2.0-or-later
"""compute bbpd/crack/tip with branches yes on a branching crack, against the tips found in
Python (bbpd.crack_branches, SciPy's Dijkstra and a union-find of its own).

The scene: examples/crack-branching/in.crack_branching on its coarsest grid (dx = 1 mm, m = 3,
4000 atoms, sigma = 2 MPa, 43 us, about half a second): the crack leaves the notch tip at
(0, 0), runs along y = 0 and splits into two mirror branches at x = 21.5 mm. The tips are
written every 3 steps (tips.dat) with the damage of every damaged atom (damage.dump). At every
output the compute must give the tips of the Python search: their number, positions and path
lengths (to round-off), and their split points; the vector's count of tips must equal the
array's rows; a split must be recorded at the first output with two tips, and the two
branches must be mirror images about y = 0 on this symmetric grid. The vector and the array
must have the same bits on 1, 2 and 4 ranks and with the atom IDs permuted.
"""
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from bbpd.crack_branches import branch_tips
from bbpd.jobs import ROOT
from bbpd.runner import run_lammps

EXAMPLE = ROOT / "examples" / "crack-branching" / "in.crack_branching"
DX, M = 1.0e-3, 3.0
LINK = M * DX                  # the compute's default link: the horizon
VARS = {"dx": DX, "m": M, "tipdt": 2.5e-7, "dumpdt": 2.5e-7}
PATH_RTOL = 1.0e-12            # the same sums in another order
COLUMNS = ("x", "y", "extension", "speed", "direction", "split_x", "split_y", "split_time",
           "split_length")


def script():
    """The example with every output at full precision (same bits are compared as text)."""
    return EXAMPLE.read_text().replace("%.10g", "%.17g").replace("%.6g", "%.17g")


def read_tips(path):
    """tips.dat (fix ave/time mode vector) -> {step: array of the rows}"""
    out, lines = {}, [l for l in Path(path).read_text().splitlines() if l and l[0] != "#"]
    k = 0
    while k < len(lines):
        step, nrows = (int(v) for v in lines[k].split())
        out[step] = np.array([[float(v) for v in l.split()[1:]] for l in lines[k + 1:k + 1 + nrows]])
        k += 1 + nrows
    return out


def read_vector(path):
    rows = [l.split() for l in Path(path).read_text().splitlines() if l and l[0] != "#"]
    return {int(r[0]): [float(v) for v in r[1:]] for r in rows}


def read_damage(path):
    """damage.dump (id c_damage) -> {step: {id: damage}}"""
    frames = {}
    for block in Path(path).read_text().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        n = int(lines[2])
        frames[int(lines[0])] = {int(l.split()[0]): float(l.split()[1]) for l in lines[8:8 + n]}
    return frames


def read_reference(path):
    lines = Path(path).read_text().splitlines()
    n = int(lines[3])
    data = np.array([[float(v) for v in l.split()] for l in lines[9:9 + n]])
    return data[np.argsort(data[:, 0])]


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    work = tmp_path_factory.mktemp("crack_branches")
    out = run_lammps(script(), workdir=work, vars=VARS).output
    dt = float(out.split("CRACK-BRANCHING:")[-1].split(" dt ")[1].split()[0])
    return work, dt


def test_tips_agree_with_the_tips_found_in_python(serial):
    work, dt = serial
    tips, vector = read_tips(work / "tips.dat"), read_vector(work / "tip.dat")
    refpos = read_reference(work / "ref.dump")
    ids, x0 = refpos[:, 0].astype(int), refpos[:, 1:3]
    index = {i: k for k, i in enumerate(ids)}
    most = 0
    for step, frame in read_damage(work / "damage.dump").items():
        damage = np.zeros(len(ids))
        for i, phi in frame.items():
            damage[index[i]] = phi
        expected = branch_tips(x0[:, 0], x0[:, 1], damage, (0.0, 0.0), LINK)
        rows, vec = tips[step], vector[step]
        assert vec[6] == len(expected), f"step {step}"
        most = max(most, len(expected))
        for row, want in zip(rows, expected):
            got = dict(zip(COLUMNS, row))
            assert (got["x"], got["y"]) == (want["x"], want["y"]), f"step {step}"
            assert got["extension"] == pytest.approx(want["extension"], rel=PATH_RTOL)
            if want["split_length"] > 0.0:    # the split of the tip's branch (when it left)
                assert got["split_length"] == pytest.approx(want["split_length"], abs=DX)
        # the first row is the vector's tip; rows past the tips are zero
        if expected:
            assert list(rows[0, :3]) == vec[:3], f"step {step}"
        assert not rows[len(expected):].any(), f"step {step}"
    # the scene is a test only if the crack branched
    assert most == 2, most


def test_the_split_is_recorded_once_and_the_branches_are_mirror_images(serial):
    work, dt = serial
    tips, vector = read_tips(work / "tips.dat"), read_vector(work / "tip.dat")
    steps = sorted(vector)
    first = next(s for s in steps if vector[s][6] == 2)
    assert vector[steps[-1]][7] == 1.0    # one split
    rows = tips[steps[-1]]
    assert rows[1, 7] == pytest.approx(first * dt, rel=1e-12)    # split time: first seen
    assert rows[0, 7] == -1.0                                      # the branch that continued
    assert abs(rows[1, 6]) <= LINK and 0.0 < rows[1, 5] < rows[1, 0]    # near the crack line
    for s in steps:
        if vector[s][6] == 2:
            a, b = tips[s][0], tips[s][1]
            assert (a[0], a[2]) == pytest.approx((b[0], b[2]), rel=1e-12), f"step {s}"
            assert a[1] == pytest.approx(-b[1], rel=1e-12) and a[1] < 0.0, f"step {s}"
            assert a[4] == pytest.approx(-b[4], abs=1e-9), f"step {s}"


@pytest.mark.parametrize("nprocs", [2, 4])
def test_same_bits_on_any_number_of_ranks(serial, tmp_path, nprocs):
    work, _ = serial
    run_lammps(script(), workdir=tmp_path, nprocs=nprocs, vars=VARS)
    for name in ("tip.dat", "tips.dat"):
        assert (tmp_path / name).read_text() == (work / name).read_text(), name


def test_same_bits_whatever_the_atom_numbering(serial, tmp_path):
    work, _ = serial
    x0 = read_reference(work / "ref.dump")[:, 1:3]
    order = np.random.default_rng(35).permutation(len(x0))
    positions = np.column_stack([x0[order], np.zeros(len(x0))])
    refmodel.write_data(tmp_path / "plate.data", positions, DX**3, 2440.0,
                   [(-0.05, 0.05), (-0.02, 0.02), (-0.5, 0.5)], types=np.full(len(x0), 2))
    text = script()
    start = text.index("lattice ")
    end = text.index("create_atoms    1 region plate\n") + len("create_atoms    1 region plate\n")
    run_lammps(text[:start] + "read_data plate.data\nset group all type 1\n" + text[end:],
               workdir=tmp_path, vars=VARS)
    for name in ("tip.dat", "tips.dat"):
        assert (tmp_path / name).read_text() == (work / name).read_text(), name
