"""'pair_style bbpd/pmb' against LAMMPS's own peri/pmb, and the Silling-Askari critical
stretch of the bbpd/KERNEL/alpha styles ('alpha').

Forces: a perturbed 3D block whose reference lattice is read from a data file (%.17g),
so both styles start from the same doubles; a few atoms are pushed towards a neighbour
so bonded pairs come closer than 0.9 |xi| and the short-range force acts on them.
"""
import re
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import peri_preamble

DX = 1.0e-3
DENSITY = 2200.0
C_PMB = 1.6863e22 * (0.5e-3 / DX) ** 4    # peri/pmb example's c, scaled to this spacing
DELTA = 3.0002 * DX    # as the example: 1.5001 mm at lc = 0.5 mm; xi = 3 dx gets the ramp
S00_ELASTIC = 0.5      # nothing breaks under the perturbation below
ALPHA = 0.25
PERTURBATION = 1.0e-3    # of dx, random on every atom
PUSH = 0.15              # of dx: pushed atoms come within 0.85 dx < 0.9 dx of a neighbour
FORCE_RTOL = 1.0e-12     # of the largest force: different summation order only
SEED = 20261201


THICKNESS = 1.0e-3    # of the 2D plate


def block(dim=3, periodic=False):
    """The reference lattice and its box: padded, or (periodic) one period of the lattice,
    so that every atom has bonds across the boundary."""
    x0 = refmodel.square_lattice((7, 7, 7) if dim == 3 else (12, 12), DX)
    pad = 0.5 * DX if periodic else 5 * DX
    box = [(x0[:, k].min() - pad, x0[:, k].max() + pad) for k in range(3)]
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    return x0, box


def perturbed(x0, dim=3):
    """Random perturbation; three atoms pushed towards their +x neighbour."""
    rng = np.random.default_rng(SEED)
    y = x0 + PERTURBATION * DX * rng.uniform(-1.0, 1.0, x0.shape)
    if dim == 3:
        pushed = [3 * 49 + 3 * 7 + 2, 1 * 49 + 5 * 7 + 4, 5 * 49 + 1 * 7 + 1]    # interior-ish atoms
    else:
        y[:, 2] = 0.0
        pushed = [5 * 12 + 5, 2 * 12 + 8, 8 * 12 + 3]
    for a in pushed:
        y[a, 0] += PUSH * DX
    return y


def short_range_pairs(x0, y):
    """Pairs closer than min(0.9 |xi|, 1.35 lc) (peri/pmb's short-range rule)."""
    i, j = np.triu_indices(len(x0), 1)
    xi = np.linalg.norm(x0[j] - x0[i], axis=1)
    r = np.linalg.norm(y[j] - y[i], axis=1)
    return np.count_nonzero(r < np.minimum(0.9 * xi, 1.35 * DX))


def force_script(pair_lines, plugin, dim=3, boundary="s s s"):
    return (peri_preamble(dim, boundary if dim == 3 else None, data="body.data",
                          lattice=f"{'sc' if dim == 3 else 'sq'} {DX!r}", plugin=plugin)
            + pair_lines +
            "neighbor 0.0005 bin\n"
            "run 0\n"
            f"read_dump current.dump 0 {'x y z' if dim == 3 else 'x y'} box no replace yes\n"
            "run 0\n"
            "write_dump all custom forces.dump id x y z fx fy fz modify format float %.17g\n")


def run_forces(lmp, tmp_path, pair_lines, plugin, nprocs=1, dim=3, boundary="s s s"):
    out = lmp(force_script(pair_lines, plugin, dim, boundary), nprocs=nprocs).output
    got = ref.read_dump(tmp_path / "forces.dump")
    return out, np.stack([got["fx"], got["fy"], got["fz"]], axis=1)


@pytest.mark.parametrize("model", ["3d", "plane/stress", "3d-periodic"])
def test_forces_equal_peri_pmb(lmp, tmp_path, model):
    """bbpd/pmb gives peri/pmb's forces (bonds with the volume ramp, short-range forces
    between bonded atoms) to 1e-12 of the largest force, on 1 and 2 ranks; ours are the
    same bits on 1 and 2 ranks. In 2D, peri/pmb runs in dimension 2 as well. 3d-periodic:
    a periodic box one lattice period long, every atom bonded across the boundaries."""
    periodic = model == "3d-periodic"
    model = "3d" if periodic else model
    boundary = "p p p" if periodic else "s s s"
    dim = 3 if model == "3d" else 2
    x0, box = block(dim, periodic)
    y = perturbed(x0, dim)
    assert short_range_pairs(x0, y) >= 3    # the short-range force is exercised
    refmodel.write_data(tmp_path / "body.data", x0, DX**3 if dim == 3 else THICKNESS * DX**2,
                   DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    numbers = f"{C_PMB!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"

    _, f_pmb = run_forces(lmp, tmp_path, f"pair_style peri/pmb\npair_coeff * * {numbers}\n",
                          plugin=False, dim=dim, boundary=boundary)
    thick = "" if dim == 3 else f" thickness {THICKNESS!r}"
    ours = f"pair_style bbpd/pmb {model}{thick}\npair_coeff * * {numbers}\n"
    out1, f1 = run_forces(lmp, tmp_path, ours, plugin=True, dim=dim, boundary=boundary)
    out2, f2 = run_forces(lmp, tmp_path, ours, plugin=True, nprocs=2, dim=dim, boundary=boundary)
    assert "BBPD pair style bbpd/pmb" in out1 and "peri/pmb rules" in out1
    # |xi| <= delta gives an interior atom 122 partners (3D), 28 (2D) at delta = 3.0002 dx
    assert f"max {122 if dim == 3 else 28}" in out1
    if periodic:    # every atom is interior
        assert "min 122 mean 122 max 122" in out1
    scale = np.linalg.norm(f_pmb, axis=1).max()
    for f in (f1, f2):
        err = np.linalg.norm(f - f_pmb, axis=1).max() / scale
        print(f"max per-atom force difference to peri/pmb: {err:.3g} of the largest force")
        assert err < FORCE_RTOL, f"max per-atom force error {err:.3g} of the largest force"
    np.testing.assert_array_equal(f1, f2)


def test_short_range_force_is_needed(lmp, tmp_path):
    """The same comparison fails without the short-range force (the test can fail)."""
    x0, box = block()
    y = perturbed(x0)
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    numbers = f"{C_PMB!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"
    _, f_pmb = run_forces(lmp, tmp_path, f"pair_style peri/pmb\npair_coeff * * {numbers}\n",
                          plugin=False)
    # plain bbpd/constant with c and the same bonds: no short-range force, other volumes
    _, f_plain = run_forces(lmp, tmp_path,
                            "pair_style bbpd/constant 3d\n"
                            f"pair_coeff * * 1.0e9 none {DELTA!r}\n", plugin=True)
    scale = np.linalg.norm(f_pmb, axis=1).max()
    assert np.linalg.norm(f_plain - f_pmb, axis=1).max() / scale > 1e-3


# ---------------------------------------------------------------------------
# alpha: two atoms, one bond; each 'run 1' is one new force evaluation (and breaking check)

PAIR_XI = 1.0e-3
S00 = 1.0e-3


def bond_script(pair_lines, stretches, lattice=True):
    """The two-atom script of bond_history()"""
    lines = [peri_preamble(3, "f f f").rstrip("\n"), "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box",
             "create_box 1 box", "create_atoms 1 single 0 0 0 units box",
             f"create_atoms 1 single {PAIR_XI!r} 0 0 units box",
             f"set group all volume {PAIR_XI**3!r}", f"set group all density {DENSITY!r}"]
    if lattice:
        lines.append(f"lattice sc {PAIR_XI!r}")
    # no integrator: 'run 1' evaluates the forces at the atoms' positions (the setup of a run
    # only repeats the last step's evaluation, which neither breaks bonds nor updates smin)
    lines += pair_lines.splitlines() + ["run 1"]
    for s in stretches:
        lines += [f"set atom 2 x {PAIR_XI * (1.0 + s)!r}", "run 1"]
    lines.append("run 1")
    return "\n".join(lines) + "\n"


def bond_history(lmp, pair_lines, stretches, lattice=True):
    """Put the bond at each stretch in turn (one force evaluation each); return the number
    of broken bonds after the first evaluation (stretch 0) and after each stretch."""
    out = lmp(bond_script(pair_lines, stretches, lattice)).output
    # each setup reports the bonds left by the evaluations before it
    return [int(v) for v in re.findall(r"total bonds 1 \((\d) broken\)", out)][1:]


@pytest.mark.parametrize("style", ["plain", "compat"])
def test_alpha_compression_then_tension(lmp, style):
    """A bond compressed at one step survives, at the next, a stretch that breaks it with
    alpha = 0: its critical stretch is s00 - alpha * (-0.01) there."""
    stretch = 1.002 * S00    # above s00, below s00 + 0.25 * 0.01
    def pair(a):
        if style == "compat":
            return f"pair_style bbpd/pmb 3d\npair_coeff * * 1.0e20 0.0015 {S00!r} {a!r}"
        return ("pair_style bbpd/constant/alpha 3d\n"
                f"pair_coeff * * 1.0e9 none 0.0015 critical_stretch {S00!r} alpha {a!r}")
    # alpha = 0: it breaks at once
    assert bond_history(lmp, pair(0.0), [-0.01, stretch]) == [0, 0, 1]
    # alpha = 0.25: it survives, and breaks one step later (compression forgotten)
    assert bond_history(lmp, pair(ALPHA), [-0.01, stretch, stretch]) == [0, 0, 0, 1]
    # without the compression it breaks with alpha too
    assert bond_history(lmp, pair(ALPHA), [0.0, stretch]) == [0, 0, 1]


def test_alpha_tension_rule_differs(lmp):
    """peri/pmb's rule lowers s0 after tension (s0 = s00 - alpha * smin, smin > 0); the
    bbpd alpha keyword counts compression only. A bond at 0.9 s00 then 0.98 s00 breaks
    under bbpd/pmb and survives with the keyword."""
    hist = [0.9 * S00, 0.98 * S00]
    compat = bond_history(lmp, "pair_style bbpd/pmb 3d\n"
                          f"pair_coeff * * 1.0e20 0.0015 {S00!r} {ALPHA!r}", hist)
    plain = bond_history(lmp, "pair_style bbpd/constant/alpha 3d\n"
                         f"pair_coeff * * 1.0e9 none 0.0015 critical_stretch {S00!r} alpha {ALPHA!r}",
                         hist)
    assert compat == [0, 0, 1]
    assert plain == [0, 0, 0]


def test_alpha_style_without_alpha_warns(lmp):
    """bbpd/KERNEL/alpha with alpha 0 for every type pair runs the Silling-Askari loop for the
    plain rule: a WARNING names the faster style; with alpha > 0 there is none."""
    warning = "alpha is 0 for every type pair"
    for a, warns in ((0.0, True), (ALPHA, False)):
        out = lmp(bond_script("pair_style bbpd/constant/alpha 3d\n"
                              f"pair_coeff * * 1.0e9 none 0.0015 critical_stretch {S00!r} alpha {a!r}",
                              [0.0])).output
        assert (warning in out) == warns, out[-2000:]
        assert "Silling-Askari critical stretch" in out


def test_compat_needs_lattice(lmp):
    proc = lmp("plugin load bbpdplugin.so\nunits si\nboundary f f f\natom_style peri\n"
               "atom_modify map array\nregion box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box\n"
               "create_box 1 box\ncreate_atoms 1 single 0 0 0 units box\n"
               "set group all volume 1e-9\nset group all density 1000\n"
               "pair_style bbpd/pmb 3d\npair_coeff * * 1e20 0.0015 0.001 0.25\n"
               "run 0\n", check=False)
    assert "needs a lattice command" in proc.error


EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "peri-pmb-dropin" / "in.bbpd.pmb"
# the cylinder's material for the kernel models: E = pi c delta^4 / 12 (doc/migrating_from_peri)
PLAIN_ALPHA = ("pair_style      bbpd/gaussian/alpha 3d contact yes\n"
               "pair_coeff      * * 22.355e9 5.0 0.0015001 alpha 0.25\n")
# a second atom type that no atom has, with another s00: the per-bond (multi-type) loop
TWO_TYPES = ("pair_coeff      * * 1.6863e22 0.0015001 0.0005 0.25\n"
             "pair_coeff      2 2 1.6863e22 0.0015001 0.001 0.25\n")


def cylinder(variant, steps=300):
    script = EXAMPLE.read_text().replace("variable        steps index 1000",
                                         f"variable        steps index {steps}")
    script = script.replace("variable        scale index 1", "variable        scale index 0.6")
    pmb_lines = ("pair_style      bbpd/pmb 3d\n"
                 "pair_coeff      * * 1.6863e22 0.0015001 0.0005 0.25\n")
    assert pmb_lines in script
    if variant == "plain-alpha":
        script = script.replace(pmb_lines, PLAIN_ALPHA)
    elif variant == "compact":
        script = script.replace("bbpd/pmb 3d\n", "bbpd/pmb 3d bond/storage compact\n", 1)
    elif variant == "two-types":
        script = script.replace("create_box      1 target", "create_box      2 target")
        script = script.replace(pmb_lines, pmb_lines.splitlines()[0] + "\n" + TWO_TYPES)
    return script


def test_per_bond_loop_gives_the_same_bits(lmp, tmp_path):
    """The per-bond loop (type pairs with different s00; compact bond storage) gives the
    bits of the one-type SIMD loop when every atom has the same type."""
    states = []
    for variant in ("compat", "two-types", "compact"):
        lmp(cylinder(variant) + "write_dump all custom end.dump id x y z vx vy vz c_1 "
            "modify format float %.17g\n")
        states.append(ref.read_dump(tmp_path / "end.dump"))
    assert states[0]["c_1"].mean() > 0.1
    for other in states[1:]:
        for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
            np.testing.assert_array_equal(states[0][key], other[key])


def test_cylinder_bitwise_on_1_and_2_threads(lmp, tmp_path):
    """bbpd/pmb on 2 OpenMP threads ends in the bits of 1 thread."""
    states = []
    for threads in (1, 2):
        script = cylinder("compat").replace("units           si",
                                            f"package omp {threads}\nunits           si", 1)
        out = lmp(script + "write_dump all custom end.dump id x y z vx vy vz c_1 "
                  "modify format float %.17g\n").output
        assert f"1 MPI tasks x {threads} OpenMP threads" in out
        states.append(ref.read_dump(tmp_path / "end.dump"))
    for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
        np.testing.assert_array_equal(states[0][key], states[1][key])


@pytest.mark.parametrize("variant", ["compat", "plain-alpha"])
def test_cylinder_bitwise_on_1_and_2_ranks(lmp, tmp_path, variant):
    """The ported peri/pmb cylinder (smaller, shattering: short-range forces or contact, and
    breaking with alpha on every step) ends in the same bits on 1 and 2 MPI ranks."""
    script = cylinder(variant)
    states = []
    for nprocs in (1, 2):
        out = lmp(script + f"write_dump all custom end{nprocs}.dump id x y z vx vy vz c_1 "
                  "modify format float %.17g\n", nprocs=nprocs).output
        assert ref.thermo_tables(out)[-1]["c_dmean"][-1] > 0.1    # bonds broke
        states.append(ref.read_dump(tmp_path / f"end{nprocs}.dump"))
    for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
        np.testing.assert_array_equal(states[0][key], states[1][key])


def test_cylinder_restart_equals_continuous_run(lmp, tmp_path):
    """bbpd/pmb across write_restart/read_restart (new process): the smallest stretches
    (per-atom s0), compat and alpha come back, and the run continues in the same bits."""
    script = EXAMPLE.read_text().replace("variable        scale index 1",
                                         "variable        scale index 0.6")
    head, tail = script.split("fix             1 all nve", 1)
    dump = ("write_dump all custom end.dump id x y z vx vy vz c_1 modify format float %.17g\n")
    lmp(script.replace("variable        steps index 1000", "variable        steps index 300")
        + dump)
    straight = ref.read_dump(tmp_path / "end.dump")
    lmp(script.replace("variable        steps index 1000", "variable        steps index 150")
        + "write_restart state.restart\n")
    # a new process: the plugin, the lattice (bbpd/pmb needs it, as peri/pmb), the fixes
    second = ("plugin load bbpdplugin.so\nread_restart state.restart\nneighbor 0.0010 bin\n"
              "lattice sc 0.0005\nvariable steps index 150\nfix 1 all nve" + tail + dump)
    lmp(second)
    restarted = ref.read_dump(tmp_path / "end.dump")
    assert straight["c_1"].mean() > 0.1
    for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
        np.testing.assert_array_equal(straight[key], restarted[key])


def test_cylinder_atom_sorting_gives_the_same_bits(lmp, tmp_path):
    """LAMMPS sorting the atoms (new local indices at a reneighboring) rebuilds the bond cache
    and the short-range candidates; without sorting both are kept from one reneighboring to
    the next. Either way the run ends in the same bits, with and without bbpd/pmb."""
    for variant in ("compat", "plain-alpha"):
        states = []
        for sort in ("atom_modify     sort 0 0.0", "atom_modify     sort 10 0.0005"):
            script = cylinder(variant).replace("atom_modify     map array",
                                               "atom_modify     map array\n" + sort)
            lmp(script + "write_dump all custom end.dump id x y z vx vy vz c_1 "
                "modify sort id format float %.17g\n")
            states.append(ref.read_dump(tmp_path / "end.dump"))
        assert states[0]["c_1"].mean() > 0.1
        for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
            np.testing.assert_array_equal(states[0][key], states[1][key])


def periodic_cylinder(style):
    """The smaller cylinder in a box periodic in x and z (its bounding box): the atoms at the
    rim where the cylinder touches the box faces are bonded across the boundary."""
    script = cylinder("compat").replace("boundary        s s s", "boundary        p s p")
    if style == "peri/pmb":
        script = script.replace("plugin load     bbpdplugin.so\n", "")
        script = script.replace("pair_style      bbpd/pmb 3d", "pair_style      peri/pmb")
        script = script.replace("bbpd/damage/atom", "damage/atom")
    return script


def test_periodic_cylinder_follows_peri_pmb(lmp, tmp_path):
    """bbpd/pmb in a periodic box: the same damage as peri/pmb at every thermo step, and the
    same bits on 1 and 2 ranks (every bond breaks at both ends at once)."""
    tables, states = [], []
    for style, nprocs in (("peri/pmb", 1), ("compat", 1), ("compat", 2)):
        out = lmp(periodic_cylinder(style) + "write_dump all custom end.dump id x y z vx vy vz "
                  "c_1 modify sort id format float %.17g\n", nprocs=nprocs).output
        assert "Periodic" not in out
        tables.append(ref.thermo_tables(out)[-1])
        states.append(ref.read_dump(tmp_path / "end.dump"))
    assert tables[0]["c_dmean"][-1] > 0.1
    np.testing.assert_allclose(tables[1]["c_dmean"], tables[0]["c_dmean"], rtol=0.02)
    for key in ("x", "y", "z", "vx", "vy", "vz", "c_1"):
        np.testing.assert_array_equal(states[1][key], states[2][key])
