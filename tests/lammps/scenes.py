"""The opening lines every bbpd test input shares, written once.

peri_preamble() returns the text up to the body: the plugin, SI units, the dimension and
boundary, atom_style peri with the atom map the bbpd styles need, and optionally the processor
grid, the atoms of a data file and a lattice. Imported by name (pytest.ini puts tests/lammps on
the path): `from scenes import peri_preamble`.

impact_plate() gives the lines of the steel plate several tests strike at 32 m/s.
assert_forces_match() holds a dump's forces and pe/atom against refmodel.Bonds.
kw_run() runs examples/kalthoff-winkler's input; drawn_kw_cracks() draws straight cracks on its
plate for the post-processing alone.
cylinder_dropin() runs the glass cylinder of LAMMPS's examples/peri with a peri/* style and
with its bbpd/* port and checks that their damage agrees.
sibling() loads another test module of tests/lammps, whose plate or runner a test reuses.
"""
import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.runner import run_lammps


def sibling(name):
    """The test module tests/lammps/NAME.py, loaded as bbpd_NAME."""
    spec = importlib.util.spec_from_file_location(f"bbpd_{name}",
                                                  Path(__file__).with_name(f"{name}.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DROPIN_STEPS = (500, 1000)    # the steps whose damage is compared
DROPIN_RTOL = 0.02


def peri_preamble(dim=2, boundary=None, lattice=None, data=None, plugin=True, clear=False,
                  processors=None, atom_modify=""):
    """Input lines in this order: [clear] [plugin load bbpdplugin.so] units si, dimension (not
    written for 3, LAMMPS's default), boundary (default 's s p' in 2D, 's s s' in 3D),
    atom_style peri, atom_modify map array[ atom_modify], [processors P], [read_data DATA],
    [lattice LATTICE], each ending in a newline.

    plugin=False where the plugin is loaded before (a script of several sections after
    'clear') or not at all (LAMMPS's own peri styles)."""
    boundary = boundary or ("s s p" if dim == 2 else "s s s")
    lines = ["clear"] if clear else []
    if plugin:
        lines.append("plugin load bbpdplugin.so")
    lines.append("units si")
    if dim != 3:
        lines.append(f"dimension {dim}")
    lines += [f"boundary {boundary}", "atom_style peri",
              f"atom_modify map array{' ' + atom_modify if atom_modify else ''}"]
    if processors:
        lines.append(f"processors {processors}")
    if data:
        lines.append(f"read_data {data}")
    if lattice:
        lines.append(f"lattice {lattice}")
    return "\n".join(lines) + "\n"


def idle_compute_is_harmless(lmp, setup, compute):
    """A compute whose tip is off the plate is harmless as long as nothing uses it: setup (no
    plugin line) with the compute added runs 5 steps without an ERROR."""
    return "ERROR" not in lmp(f"plugin load bbpdplugin.so\n{setup}{compute}\nfix 1 all nve\n"
                              "run 5\n").output


def impact_plate(pair_style, gc):
    """After create_atoms on a 1 mm square lattice: steel (7800 kg/m3, E = 190 GPa, G_c = gc,
    delta = 5 mm) with pair_style, its left three columns moving at 32 m/s, fix nve in 2D."""
    return f"""set group all density 7800
set group all volume 1e-9
pair_style {pair_style}
pair_coeff 1 1 190e9 {gc} 0.005
region left block INF 3 INF INF INF INF
group left region left
velocity left set 32 0 0 units box
fix 1 all nve
fix 2 all enforce2d
"""


def assert_forces_match(dump, bonds, y, rtol):
    """dump's fx fy fz within rtol of the largest force, and its c_pea within rtol of the largest
    energy density, of bonds (a refmodel.Bonds) at the positions y"""
    got = ref.read_dump(dump)
    f_lmp = np.stack([got["fx"], got["fy"], got["fz"]], axis=1)
    f_ref = bonds.force_density(y)
    err = np.linalg.norm(f_lmp - f_ref, axis=1).max() / np.linalg.norm(f_ref, axis=1).max()
    assert err < rtol, f"max per-atom force error {err:.3g} of the largest force"
    w_ref = bonds.energy_density(y)
    np.testing.assert_allclose(got["c_pea"], w_ref, rtol=0, atol=rtol * w_ref.max())
    return got, w_ref


def cylinder_dropin(lmp, model, scale, atoms_abs=0):
    """examples/peri-MODEL-dropin's in.peri.MODEL and in.bbpd.MODEL at scale: the mean damage and
    the number of atoms with damage > 0.5 at DROPIN_STEPS agree within DROPIN_RTOL (the atom
    count also within atoms_abs); the loop-time ratio is printed, not asserted."""
    got = {}
    for style in ("peri", "bbpd"):
        out = lmp(str(EXAMPLES / f"peri-{model}-dropin" / f"in.{style}.{model}"),
                  vars={"scale": scale, "steps": 1000}).output
        table = ref.thermo_tables(out)[-1]
        rows = {int(s): k for k, s in enumerate(table["Step"])}
        got[style] = {step: (table["c_dmean"][rows[step]], table["c_ncracked"][rows[step]])
                      for step in DROPIN_STEPS}
        got[style]["loop"] = float(next(line.split()[3] for line in out.splitlines()
                                        if line.startswith("Loop time")))
    peri, ours = got["peri"], got["bbpd"]
    print(f"loop time peri/{model} {peri['loop']:.3f} s, bbpd/{model} {ours['loop']:.3f} s, "
          f"ratio {peri['loop'] / ours['loop']:.2f}")
    for step in DROPIN_STEPS:
        (d_peri, n_peri), (d_ours, n_ours) = peri[step], ours[step]
        print(f"step {step}: mean damage {d_peri:.6g} / {d_ours:.6g}, "
              f"atoms > 0.5: {n_peri:.0f} / {n_ours:.0f}")
        assert d_peri > 0.05 and n_peri > 50    # the target cracks: the comparison means something
        assert d_ours == pytest.approx(d_peri, rel=DROPIN_RTOL)
        assert n_ours == pytest.approx(n_peri, rel=DROPIN_RTOL, abs=atoms_abs)


def kw_run(work, dx, nprocs=1, script=None, **variables):
    """examples/kalthoff-winkler/in.kalthoff_winkler (or script), Gaussian at spacing dx, with
    the other -var variables given; returns work"""
    v = {"kernel": "gaussian", "dx": repr(dx)}
    v.update({k: str(x) for k, x in variables.items()})
    run_lammps(script or str(kw.EXAMPLE), work, nprocs=nprocs, vars=v)
    return work


def drawn_kw_cracks(angle_deg, length, dx=1.0e-3):
    """The Kalthoff-Winkler plate (100 x 200 mm, notches 50 mm long at y = 75 and 125 mm) as a
    grid of spacing dx whose damage is 0.44 (as next to a cut) along both notches and along two
    mirror cracks drawn straight from the tips at angle_deg for length: x, y, phi and the
    geometry dict the benchmark's measures take"""
    g = dict(dx=dx, delta=5 * dx, a=0.050, ylo=0.075, yhi=0.125, Lx=0.100, Ly=0.200)
    i, j = (m.ravel() for m in np.mgrid[0:round(g["Lx"] / dx), 0:round(g["Ly"] / dx)])
    x, y = (i + 0.5) * dx, (j + 0.5) * dx
    phi = 0.0 * x
    th = math.radians(angle_deg)
    for yn, sign in ((g["ylo"], -1.0), (g["yhi"], 1.0)):
        along_notch = (x < g["a"]) & (abs(y - yn) < dx)
        # distance along and across the drawn segment tip -> tip + length (cos th, sign sin th)
        s = (x - g["a"]) * math.cos(th) + sign * (y - yn) * math.sin(th)
        d = abs(-(x - g["a"]) * math.sin(th) + sign * (y - yn) * math.cos(th))
        phi[along_notch | ((s > 0) & (s <= length) & (d < 0.75 * dx))] = 0.44
    return x, y, phi, g


# the plate with a hole for quasi-static loading (test_minimize.py, test_relax.py):
# 40 x 20 mm, a 6 mm hole at its centre, delta = 2 mm = 3 Delta, 1 mm thick
HOLED_PLATE_DX, HOLED_PLATE_DELTA, HOLED_PLATE_H = 2.0e-3 / 3, 2.0e-3, 1.0e-3
HOLED_PLATE_L, HOLED_PLATE_W, HOLED_PLATE_R = 0.04, 0.02, 0.003


def holed_plate(pair_style, pair_coeff, density=2700.0):
    """the plate with its pair style, and the groups left and right: one horizon at each end"""
    dx, delta, h = HOLED_PLATE_DX, HOLED_PLATE_DELTA, HOLED_PLATE_H
    length, width, radius = HOLED_PLATE_L, HOLED_PLATE_W, HOLED_PLATE_R
    return peri_preamble(lattice=f"sq {dx} origin 0.5 0.5 0.0") + f"""
region          plate block 0.0 {length} 0.0 {width} -0.5 0.5 units box
create_box      1 plate
create_atoms    1 region plate
region          hole cylinder z {length / 2} {width / 2} {radius} INF INF units box
delete_atoms    region hole
set             group all density {density}
set             group all volume {dx * dx * h}
pair_style      {pair_style}
pair_coeff      {pair_coeff}
neighbor        {dx} bin
region          left block INF {delta} INF INF INF INF units box
region          right block {length - delta} INF INF INF INF INF units box
group           left region left
group           right region right
"""


# the end state of a run that breaks bonds, and the same run made in other ways
END_KEYS = ("x", "y", "z", "vx", "vy", "vz", "c_dmg")
END_DUMP = "write_dump all custom end.dump id x y z vx vy vz c_dmg modify sort id format float %.17g\n"


def assert_same_bits_every_way(lmp, tmp_path, head, lattice, steps, dt, others=()):
    """head (a script up to its run: compute dmg, thermo of c_dmean) run `steps` steps of dt on 1
    and 2 ranks (bonds must break), each script of others on 1 rank, and from a restart written
    half way on 1 and 2 ranks: every run ends in the same bits. Returns the outputs of others."""
    def end(script, nsteps, nprocs=1):
        out = lmp(script + f"fix 1 all nve\nrun {nsteps}\n" + END_DUMP, nprocs=nprocs).output
        d = ref.read_dump(tmp_path / "end.dump")
        return out, {k: np.asarray(d[k]) for k in END_KEYS}
    states, outs = [], []
    for nprocs in (1, 2):
        out, state = end(head, steps, nprocs)
        dmean = ref.thermo_tables(out)[-1]["c_dmean"]
        assert dmean[0] == 0.0 and dmean[-1] > 0.01, dmean    # bonds broke during the run
        states.append(state)
    for other in others:
        out, state = end(other, steps)
        outs.append(out)
        states.append(state)
    half = steps // 2
    lmp(head + f"fix 1 all nve\nrun {half}\nwrite_restart state.restart\n")
    second = ("plugin load bbpdplugin.so\nread_restart state.restart\n" + lattice +
              f"timestep {dt!r}\ncompute dmg all bbpd/damage/atom\n")
    for nprocs in (1, 2):
        states.append(end(second, steps - half, nprocs)[1])
    for other in states[1:]:
        for key in END_KEYS:
            np.testing.assert_array_equal(states[0][key], other[key])
    return outs
