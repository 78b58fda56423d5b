"""Load balancing moves atoms between ranks and keeps the same bits as one rank.

The Kalthoff-Winkler plate of test_mpi_restart.py (60 x 30 atoms, notch, impact) in a box of
125 x 31.25 mm, empty right of x = 60 mm, so that the even split LAMMPS starts from is out of
balance: `balance 1.0 shift x 10 1.1` moves the cut planes before the run, then `fix balance`
repartitions during it, by shifting the planes again (comm_style brick) or by recursive
coordinate bisection (comm_style tiled), handing atoms to other ranks at the first setup and
every 50 steps (with 'weight time', by the ranks' measured loads: cuts that move during the
run and differ from run to run). The final %.17g dump (sorted by id) and the broken-bond
count on 2 and 4 ranks must equal those of the 1-rank run without any balancing.

Why the box lengths are powers of two: LAMMPS's shift balancing (Balance::shift) converts
every position to box fractions and back, which rounds it to a neighbouring double unless
multiplying by the box length is exact; the control test shows the last bits move in a 100 mm
box, for any pair style. bisection (rcb) keeps the positions.
"""
import re

import pytest

from test_mpi_restart import (DT, DYNAMICS, FINISH, GRIDS, SETUP_2D, THICKNESS, broken_counts,
                              check_identical, final_state, write_data)
from bbpd.runner import run_lammps

DX = 1.0e-3
NX, NY = 60, 30
BOX_X = 0.125           # m, 2^-3: the even split of 2 ranks puts every atom on rank 0
BOX_Y = 0.03125         # m, 2^-5
ROUNDING_BOX_X = 0.1    # m: a box in which shift balancing rounds the positions
STEPS = 200
BALANCE_EVERY = 50      # steps between fix balance's repartitions

BEFORE = "balance 1.0 shift x 10 1.1\n"
DURING = {
    "shift": f"fix bal all balance {BALANCE_EVERY} 1.0 shift x 10 1.1\n",
    "rcb": f"comm_style tiled\nfix bal all balance {BALANCE_EVERY} 1.0 rcb\n",
    # weighted by each rank's measured time: the cuts move during the run, differently in
    # every run, and the bits must not care
    "rcb-time": f"comm_style tiled\nfix bal all balance {BALANCE_EVERY} 1.0 rcb weight time 1.0\n",
}
# fix balance's imbalance before its last repartition, to see that it repartitioned
REPORT = "thermo_style custom step f_bal[3] f_bal\n"
THERMO_RE = re.compile(r"^\s*(\d+)\s+(\S+)\s+(\S+)\s*$", re.M)
IMBALANCE_RE = re.compile(r"initial/final maximal load/proc = (\d+) (\d+)")


def plate_data(path, box_x):
    atoms = [((i + 0.5) * DX, (j + 0.5) * DX, 0.0) for j in range(NY) for i in range(NX)]
    box = [(0.0, box_x), (0.0, BOX_Y), (-0.5 * THICKNESS, 0.5 * THICKNESS)]
    write_data(path, atoms, box, DX * DX * THICKNESS)


def run(tmp_path, name, nprocs, balance=None, box_x=BOX_X):
    wd = tmp_path / name
    wd.mkdir()
    plate_data(wd / "atoms.data", box_x)
    # fixed x and y boundaries: a shrink-wrapped box would drop the empty part at once
    setup = SETUP_2D.format(grid=GRIDS[nprocs]).replace("boundary s s p", "boundary f f p")
    assert "boundary f f p" in setup
    script = setup + (BEFORE + DURING[balance] if balance else "") + \
        DYNAMICS.format(enforce2d="fix 2d all enforce2d") + \
        (REPORT if balance else "") + f"timestep {DT!r}\nrun {STEPS}\n" + FINISH
    out = run_lammps(script, workdir=wd, nprocs=nprocs).output
    return out, final_state(wd, out)


@pytest.fixture(scope="module")
def one_rank(tmp_path_factory):
    out, state = run(tmp_path_factory.mktemp("balance"), "np1", 1)
    notch, final = broken_counts(out)[0], broken_counts(out)[-1]
    assert final > notch > 0      # the crack grows, so the bits compare a fracture run
    return state


@pytest.mark.parametrize("balance", list(DURING))
@pytest.mark.parametrize("nprocs", [2, 4])
def test_balanced_run_same_bits_as_one_rank(tmp_path, one_rank, nprocs, balance):
    out, state = run(tmp_path, f"np{nprocs}-{balance}", nprocs, balance)
    # the balance command moved the planes: the most loaded rank holds fewer atoms after it
    before, after = map(int, IMBALANCE_RE.findall(out)[0])
    assert after < before
    # fix balance found the load uneven (above its threshold 1.0) and repartitioned
    assert max(float(b) for _, b, _ in THERMO_RE.findall(out)) > 1.0
    assert state[1:] == one_rank[1:]
    check_identical(one_rank[0], state[0], f"{balance} balance on {nprocs} ranks vs 1 rank")


def test_control_shift_balance_rounds_positions_in_other_boxes(tmp_path):
    """negative control: in a 100 mm box the shift balance alone, on one rank, moves the last
    bits of the positions, so the test above would see a change that is not the plugin's"""
    _, plain = run(tmp_path, "plain", 1, box_x=ROUNDING_BOX_X)
    _, shifted = run(tmp_path, "shifted", 1, "shift", box_x=ROUNDING_BOX_X)
    assert plain[1:] == shifted[1:]
    assert plain[0] != shifted[0]
