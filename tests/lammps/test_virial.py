"""Global virial and pressure of the bbpd/* pair styles against the NumPy reference.

compute pressure NULL virial gives P_ab = sum_i W_i,ab / V_box (area in 2D), with W_i the
per-atom virial 1/2 sum_j (y_i - y_j) (x) f_ij of python/bbpd/reference.py. Under a uniform
stretch every bond pulls: the pressure is negative (tension) in the stretched direction, so a
sign flip, a missing factor 1/2 or a virial of one bond end only fails. Each force-loop variant
tallies the virial on its own: the SIMD kernel (default storage), the portable loop (compact
storage) and the per-type-pair s0 loop (two types), on 1 and 2 ranks.
"""
import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import EXAMPLES, peri_preamble

DX = 1.0e-3
THICKNESS = 1.0e-3
DELTA = 3.05 * DX
STRETCH = (1.0e-4, -0.4e-4, 0.7e-4)    # strain along x, y, z
SHEAR = 0.3e-4                         # y += SHEAR x
RTOL = 1.0e-11                         # of the largest component: summation order only


def body(dim):
    shape = (12, 10) if dim == 2 else (7, 6, 5)
    x0 = refmodel.square_lattice(shape, DX)
    pad = 4 * DX
    box = [(x0[:, k].min() - pad, x0[:, k].max() + pad) for k in range(3)]
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    y = x0.copy()
    for k in range(dim):
        y[:, k] *= 1.0 + STRETCH[k]
    y[:, 1] += SHEAR * x0[:, 0]
    return x0, y, box


@pytest.mark.parametrize("model,variant,nprocs", [
    ("plane/strain", "fast", 1), ("plane/strain", "compact", 1),
    ("plane/strain", "types", 1), ("plane/strain", "fast", 2), ("3d", "fast", 1),
    ("3d", "types", 2)])
def test_pressure_matches_reference(lmp, tmp_path, model, variant, nprocs):
    dim = ref.DIMENSION[model]
    x0, y, box = body(dim)
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    types = np.ones(len(x0), dtype=int)
    if variant == "types":
        types[x0[:, 0] > 4.5 * DX] = 2
    refmodel.write_data(tmp_path / "body.data", x0, volume, 8000.0, box, types=types)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    thick = f" thickness {THICKNESS!r}" if dim == 2 else ""
    storage = " bond/storage compact" if variant == "compact" else ""
    coeffs = f"pair_coeff * * 200e9 none {DELTA!r}\n"
    if variant == "types":
        # same material, a different (never reached) s0 per pair: the per-pair-s0 loop
        coeffs = "".join(f"pair_coeff {a} {b} 200e9 none {DELTA!r} critical_stretch {s!r}\n"
                         for a, b, s in ((1, 1, 0.1), (1, 2, 0.2), (2, 2, 0.3)))
    coords = "x y z" if dim == 3 else "x y"
    boundary = "f f p" if dim == 2 else "f f f"    # fixed: the box volume is known
    script = (peri_preamble(dim, boundary, data="body.data") +
              f"pair_style bbpd/gaussian {model}{thick}{storage}\n" + coeffs
              + "compute p all pressure NULL virial\n"
              "thermo_style custom step press c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6]\n"
              "thermo_modify format float %.17g\n"
              "run 0\n"
              f"read_dump current.dump 0 {coords} box no replace yes\n"
              "run 0\n")
    out = lmp(script, nprocs=nprocs).output
    c0 = ref.micromodulus("gaussian", model, 200e9, DELTA, THICKNESS if dim == 2 else 1.0)
    bonds = refmodel.Bonds(x0, volume, "gaussian", c0, DELTA, DX)
    virial = bonds.virial_density(y).sum(axis=0)
    size = 1.0
    for k in range(dim):
        size *= box[k][1] - box[k][0]
    expected = virial / size
    table = ref.thermo_tables(out)[-1]
    got = np.array([table[f"c_p[{k}]"][-1] for k in range(1, 7)])
    scale = np.abs(expected).max()
    np.testing.assert_allclose(got, expected, rtol=0, atol=RTOL * scale)
    assert table["Press"][-1] == pytest.approx(expected[:dim].sum() / dim, rel=1e-10,
                                               abs=RTOL * scale)
    assert expected[0] < 0.0    # tension along the largest stretch
    assert abs(expected[3]) > 1e-3 * scale    # the shear component is tested too


# The virial from the rows' forces, sum_i x_i (x) f_i over the ranks, where the two rows of every
# bond give it opposite forces (no periodic boundary, one type and volume on every rank:
# PairBBPD::row_tally), against the bonds' own tallies, which compute stress/atom asks for at its
# steps: LAMMPS's cylinder shattered by its indenter, whose variable position asks for the virial
# at every step, on one rank and on two (bonds between ranks). Bonds break, the short-range
# forces act, and the forces of the bonds breaking in a step count in it.
ROW_VIRIAL_RTOL = 1.0e-12    # of the largest component: round-off of x_i (x) f_i (found 6e-14)
CYLINDER_KERNEL = """pair_style      bbpd/gaussian 3d
pair_coeff      * * 72e9 3.8 0.0015001
"""


@pytest.mark.parametrize("model,nprocs", [("pmb", 1), ("lps", 1), ("gaussian", 1), ("pmb", 2), ("lps", 2)])
def test_virial_from_row_forces_matches_bond_tallies(lmp, model, nprocs):
    script = (EXAMPLES / f"peri-{'lps' if model == 'lps' else 'pmb'}-dropin" /
              f"in.bbpd.{'lps' if model == 'lps' else 'pmb'}").read_text()
    if model == "gaussian":
        script = script.replace("pair_style      bbpd/pmb 3d\n", "").replace(
            "pair_coeff      * * 1.6863e22 0.0015001 0.0005 0.25\n", CYLINDER_KERNEL)
        assert "bbpd/gaussian 3d" in script and "bbpd/pmb 3d" not in script
    components = " ".join(f"c_p[{k}]" for k in range(1, 7))
    thermo = ("compute p all pressure NULL virial\n"
              f"thermo_style custom step ke c_dmean {components}{{}}\n"
              "thermo_modify format float %.17g\nthermo 50\n")
    tallies = ("compute sa all stress/atom NULL virial\n"
               "compute ssum all reduce sum c_sa[1]\n")
    tables = {}
    for name, extra, column in (("rows", "", ""), ("bonds", tallies, " c_ssum")):
        text = script.replace("run             ${steps}", extra + thermo.format(column) + "run ${steps}")
        out = lmp(text, vars={"scale": 0.6, "steps": 300}, nprocs=nprocs).output
        tables[name] = ref.thermo_tables(out)[-1]
    rows, bonds = tables["rows"], tables["bonds"]
    np.testing.assert_array_equal(rows["KinEng"], bonds["KinEng"])    # the virial does not act
    assert bonds["c_dmean"][-1] > 0.01          # bonds broke
    got = np.array([rows[f"c_p[{k}]"] for k in range(1, 7)]).T
    want = np.array([bonds[f"c_p[{k}]"] for k in range(1, 7)]).T
    for g, w in zip(got[1:], want[1:]):    # step 0: at rest, no force
        np.testing.assert_allclose(g, w, rtol=0, atol=ROW_VIRIAL_RTOL * np.abs(w).max())
    # the rows' sum is another summation than the bonds': were it the same, it would not be tested
    assert np.any(got != want)


def test_ranks_take_the_bonds_tally_together_where_one_rank_sees_another_volume(lmp):
    """Two ranks, each of whose atoms have one volume, the two volumes differing: a bond between
    the ranks gets unequal forces at its two ends, so neither rank may take the virial from its
    rows' forces although each sees a single volume. Both runs then tally the bonds, and the
    global virial is the same to the bit with compute stress/atom and without."""
    script = (EXAMPLES / "peri-pmb-dropin" / "in.bbpd.pmb").read_text()
    script = script.replace("lattice         sc", "processors      2 1 1\nlattice         sc")
    script = script.replace("set             group all volume 1.25e-10\n",
                            "set             group all volume 1.25e-10\n"
                            # the right half, the second rank's (the box is split at x = 0)
                            "region          right block 0.0 INF INF INF INF INF units box\n"
                            "set             region right volume 1.0e-10\n")
    components = " ".join(f"c_p[{k}]" for k in range(1, 7))
    thermo = ("compute p all pressure NULL virial\n"
              f"thermo_style custom step ke c_dmean {components}\n"
              "thermo_modify format float %.17g\nthermo 50\n")
    tallies = "compute sa all stress/atom NULL virial\n"
    tables = {}
    for name, extra in (("rows", ""), ("bonds", tallies)):
        text = script.replace("run             ${steps}", extra + thermo + "run ${steps}")
        assert text.count("processors") == 1 and text.count("region right") == 1
        tables[name] = ref.thermo_tables(lmp(text, vars={"scale": 0.6, "steps": 200}, nprocs=2).output)[-1]
    rows, bonds = tables["rows"], tables["bonds"]
    assert bonds["c_dmean"][-1] > 0.001
    for k in range(1, 7):
        np.testing.assert_array_equal(rows[f"c_p[{k}]"], bonds[f"c_p[{k}]"])
    assert np.abs(bonds["c_p[2]"]).max() > 0.0


@pytest.mark.parametrize("model,nprocs", [("pmb", 2), ("lps", 2), ("ves", 2), ("pmb", 1)])
def test_a_second_evaluation_of_a_step_has_its_virial(lmp, model, nprocs):
    """`run 0` after a run evaluates its last step again, and re-applies the forces of the bonds
    that broke in it (they act in the step they break, as in peri/*): its virial is the one
    the run's last step had, with those bonds' (W = P V, the box shrink-wrapped again), on two
    ranks (the bonds' tally) and on one (the rows' forces)"""
    script = (EXAMPLES / f"peri-{model}-dropin" / f"in.bbpd.{model}").read_text()
    components = " ".join(f"v_w{k}" for k in range(1, 7))
    thermo = ("compute p all pressure NULL virial\n" +
              "".join(f"variable w{k} equal c_p[{k}]*vol\n" for k in range(1, 7)) +
              f"thermo_style custom step c_dmean {components}\n"
              "thermo_modify format float %.17g\n")
    text = script.replace("run             ${steps}", thermo + "run ${steps}\nrun 0\n")
    out = lmp(text, nprocs=nprocs, vars={"scale": 0.6, "steps": 300}).output
    run, again = ref.thermo_tables(out)[-2:]
    assert run["Step"][-1] == again["Step"][0] == 300
    assert run["c_dmean"][-1] > 0.01    # bonds broke, some of them in the last step (below)
    w_run = np.array([run[f"v_w{k}"][-1] for k in range(1, 7)])
    w_again = np.array([again[f"v_w{k}"][0] for k in range(1, 7)])
    np.testing.assert_allclose(w_again, w_run, rtol=0, atol=1e-9 * np.abs(w_run).max())
