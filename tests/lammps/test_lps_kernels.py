"""Pair styles bbpd/lps/constant, bbpd/lps/triangular, bbpd/lps/gaussian (the kernel-weighted
linear peridynamic solid: PairBBPDLPS with its kernel coefficients, pair_bbpd_lps.h).

Energy: a block at m = delta / dx = 5 deformed by u = eps . (x - x_c), uniform dilatation
(eps = e I) and pure shear (eps_12 = eps_21 = e); the per-atom energy density (compute
pe/atom) of every interior atom (farther than delta from the surface: its family is whole)
against the classical W = lambda/2 tr(eps)^2 + G eps:eps of the model and nu (plane stress:
lambda' = E nu / (1 - nu^2)), for nu = 0.2 and 0.3, every kernel and model. The dilatation
is exact on the lattice (theta = d / m sum omega xi e V with e = xi n.eps.n gives tr eps with
the lattice's own m); the deviatoric energy of the shear carries the lattice's fourth moment
in place of the isotropic one, and the volume ramp of peri/pmb at the horizon: that cubic
anisotropy is largest for the constant kernel (its step at the horizon); at m = 7 the shear
eps_12 is within 0.7 %, while the same pure shear along the axes (eps_11 = -eps_22) is off by
-1.04 % in 3D (measured), so the test takes eps_12.

Also: the same bits on 1 and 2 ranks, on 2 OpenMP threads and across write_restart /
read_restart, and breaking:
an isotropically pre-stretched block (every bond at stretch s) keeps all its bonds at
s = 0.95 s0 and loses them at 1.05 s0, with s0 from G_c (bbpd_lps_kernel.h), computed here
independently.
"""
import math
import re

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import assert_same_bits_every_way, peri_preamble

KERNELS = ("constant", "triangular", "gaussian")
MODELS = ("3d", "plane/strain", "plane/stress")
POISSON = (0.2, 0.3)
# m = 7: the lattice's fourth moment of the constant kernel (a step at the horizon) is
# anisotropic by 6 % in 2D at m = 5 (2 % in 3D), by 0.7 % at m = 7 (tests/lammps/
# test_lps_kernels.py prints the table; the smooth kernels are below 0.4 % there)
M = 7
# the horizon a little past m dx, as LAMMPS's peri examples (3.015 lc): a bond of length
# exactly m dx would join the family |xi| <= delta or not by round-off, atom by atom
HORIZON = (M + 0.015) * 1.0e-3
STRAIN = 1.0e-5
DX = 1.0e-3
THICKNESS = 1.0e-3
YOUNGS = 200.0e9
DENSITY = 8000.0
GC = 1.0e4
MAX_ENERGY_ERROR = 0.01


def classical_energy(model, E, nu, eps):
    """W = lambda/2 tr(eps)^2 + G eps:eps (plane stress: lambda of plane stress)."""
    lam, G = ref.lame_moduli(model, E, nu)
    return 0.5 * lam * np.trace(eps) ** 2 + G * np.sum(eps * eps)


def deformations(dim):
    iso = np.zeros((dim, dim))
    iso[np.diag_indices(dim)] = STRAIN
    shear = np.zeros((dim, dim))
    shear[0, 1] = shear[1, 0] = STRAIN
    return {"dilatation": iso, "shear": shear}


def block(dim, m, nmore=5):
    n = 2 * m + nmore
    x0 = refmodel.square_lattice((n,) * dim, DX)
    centre = int(np.argmin(np.linalg.norm(x0 - x0.mean(axis=0), axis=1)))
    pad = (m + 1) * DX
    box = [(x0[:, k].min() - pad, x0[:, k].max() + pad) for k in range(3)]
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    return x0, centre, box


def style_line(kernel, model):
    thick = f" thickness {THICKNESS!r}" if model != "3d" else ""
    return f"pair_style bbpd/lps/{kernel} {model}{thick}\n"


def lattice_line(dim):
    return f"lattice {'sc' if dim == 3 else 'sq'} {DX!r}\n"


@pytest.mark.parametrize("model", MODELS)
def test_homogeneous_energy_density(lmp, tmp_path, model):
    dim = ref.DIMENSION[model]
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    x0, centre, box = block(dim, M)
    refmodel.write_data(tmp_path / "body.data", x0, volume, DENSITY, box)
    strains = deformations(dim)
    for name, eps in strains.items():
        e3 = np.zeros((3, 3))
        e3[:dim, :dim] = eps
        refmodel.write_positions(tmp_path / f"{name}.dump", x0 + (x0 - x0[centre]) @ e3.T, box)
    lo, hi = x0.min(axis=0) + HORIZON * 1.0001, x0.max(axis=0) - HORIZON * 1.0001
    zlo, zhi = (lo[2], hi[2]) if dim == 3 else (-1.0, 1.0)
    coords = "x y z" if dim == 3 else "x y"
    script = "plugin load bbpdplugin.so\n"
    cases = []
    for kernel in KERNELS:
        for nu in POISSON:
            script += (peri_preamble(dim, data="body.data", plugin=False, clear=True) +
                       lattice_line(dim) + style_line(kernel, model) +
                       f"pair_coeff * * {YOUNGS!r} {nu!r} none {HORIZON!r}\n"
                       f"region inner block {lo[0]!r} {hi[0]!r} {lo[1]!r} {hi[1]!r} {zlo!r} {zhi!r}"
                       " units box\ngroup inner region inner\n"
                       "compute pea all pe/atom\ncompute emin inner reduce min c_pea\n"
                       "compute emax inner reduce max c_pea\ncompute nin inner count/type atom\n"
                       "thermo_style custom step pe c_emin c_emax\n"
                       "thermo_modify format float %.17g\nrun 0\n")
            for name in strains:
                script += f"read_dump {name}.dump 0 {coords} box no replace yes\nrun 0\n"
            cases.append((kernel, nu))
    out = lmp(script).stdout
    tables = ref.thermo_tables(out)
    assert len(tables) == len(cases) * (1 + len(strains))
    rows, worst = [], 0.0
    for n, (kernel, nu) in enumerate(cases):
        runs = tables[n * (1 + len(strains)):(n + 1) * (1 + len(strains))]
        assert runs[0]["c_emax"][-1] == 0.0
        for (name, eps), t in zip(strains.items(), runs[1:]):
            w = classical_energy(model, YOUNGS, nu, eps)
            errs = (t["c_emin"][-1] / w - 1.0, t["c_emax"][-1] / w - 1.0)
            err = max(errs, key=abs)
            worst = max(worst, abs(err))
            rows.append(f"{model},{kernel},{nu},{name},{errs[0]:+.5f},{errs[1]:+.5f}")
            assert abs(errs[0]) < MAX_ENERGY_ERROR and abs(errs[1]) < MAX_ENERGY_ERROR, rows[-1]
    print("\nmodel,kernel,nu,deformation,min error,max error (interior atoms)\n" + "\n".join(rows))


def test_energy_check_can_fail(lmp, tmp_path):
    """The energy comparison can fail: a wrong Poisson's ratio (0.2 against 0.3) misses the
    classical energy of the dilatation by far more than 1 %."""
    x0, centre, box = block(3, 3)
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    eps = STRAIN * np.eye(3)
    refmodel.write_positions(tmp_path / "iso.dump", x0 + (x0 - x0[centre]) @ eps.T, box)
    script = (peri_preamble(3, data="body.data") + lattice_line(3) + style_line("constant", "3d") +
              f"pair_coeff * * {YOUNGS!r} 0.2 none {3.015 * DX!r}\n"
              f"compute pea all pe/atom\ngroup c id {centre + 1}\ncompute ec c reduce sum c_pea\n"
              "thermo_style custom step c_ec\nthermo_modify format float %.17g\n"
              "read_dump iso.dump 0 x y z box no replace yes\nrun 0\n")
    t = ref.thermo_tables(lmp(script).stdout)[-1]
    assert t["c_ec"][-1] == pytest.approx(classical_energy("3d", YOUNGS, 0.2, eps), rel=1e-6)
    assert abs(t["c_ec"][-1] / classical_energy("3d", YOUNGS, 0.3, eps) - 1.0) > 0.1


# ---------------------------------------------------------------------------
# the same bits on 1 and 2 ranks and across a restart, in a run where bonds break

RUN_CASES = (("gaussian", "3d"), ("triangular", "plane/stress"), ("constant", "plane/strain"))
RUN_N = 10
RUN_HORIZON = 3.015 * DX
RUN_STEPS = 60
RUN_DT = 5.0e-8
EXPANSION_RATE = 2.0e4    # 1/s: the bonds reach s0 (~4e-3) within the run



def run_head(tmp_path, kernel, model, nprocs_grid=None):
    dim = ref.DIMENSION[model]
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    x0, centre, box = block(dim, 0, nmore=RUN_N)
    refmodel.write_data(tmp_path / "run.data", x0, volume, DENSITY, box)
    c = x0[centre]
    zvar = f"variable vz atom {EXPANSION_RATE!r}*(z-{c[2]!r})\n" if dim == 3 else ""
    vz = "v_vz" if dim == 3 else "NULL"
    return (peri_preamble(dim, data="run.data") + lattice_line(dim) + style_line(kernel, model) +
            f"pair_coeff * * {YOUNGS!r} 0.3 {GC!r} {RUN_HORIZON!r}\n"
            f"variable vx atom {EXPANSION_RATE!r}*(x-{c[0]!r})\n"
            f"variable vy atom {EXPANSION_RATE!r}*(y-{c[1]!r})\n" + zvar +
            f"velocity all set v_vx v_vy {vz}\n"
            f"timestep {RUN_DT!r}\ncompute dmg all bbpd/damage/atom\n"
            "compute dmean all reduce ave c_dmg\nthermo_style custom step pe c_dmean\n"
            "thermo 10\nthermo_modify format float %.17g\n")


@pytest.mark.parametrize("kernel,model", RUN_CASES)
def test_same_bits_on_1_and_2_ranks_and_restart(lmp, tmp_path, kernel, model):
    head = run_head(tmp_path, kernel, model)
    threaded = head.replace("units si", "package omp 2\nunits si", 1)
    out, = assert_same_bits_every_way(lmp, tmp_path, head, lattice_line(ref.DIMENSION[model]),
                                      RUN_STEPS, RUN_DT, [threaded])
    assert "1 MPI tasks x 2 OpenMP threads" in out


# ---------------------------------------------------------------------------
# breaking: every bond of an isotropically stretched block is at the stretch s


def critical_stretch(kernel, model, nu, gc, delta):
    """s0 of the header comment of bbpd_lps_kernel.h, by numpy quadrature of the moments"""
    w = ref.kernel(kernel)
    r = np.linspace(0.0, 1.0, 400001)

    def moment(n):
        return np.trapz(w(r) * r**n, r)
    G = YOUNGS / (2.0 * (1.0 + nu))
    if ref.DIMENSION[model] == 2:
        per_s2 = 8.0 / math.pi * G * delta * moment(4) / moment(3)
    else:
        per_s2 = 15.0 / 4.0 * G * delta * moment(5) / moment(4)
    return math.sqrt(gc / per_s2)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("kernel", KERNELS)
def test_breaks_above_s0_not_below(lmp, tmp_path, kernel, model):
    dim = ref.DIMENSION[model]
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    x0, centre, box = block(dim, 0, nmore=7)
    box = [(lo * 1.2, hi * 1.2) for lo, hi in box] if dim == 3 else box
    refmodel.write_data(tmp_path / "b.data", x0, volume, DENSITY, box)
    nu = 0.3
    s0 = critical_stretch(kernel, model, nu, GC, RUN_HORIZON)
    coords = "x y z" if dim == 3 else "x y"
    script = "plugin load bbpdplugin.so\n"
    factors = (0.95, 1.05)
    for f in factors:
        eps = np.zeros((3, 3))
        eps[np.diag_indices(dim)] = f * s0
        refmodel.write_positions(tmp_path / f"s{f}.dump", x0 + (x0 - x0[centre]) @ eps.T, box)
        script += (peri_preamble(dim, data="b.data", plugin=False, clear=True) + lattice_line(dim) +
                   style_line(kernel, model) + f"pair_coeff * * {YOUNGS!r} {nu!r} {GC!r} {RUN_HORIZON!r}\n"
                   "compute dmg all bbpd/damage/atom\ncompute dmax all reduce max c_dmg\n"
                   "compute dmin all reduce min c_dmg\n"
                   "thermo_style custom step c_dmin c_dmax\nthermo_modify format float %.17g\n"
                   "run 0\n"
                   f"read_dump s{f}.dump 0 {coords} box no replace yes\n"
                   f"timestep {1e-12!r}\nfix 1 all nve\nrun 1\n")
    out = lmp(script).output
    # the style's s0 (printed to 8 digits) is the one computed here
    printed = float(re.search(r"critical_stretch s0 = (\S+)", out).group(1))
    assert printed == pytest.approx(s0, rel=1e-7)
    tables = ref.thermo_tables(out)
    below, above = tables[1], tables[3]
    assert below["c_dmax"][-1] == 0.0, "bonds broke below s0"
    assert above["c_dmin"][-1] == 1.0, "bonds survived above s0"
