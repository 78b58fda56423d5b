"""Dynamic fracture is bitwise independent of the MPI rank count and of a restart.

The bbpd styles evaluate every bond from both ends and sum each atom's partners in tag order
(pair_bbpd.cpp), so a run must give the same bits on 1, 2 and 4 ranks, and `run 2N` must give
the same bits as `run N` + write_restart + read_restart (in a new process) + `run N`.

The atoms come from data files, so their tags do not depend on the rank count; that the
numbering does not matter either (create_atoms numbers atoms rank by rank) is tested in
test_reliability.py.
"""
import re

import pytest

from bbpd.runner import run_lammps
from scenes import peri_preamble

DX = 1.0e-3            # grid spacing (m)
THICKNESS = 1.0e-3     # plate thickness (m)
RHO = 7800.0           # maraging steel density (kg/m^3), potentials/kalthoff_winkler_steel.bbpd
E = 190.0e9            # Young's modulus (Pa), same file
GC = 6.9e3             # 1/10 of the steel's Gc: the crack starts within 200 steps of 50 ns
V_IMPACT = 32.0        # Kalthoff-Winkler impact speed (m/s), paper sec. 4.2.3
DT = 5.0e-8            # 0.28 (2D) and 0.37 (3D) of the velocity-Verlet limit the pair reports
GRIDS = {1: "1 1 1", 2: "2 1 1", 4: "2 2 1"}

BONDS_RE = re.compile(r"total bonds (\d+) \((\d+) broken\)")


def write_data(path, atoms, box, volume):
    """Data file (atom_style peri) with tags in the order of `atoms`."""
    lines = ["BBPD test atoms, tags independent of the rank count", "",
             f"{len(atoms)} atoms", "1 atom types", ""]
    lines += [f"{lo!r} {hi!r} {d}lo {d}hi" for (lo, hi), d in zip(box, "xyz")]
    lines += ["", "Atoms # peri", ""]
    lines += [f"{t} 1 {volume!r} {RHO!r} {x!r} {y!r} {z!r}" for t, (x, y, z) in
              enumerate(atoms, start=1)]
    path.write_text("\n".join(lines) + "\n")


def grid_data(path, n):
    """simple-cubic (nz > 1) or square grid of nx x ny (x nz) atoms, row-major tags"""
    nx, ny, nz = n
    if nz == 1:
        atoms = [((i + 0.5) * DX, (j + 0.5) * DX, 0.0) for j in range(ny) for i in range(nx)]
        box = [(0.0, nx * DX), (0.0, ny * DX), (-0.5 * THICKNESS, 0.5 * THICKNESS)]
        volume = DX * DX * THICKNESS
    else:
        atoms = [((i + 0.5) * DX, (j + 0.5) * DX, (k + 0.5) * DX)
                 for k in range(nz) for j in range(ny) for i in range(nx)]
        box = [(0.0, nx * DX), (0.0, ny * DX), (0.0, nz * DX)]
        volume = DX ** 3
    write_data(path, atoms, box, volume)


def blocks_data(path):
    """two 15 x 20 blocks, 4 mm apart (no bond between them), the right one shifted by half a
    spacing in y so that each face atom meets two atoms of the other face"""
    left = [((i + 0.5) * DX, (j + 0.5) * DX, 0.0) for j in range(20) for i in range(15)]
    right = [((i + 18.5) * DX, (j + 1.0) * DX, 0.0) for j in range(20) for i in range(15)]
    box = [(0.0, 35 * DX), (0.0, 21 * DX), (-0.5 * THICKNESS, 0.5 * THICKNESS)]
    write_data(path, left + right, box, DX * DX * THICKNESS)


def plate_2d(impact_top):
    """A small Kalthoff-Winkler plate (the atoms of atoms.data), its impact layer 3 mm wide from
    y = 0 to impact_top, struck at V_IMPACT."""
    return peri_preamble(2, processors="{grid}", data="atoms.data") + f"""\
pair_style bbpd/triangular plane/strain thickness {THICKNESS!r}
pair_coeff * * {E!r} {GC!r} 0.003015
region impact block INF 0.003 INF {impact_top!r} INF INF units box
group impact region impact
velocity impact set {V_IMPACT!r} 0.0 0.0 units box
"""


# 2D: 60 x 30 atoms, notch from the left edge between the atom rows at y = 15 mm, the impact
# layer below it
SETUP_2D = plate_2d(0.015) + "fix notch all bbpd/notch segment 0.0 0.015 0.02 0.015\n"

# 3D: a 16 x 10 x 6 block, notch plane y = 5 mm from the left face to x = 6 mm
SETUP_3D = peri_preamble(3, processors="{grid}", data="atoms.data") + f"""\
pair_style bbpd/gaussian 3d
pair_coeff * * {E!r} {GC!r} 0.003015
region impact block INF 0.003 INF 0.005 INF INF units box
group impact region impact
velocity impact set {V_IMPACT!r} 0.0 0.0 units box
fix notch all bbpd/notch rectangle 0.0 0.005 -0.001 0.006 0.0 0.0 0.0 0.0 0.008
"""

# what a restart file does not hold: fixes, computes, neighbor settings. A small skin makes
# LAMMPS reneighbor (and migrate atoms) during the run.
DYNAMICS = """
neighbor 0.0001 bin
neigh_modify every 1 delay 0 check yes
fix nve all nve
fix hold impact setforce 0.0 0.0 0.0
{enforce2d}
compute dmg all bbpd/damage/atom
thermo 50
"""

# contact: two elastic blocks collide at 2 x 500 m/s; they touch after about 130 steps
SETUP_CONTACT = peri_preamble(2, processors="{grid}", data="atoms.data") + f"""\
pair_style bbpd/triangular plane/strain thickness {THICKNESS!r} contact yes contact/distance 1.0
pair_coeff * * {E!r} none 0.003015
region left block INF 0.016 INF INF INF INF units box
group left region left
group right subtract all left
velocity left set 500.0 0.0 0.0 units box
velocity right set -500.0 0.0 0.0 units box
"""
DYNAMICS_CONTACT = """
neighbor 0.0001 bin
neigh_modify every 1 delay 0 check yes
fix nve all nve
fix 2d all enforce2d
compute dmg all bbpd/damage/atom
thermo 50
"""

# final state at full precision, then `run 0` prints the broken-bond count of that state
FINISH = """
write_dump all custom final.dump id x y z vx vy vz fx fy fz c_dmg modify sort id format float %.17g
run 0
"""

SCENES = {
    "2d": dict(setup=SETUP_2D, data=lambda p: grid_data(p, (60, 30, 1)),
               dynamics=DYNAMICS.format(enforce2d="fix 2d all enforce2d"), dt=DT),
    "3d": dict(setup=SETUP_3D, data=lambda p: grid_data(p, (16, 10, 6)),
               dynamics=DYNAMICS.format(enforce2d=""), dt=DT),
    "contact": dict(setup=SETUP_CONTACT, data=blocks_data, dynamics=DYNAMICS_CONTACT, dt=2.5e-8),
}


def fresh_script(scene, nprocs, steps):
    s = SCENES[scene]
    return (s["setup"].format(grid=GRIDS[nprocs]) + s["dynamics"]
            + f"timestep {s['dt']!r}\nrun {steps}\n" + FINISH)


def run_in(workdir, scene, script, nprocs):
    workdir.mkdir(parents=True, exist_ok=True)
    if not (workdir / "atoms.data").exists():
        SCENES[scene]["data"](workdir / "atoms.data")
    out = run_lammps(script, workdir=workdir, nprocs=nprocs).output
    if "processors" in script:
        assert f"{GRIDS[nprocs].replace(' ', ' by ')} MPI processor grid" in out
    return out


def final_state(workdir, out):
    """(atom lines of the dump as text, bonds, broken bonds at the final `run 0`)"""
    text = (workdir / "final.dump").read_text().splitlines()
    atoms = text[next(i for i, l in enumerate(text) if l.startswith("ITEM: ATOMS")) + 1:]
    total, broken = map(int, BONDS_RE.findall(out)[-1])
    return atoms, total, broken


def broken_counts(out):
    """broken bonds of every setup report, in order"""
    return [int(b) for _, b in BONDS_RE.findall(out)]


def damaged_atoms(atoms):
    return sum(float(line.split()[-1]) > 0.0 for line in atoms)


def check_identical(ref, other, label):
    """bitwise identity of the %.17g text; name the first differing atom if not"""
    assert len(ref) == len(other)
    diff = [(a, b) for a, b in zip(ref, other) if a != b]
    assert not diff, f"{label}: {len(diff)} atoms differ, first:\n  {diff[0][0]}\n  {diff[0][1]}"



@pytest.mark.parametrize("scene,ranks,steps", [
    ("2d", [1, 2, 4], 200),
    ("3d", [1, 2], 200),
    ("contact", [1, 2, 4], 400),
])
def test_rank_count_invariance(tmp_path, scene, ranks, steps):
    states = {}
    for n in ranks:
        wd = tmp_path / f"np{n}"
        out = run_in(wd, scene, fresh_script(scene, n, steps), n)
        states[n] = final_state(wd, out)
        # the test is void unless LAMMPS reneighbours and (with fracture) bonds break
        # beyond the notch
        assert int(re.findall(r"Neighbor list builds = (\d+)", out)[0]) > 0
        if scene != "contact":
            notch, final = broken_counts(out)[0], broken_counts(out)[-1]
            assert final > notch > 0
            assert damaged_atoms(states[n][0]) > 0
    ref_atoms, ref_total, ref_broken = states[1]
    for n in ranks[1:]:
        atoms, total, broken = states[n]
        assert (total, broken) == (ref_total, ref_broken), f"{n} ranks"
        check_identical(ref_atoms, atoms, f"{scene}: 1 vs {n} ranks")


# model, thickness, E, Gc, horizon, c0, s0 and grid spacing of the setup report
PAIR_REPORT = re.compile(r"(BBPD pair style .*?grid spacing[^\n]*)", re.S)


def restart_scripts(scene, nwrite, steps):
    s = SCENES[scene]
    first = (s["setup"].format(grid=GRIDS[nwrite]) + s["dynamics"]
             + f"timestep {s['dt']!r}\nrun {steps}\nwrite_restart state.restart\nrun 0\n")
    # no pair_style, pair_coeff, timestep or notch: they must come back from the file
    second = "plugin load bbpdplugin.so\nread_restart state.restart\n" + s["dynamics"] + \
        f"run {steps}\n" + FINISH
    return first, second


@pytest.mark.parametrize("nwrite,nread", [(1, 1), (2, 2), (1, 2)])
def test_restart_equals_continuous_run(tmp_path, nwrite, nread):
    scene, half = "2d", 100
    ref_dir = tmp_path / "continuous"
    ref_out = run_in(ref_dir, scene, fresh_script(scene, 1, 2 * half), 1)
    ref_atoms, ref_total, ref_broken = final_state(ref_dir, ref_out)

    wd = tmp_path / "restarted"
    first, second = restart_scripts(scene, nwrite, half)
    assert "pair_style" not in second and "bbpd/notch" not in second
    out1 = run_in(wd, scene, first, nwrite)
    out2 = run_in(wd, scene, second, nread)

    # the crack grows in both halves, so the restart carries a growing crack
    notch, at_write = broken_counts(out1)[0], broken_counts(out1)[-1]
    assert notch < at_write < ref_broken
    # pair style, coefficients, timestep and broken bonds come back from the restart file
    assert PAIR_REPORT.search(out2).group(1) == PAIR_REPORT.search(ref_out).group(1)
    assert broken_counts(out2)[0] == at_write
    assert f"timestep = {DT:g} " in out2

    atoms, total, broken = final_state(wd, out2)
    assert (total, broken) == (ref_total, ref_broken)
    check_identical(ref_atoms, atoms, f"restart {nwrite} -> {nread} ranks")
