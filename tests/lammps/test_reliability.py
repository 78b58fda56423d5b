"""Reliability of the bond families against LAMMPS's contracts: large families that migrate
between ranks, the neighbor list of the family build, bonds across periodic boundaries,
restarts, a re-issued pair_style, the unstable-run message and the atom numbering.
The cases are listed in doc/stability.md (extreme cases and bad input)."""
import re

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from bbpd.runner import LammpsError
from scenes import impact_plate, peri_preamble

DX = 1.0e-3
RHO = 7800.0
E = 190.0e9
TIMEOUT = 300

def block_3d(n, m, boundary="p p p", processors=None, extra=""):
    """n^3 simple-cubic steel block, Gaussian kernel with horizon m dx, no fracture."""
    return peri_preamble(3, boundary, processors=processors, lattice=f"sc {DX!r}") + f"""\
region box block 0 {n} 0 {n} 0 {n}
create_box 1 box
create_atoms 1 box
set group all density {RHO!r}
set group all volume {DX ** 3!r}
pair_style bbpd/gaussian 3d
pair_coeff * * {E!r} none {m * DX!r}
{extra}"""


# --------------------------------------------------------------------------- exchange buffer

def migrating_block(n, m):
    """The block translates by 3 lattice planes between reneighborings (every 10 steps) across
    the boundary of 2 ranks: every exchange carries atoms with ~(4/3) pi (m + 1/2)^3 partners."""
    return block_3d(n, m, processors="2 1 1") + f"""neighbor {1e-3 * DX!r} bin
neigh_modify every 10 delay 0 check no
velocity all set 6000.0 0.0 0.0 units box
fix nve all nve
timestep 5e-8
thermo 10
run 40
"""


def check_migrated(out, n):
    assert int(re.findall(r"Neighbor list builds = (\d+)", out)[-1]) == 4
    assert f"Created {n ** 3} atoms" in out
    # rigid translation: the bonds keep their length, the energy stays at round-off level
    table = ref.thermo_tables(out)[-1]
    assert np.all(np.abs(table["E_pair"]) < 1e-6 * table["TotEng"])


def test_large_families_migrate_between_ranks(lmp):
    """m = 6: 1150 partners, more than the 1024 values of slack LAMMPS gives a migrating atom
    unless the fix declares its size (crashed in pack_exchange before)."""
    out = lmp(migrating_block(14, 6), nprocs=2, timeout=TIMEOUT).output
    check_migrated(out, 14)


@pytest.mark.slow
def test_m7_families_migrate_between_ranks(lmp):
    """The scene of the report: m = 7 (1790 partners per atom), 16^3 periodic block."""
    out = lmp(migrating_block(16, 7), nprocs=2, timeout=TIMEOUT).output
    check_migrated(out, 16)
    assert "bonds per atom: min 1790 mean 1790 max 1790" in out


# --------------------------------------------------------------------------- neighbor list size

def test_large_family_sizes_the_neighbor_list(lmp):
    """m = 7 in 3D lists ~2600 atoms within the family cutoff + skin, more than LAMMPS's default
    'neigh_modify one 2000': the fix raises it (before: 'Neighbor list overflow')."""
    out = lmp(block_3d(16, 7, boundary="s s s") + "run 0\n", timeout=TIMEOUT).output
    need = int(re.search(r"bond families need up to (\d+) neighbors per atom", out)[1])
    assert need > 2000
    assert "bonds per atom: min" in out and "max 1790" in out


def test_user_neighbor_limit_is_kept_when_larger(lmp):
    out = lmp(block_3d(16, 7, boundary="s s s", extra="neigh_modify one 5000 page 60000\n")
              + "run 0\n", timeout=TIMEOUT).output
    assert "bond families need up to" not in out
    assert "max 1790" in out


# --------------------------------------------------------------------------- periodic images

S0 = 0.001
PAIRS = 40


def straddling_pairs(tmp_path, seed=12, alpha=False):
    """PAIRS two-atom bodies in a box periodic in x, each straddling the x boundary, far apart
    in y; returns the script that stretches each bond to s0 (to round-off) and runs."""
    rng = np.random.default_rng(seed)
    lo = 0.0123
    hi = lo + 20 * DX
    length = hi - lo    # what LAMMPS uses as the period
    x0, moved = [], []
    for k in range(PAIRS):
        y = k * 5 * DX
        a, b = lo + rng.uniform(0.1, 1.4) * DX, hi - rng.uniform(0.1, 1.4) * DX
        x0 += [(a, y, 0.0), (b, y, 0.0)]
        d0 = b - a - length    # the minimum image: the bond crosses the boundary
        # place the right atom so that the exact stretch is s0
        moved.append((2 * k + 2, a + length - (-d0) * (1.0 + S0)))
    box = [(lo, hi), (-2 * DX, PAIRS * 5 * DX), (-0.5 * DX, 0.5 * DX)]
    refmodel.write_data(tmp_path / "pairs.data", np.array(x0), DX * DX * DX, RHO, box)
    sets = "".join(f"set atom {t} x {x!r}\n" for t, x in moved)
    # with alpha the setup of a run re-evaluates the step before without breaking (pair_bbpd.rst):
    # the bonds are first tested at step 1, after a step too short to move an atom by one ulp
    dt = 1e-15 if alpha else 1e-9
    return peri_preamble(2, "p f p", data="pairs.data") + f"""\
pair_style bbpd/gaussian{"/alpha" if alpha else ""} plane/stress thickness {DX!r}
pair_coeff * * {E!r} none {3 * DX!r} critical_stretch {S0!r}{" alpha 0.25" if alpha else ""}
fix nve all nve
fix 2d all enforce2d
compute d all bbpd/damage/atom
variable mvx atom mass*vx
variable amvx atom abs(mass*vx)
compute p all reduce sum v_mvx v_amvx
run 0
{sets}timestep {dt!r}
thermo_style custom step c_p[1] c_p[2]
thermo_modify format float %.17g
run 3
write_dump all custom final.dump id x c_d vx modify sort id format float %.17g
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("alpha", [False, True], ids=["plain", "alpha"])
def test_periodic_bonds_break_at_both_ends(lmp, tmp_path, nprocs, alpha):
    """Bonds stretched to s0 across the periodic boundary: each end sees the other through an
    image x +- L that rounds differently. Every bond must be broken at both ends or at none
    (equal damage of the two atoms of a body), so momentum stays zero; also with the
    Silling-Askari rule (alpha; in tension it keeps s0), whose loop decides breaking apart."""
    out = lmp(straddling_pairs(tmp_path, alpha=alpha), nprocs=nprocs, timeout=TIMEOUT).output
    final = ref.read_dump(tmp_path / "final.dump")
    damage = final["c_d"].reshape(PAIRS, 2)
    broken = damage[:, 0] == 1.0
    assert 0 < np.count_nonzero(broken) < PAIRS    # the scene sits at the threshold
    np.testing.assert_array_equal(damage[:, 0], damage[:, 1])
    # a bond pulling at one end only gives its body a momentum of the order of the sum of |mv|
    table = ref.thermo_tables(out)[-1]
    assert table["c_p[2]"][-1] > 0.0
    assert np.all(np.abs(table["c_p[1]"]) <= 1e-12 * table["c_p[2]"][-1])


# --------------------------------------------------------------------------- restart

def exploding_plate(velocity_scale):
    """A soft 3 x 3 plate (E = 1e3 Pa: stable time-step bound 2e-3 s) set flying apart at up to
    1400 m/s with a timestep of 1e-6 s: atoms move 1.4 spacings per step, so only the growth
    of the still-bonded body (1000 x its size after ~1000 steps) reveals the explosion."""
    return peri_preamble(2, lattice=f"sq {DX!r}") + f"""\
region box block -0.5 2.5 -0.5 2.5 -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {RHO!r}
set group all volume {DX ** 3!r}
pair_style bbpd/gaussian plane/stress thickness {DX!r}
pair_coeff * * 1000.0 none {3 * DX!r}
variable vx atom {velocity_scale!r}*(x-{DX!r})
variable vy atom {velocity_scale!r}*(y-{DX!r})
velocity all set v_vx v_vy 0.0 units box
fix nve all nve
fix 2d all enforce2d
neigh_modify every 1 delay 0 check yes
timestep 1e-6
thermo 500
run 100
"""


RESTARTED = """plugin load bbpdplugin.so
units si
atom_modify map array
read_restart state.restart
fix nve all nve
fix 2d all enforce2d
neigh_modify every 1 delay 0 check yes
thermo 500
run 3000
"""

UNSTABLE = re.compile(r"unstable at step (\d+) .*the bonded body spans (\S+) x its size")


def test_restart_keeps_the_unstable_run_detector(lmp, tmp_path):
    """The size of the body at bond creation travels in the restart file: the restarted run
    stops at the same step, with the same message, as the uninterrupted one."""
    script = exploding_plate(1.0e6)
    with pytest.raises(LammpsError) as whole:
        lmp(script + "run 3000\n", timeout=TIMEOUT)
    step, spans = UNSTABLE.search(whole.value.message).groups()
    assert float(spans) >= 1000.0    # printed to 3 digits
    lmp(script + "write_restart state.restart\n", timeout=TIMEOUT)
    with pytest.raises(LammpsError) as restarted:
        lmp(RESTARTED, timeout=TIMEOUT)
    assert UNSTABLE.search(restarted.value.message).groups() == (step, spans)


# --------------------------------------------------------------------------- re-issued pair_style

PLATE_2D = peri_preamble(2, lattice=f"sq {DX!r}") + f"""\
region box block 0 12 0 8 -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {RHO!r}
set group all volume {DX ** 3!r}
"""
REPORT = re.compile(r"(BBPD pair style .*?stable timestep[^\n]*)", re.S)


def test_reissued_pair_style_recalibrates(lmp):
    """pair_style re-issued with another model and thickness after a run: c0, s0, the grid
    spacing and the stable bound of the next setup equal those of a fresh run."""
    gaussian = "pair_style bbpd/gaussian {}\n"
    coeff = f"pair_coeff * * {E!r} 6.9e4 0.003015\n"
    fresh = lmp(PLATE_2D + gaussian.format("plane/stress thickness 0.002") + coeff
                + "run 0\n").output
    first = gaussian.format("plane/strain thickness 0.001")
    out = lmp(PLATE_2D + first + coeff + "run 0\n"
              + gaussian.format("plane/stress thickness 0.002") + "run 0\n").output
    reports = REPORT.findall(out)
    assert len(reports) == 2 and reports[0] != reports[1]
    assert reports[1] == REPORT.search(fresh).group(1)


# --------------------------------------------------------------------------- the message

def test_fast_impact_names_the_velocity_not_the_timestep(lmp):
    """E = 1e3 Pa (wave speed 0.36 m/s) hit at 20 m/s with dt = 0.44 of the stable bound:
    atoms move ~18 spacings per step. The ERROR names the velocities, not the timestep."""
    script = PLATE_2D + f"""pair_style bbpd/gaussian plane/stress thickness {DX!r}
pair_coeff * * 1000.0 none 0.003015
region impact block INF 2 INF INF INF INF
group impact region impact
velocity impact set 20.0 0.0 0.0 units box
fix nve all nve
fix 2d all enforce2d
compute dtb all pair bbpd/gaussian
run 0
variable dt equal 0.44*c_dtb[1]
timestep ${{dt}}
run 100
"""
    with pytest.raises(LammpsError) as err:
        lmp(script)
    message = err.value.message
    assert "unstable" in message and "Reduce the imposed velocities" in message
    assert "0.44 of the stable bound" in message
    assert "must stay below" not in message


# --------------------------------------------------------------------------- atom numbering

NUMBERED = peri_preamble(2, processors="{grid}", lattice="sq 0.001") + """\
region box block 0 40 0 20 -0.5 0.5
create_box 1 box
create_atoms 1 box
""" + impact_plate("bbpd/gaussian plane/strain thickness 0.001", "6.9e4") + """\
fix n all bbpd/notch segment 0.02 0.0095 0.03 0.0095
compute d all bbpd/damage/atom
write_dump all custom initial.dump id x y modify format float %.17g sort id
neighbor 0.0001 bin
timestep 8.7e-8
thermo 100
run 400
write_dump all custom final.dump id x y vx vy c_d modify format float %.17g sort id
"""


def by_initial_position(workdir):
    """final dump lines keyed by the atom's initial position (text), with the id removed"""
    first = {l.split()[0]: " ".join(l.split()[1:]) for l in
             (workdir / "initial.dump").read_text().split("ITEM: ATOMS id x y\n")[1].splitlines()}
    final = (workdir / "final.dump").read_text().split("c_d\n")[1].splitlines()
    return {first[l.split()[0]]: " ".join(l.split()[1:]) for l in final}, first


def test_same_bits_whatever_the_atom_numbering(lmp, tmp_path):
    """create_atoms numbers atoms rank by rank, so 1 and 2 ranks give the same atoms different
    ids: families are summed in reference-offset order, so the trajectories are bitwise equal."""
    states = {}
    for n, grid in ((1, "1 1 1"), (2, "2 1 1")):
        wd = tmp_path / f"np{n}"
        wd.mkdir()
        from bbpd.runner import run_lammps
        run_lammps(NUMBERED.format(grid=grid), workdir=wd, nprocs=n, timeout=TIMEOUT)
        states[n] = by_initial_position(wd)
    (final1, ids1), (final2, ids2) = states[1], states[2]
    assert ids1 != ids2    # the numbering differs
    assert sorted(ids1.values()) == sorted(ids2.values())
    assert any(float(v.split()[-1]) > 0.0 for v in final1.values())    # the crack grew
    diff = [p for p in final1 if final1[p] != final2[p]]
    assert not diff, f"{len(diff)} atoms differ, first at {diff[0]}"
