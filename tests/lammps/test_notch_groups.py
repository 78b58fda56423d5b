"""fix bbpd/notch groups G1 G2: the bonds between two groups start broken.

A plate of 60 x 30 atoms split by the line y = 15 mm (between two atom rows) into the groups
`lower` and `upper`: cutting by these groups must break exactly the bonds the segment along
that line breaks, so a short impact run gives the same bits (%.17g dump, sorted by id) either
way, with a second notch (a segment) in the same fix; and the same bits on 2 and 4 ranks, where
bonds between a local atom and a ghost are cut from both ends. Negative control: two groups
without a bond between them cut nothing. After a restart the fix defined again cuts nothing new.
In 3D the groups either side of a plane cut what a rectangle over the whole plane cuts.
"""
import re
from pathlib import Path

import pytest

from test_mpi_restart import SETUP_3D as SETUP_3D_MPI
from test_mpi_restart import (BONDS_RE, DT, DYNAMICS, FINISH, GRIDS, check_identical, final_state,
                              grid_data, plate_2d)
from bbpd.runner import run_lammps

NX, NY = 60, 30
SPLIT_Y = 0.015        # the line between the atom rows at 14.5 and 15.5 mm
FULL_LINE = f"segment -0.001 {SPLIT_Y!r} 0.061 {SPLIT_Y!r}"   # beyond both plate edges
SHORT_NOTCH = "segment 0.0 0.007 0.02 0.007"                     # from the left edge, below
STEPS = 100
CUT_RE = re.compile(r"fix notch bbpd/notch: (\d+) bonds cut by (\d+) notch")

SETUP = plate_2d(0.007) + f"""\
region lower block INF INF INF {SPLIT_Y!r} INF INF units box
group lower region lower
group upper subtract all lower
region left block INF 0.01 INF INF INF INF units box
group left region left
region right block 0.05 INF INF INF INF INF units box
group right region right
fix notch all bbpd/notch {{notch}}
"""


def run(tmp_path, name, notch, nprocs=1, steps=STEPS):
    wd = tmp_path / name
    wd.mkdir()
    grid_data(wd / "atoms.data", (NX, NY, 1))
    script = (SETUP.format(grid=GRIDS[nprocs], notch=notch)
              + DYNAMICS.format(enforce2d="fix 2d all enforce2d")
              + f"timestep {DT!r}\nrun {steps}\n" + FINISH)
    out = run_lammps(script, workdir=wd, nprocs=nprocs).output
    return out, final_state(wd, out)


def test_groups_cut_what_the_equivalent_segment_cuts(tmp_path):
    ref_out, ref = run(tmp_path, "segments", f"{SHORT_NOTCH} {FULL_LINE}")
    out, state = run(tmp_path, "groups", f"{SHORT_NOTCH} groups lower upper")
    cut_ref, cut = CUT_RE.findall(ref_out), CUT_RE.findall(out)
    # the full line alone cuts every bond of the 3 rows each side that reaches across: many
    assert cut == cut_ref and int(cut[0][0]) > 5 * NX and cut[0][1] == "2"
    # the run breaks bonds beyond the notches, so the dumps compare a growing state
    assert int(BONDS_RE.findall(out)[-1][1]) > int(BONDS_RE.findall(out)[0][1])
    assert state[1:] == ref[1:]
    check_identical(ref[0], state[0], "groups vs segment")
    # idempotent: the run 0 after the run cuts nothing new (the message is printed once)
    assert len(cut) == 1


@pytest.mark.parametrize("nprocs", [2, 4])
def test_groups_same_bits_on_more_ranks(tmp_path, nprocs):
    _, ref = run(tmp_path, "np1", "groups lower upper")
    _, state = run(tmp_path, f"np{nprocs}", "groups lower upper", nprocs=nprocs)
    assert state[1:] == ref[1:]
    check_identical(ref[0], state[0], f"groups: 1 vs {nprocs} ranks")


def test_groups_that_do_not_touch_cut_nothing(tmp_path):
    """negative control: 'left' and 'right' are 40 mm apart, beyond the 3 mm horizon"""
    out, (atoms, _, broken) = run(tmp_path, "apart", "groups left right", steps=0)
    assert not CUT_RE.search(out)
    assert broken == 0 and all(float(line.split()[-1]) == 0.0 for line in atoms)


def test_groups_restart_cuts_nothing_new(tmp_path):
    """restart-safe: the broken bonds and the groups come back from the restart file, the fix
    defined again cuts nothing new"""
    wd = tmp_path / "restart"
    wd.mkdir()
    grid_data(wd / "atoms.data", (NX, NY, 1))
    first = SETUP.format(grid=GRIDS[1], notch="groups lower upper") + \
        "run 0\nwrite_restart s.restart\n"
    out1 = run_lammps(first, workdir=wd).output
    out = run_lammps("plugin load bbpdplugin.so\nread_restart s.restart\n"
                     "fix notch all bbpd/notch groups lower upper\nrun 0\nrun 0\n",
                     workdir=wd).output
    cut = int(CUT_RE.search(out1).group(1))
    assert cut > 5 * NX and not CUT_RE.search(out)
    assert [int(b) for _, b in BONDS_RE.findall(out)] == [cut, cut]


# 3D: the 16 x 10 x 6 block of test_mpi_restart.py, split by the plane y = 5 mm
SETUP_3D = SETUP_3D_MPI.replace(
    "fix notch all bbpd/notch rectangle 0.0 0.005 -0.001 0.006 0.0 0.0 0.0 0.0 0.008",
    "region below block INF INF INF 0.005 INF INF units box\ngroup below region below\n"
    "group above subtract all below\nfix notch all bbpd/notch {notch}")
PLANE = "rectangle -0.001 0.005 -0.001 0.018 0.0 0.0 0.0 0.0 0.008"   # beyond every face


def run_3d(tmp_path, name, notch, nprocs):
    wd = tmp_path / name
    wd.mkdir()
    grid_data(wd / "atoms.data", (16, 10, 6))
    script = (SETUP_3D.format(grid=GRIDS[nprocs], notch=notch) + DYNAMICS.format(enforce2d="")
              + f"timestep {DT!r}\nrun 50\n" + FINISH)
    out = run_lammps(script, workdir=wd, nprocs=nprocs).output
    return CUT_RE.findall(out), final_state(wd, out)


def test_groups_in_3d_cut_what_the_plane_cuts(tmp_path):
    assert "{notch}" in SETUP_3D
    cut_ref, ref = run_3d(tmp_path, "plane", PLANE, 1)
    for n in (1, 2):
        cut, state = run_3d(tmp_path, f"groups{n}", "groups below above", n)
        assert cut == cut_ref and int(cut[0][0]) > 16 * 6
        assert state[1:] == ref[1:]
        check_identical(ref[0], state[0], f"3D groups on {n} ranks vs plane")


EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "notch-groups" / "in.notch_groups"
CRACK_BAND_MM = (9.5, 12.0)    # y of every atom with damage > 0.35 at the end
TIP_MM = 15.0                  # x of the stair's tip


def test_example_stair_precrack_grows_from_its_tip(tmp_path):
    """examples/notch-groups: what its README states"""
    out = run_lammps(str(EXAMPLE), workdir=tmp_path).output
    assert "fix notch bbpd/notch: 762 bonds cut by 1 notch" in out
    text = (tmp_path / "damage.dump").read_text().splitlines()
    rows = [l.split() for l in text[text.index("ITEM: ATOMS id x y c_dmg") + 1:]]
    cracked = [(float(x) * 1e3, float(y) * 1e3) for _, x, y, d in rows if float(d) > 0.35]
    assert all(CRACK_BAND_MM[0] <= y <= CRACK_BAND_MM[1] for _, y in cracked)
    grown = max(x for x, _ in cracked) - TIP_MM
    assert 5.0 < grown < 10.0
