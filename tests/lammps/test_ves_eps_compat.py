"""'pair_style bbpd/ves 3d' and 'bbpd/eps 3d' against LAMMPS's own peri/ves and peri/eps.

The loading history: the perturbed 3D block of test_pmb_compat.py (reference lattice from a
data file at %.17g; three atoms pushed towards a neighbour so that the short-range force acts)
is moved by 'fix move variable' through a prescribed deformation (shear growing with time, a
stretch and a wave through the block, all smooth functions of the atoms' starting positions
and of time) for STEPS steps. The positions are the same doubles for every style and rank
count (they do not depend on the forces), so only the history of the bonds decides whether
the forces agree after STEPS steps. The two styles sum in different orders, so they agree to
round-off, not bitwise; ours are the same bits on 1, 2 and 4 ranks.

How much the history matters is measured, not assumed: the same run with the history switched
off (VES: lambda = 0, the elastic part alone; EPS: a yield stress that is never reached) gives
forces that differ by VISCOUS_SHARE_MIN / PLASTIC_SHARE_MIN of the largest force or more.
"""
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from test_bad_input import BASE_3D, check_error_exit, run_case, script
from test_lps_compat import END_DUMP, KEYS, end_state
from test_pmb_compat import DELTA, DENSITY, DX, block, perturbed, short_range_pairs
from scenes import peri_preamble

BULK = 14.9e9       # the peri/ves and peri/eps examples' K and G
SHEAR = 14.9e9
S00_ELASTIC = 0.5   # nothing breaks under this loading
ALPHA = 0.25
DT = 1.0e-7
STEPS = 200
TAU = 20 * DT       # relaxation time: 20 steps, so that the back extension moves in the run
LAMBDA = 0.5
YIELD = 1.0e8       # reached from the first step on (by every atom: lambda > 0 at the end)
NEVER = 1.0e30      # a yield stress never reached
FORCE_RTOL = 1.0e-12    # of the largest force: different summation order only
VISCOUS_SHARE_MIN = 0.05    # the history changes the forces by at least this much
PLASTIC_SHARE_MIN = 0.05
ENERGY = "thermo_style custom step pe\nthermo_modify format float %.17g\n"
# the deformation: shear g(t) (y -> x), stretch a(t) along y, a wave along z
LOADING = f"""timestep {DT!r}
fix S all store/state 0 x y z
variable t equal step/{STEPS}
variable g equal 4.0e-3*v_t+1.0e-3*sin(6.283185307179586*3*v_t)
variable a equal 1.0e-3*v_t
variable dx atom v_g*(f_S[2]-0.003)
variable dy atom v_a*(f_S[2]-0.003)
variable dz atom 2.0e-6*v_t*sin(f_S[1]*1000.0)
fix M all move variable v_dx v_dy v_dz NULL NULL NULL
thermo {STEPS}
"""


def coeffs(family, history=True):
    numbers = f"{BULK!r} {SHEAR!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"
    if family == "ves":
        return f"{numbers} {LAMBDA if history else 0.0!r} {TAU!r}"
    return f"{numbers} {YIELD if history else NEVER!r}"


def loaded_forces(lmp, tmp_path, pair_lines, plugin, nprocs=1, family="ves"):
    """forces and energy after STEPS steps of the loading, and the per-atom dilatation and
    (EPS) plastic multiplier of compute [bbpd/]dilatation/atom and [bbpd/]plasticity/atom"""
    prefix = "bbpd/" if plugin else ""
    computes = f"compute theta all {prefix}dilatation/atom\n"
    columns = "fx fy fz c_theta"
    if family == "eps":
        computes += f"compute lambda all {prefix}plasticity/atom\n"
        columns += " c_lambda"
    script_text = (peri_preamble(3, "s s s", data="body.data", lattice=f"sc {DX!r}", plugin=plugin)
                   + pair_lines + computes + "neighbor 0.0005 bin\nrun 0\n"
                   "read_dump current.dump 0 x y z box no replace yes\n"
                   # a new step: peri/* advance the history at every evaluation, bbpd/* once a step
                   "reset_timestep 1\n" + LOADING + ENERGY
                   + f"run {STEPS}\n"
                   f"write_dump all custom forces.dump id {columns} modify sort id format float %.17g\n")
    out = lmp(script_text, nprocs=nprocs).output
    got = ref.read_dump(tmp_path / "forces.dump")
    per_atom = {key: np.asarray(got[key]) for key in ("c_theta", "c_lambda") if key in got}
    return out, np.stack([got["fx"], got["fy"], got["fz"]], axis=1), per_atom


def pe_of(out):
    return ref.thermo_tables(out)[-1]["PotEng"][-1]


@pytest.fixture
def block_files(tmp_path):
    x0, box = block(3)
    y = perturbed(x0, 3)
    assert short_range_pairs(x0, y) >= 3    # the short-range force is exercised
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    return tmp_path


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_forces_and_energy_equal_peri(lmp, block_files, family):
    """bbpd/ves and bbpd/eps give peri/ves's and peri/eps's forces to 1e-12 of the largest force
    and their energy to 1e-12 after STEPS steps of loading, on 1, 2 and 4 ranks (ours: the
    same bits on every rank count); the history changes the forces by more than 5 % of the
    largest force (printed: its share)."""
    tmp_path = block_files
    out_peri, f_peri, atoms_peri = loaded_forces(lmp, tmp_path, f"pair_style peri/{family}\n"
                                                 f"pair_coeff * * {coeffs(family)}\n",
                                                 plugin=False, family=family)
    ours = f"pair_style bbpd/{family} 3d\npair_coeff * * {coeffs(family)}\n"
    results = [loaded_forces(lmp, tmp_path, ours, plugin=True, nprocs=n, family=family)
               for n in (1, 2, 4)]
    assert f"BBPD pair style bbpd/{family}" in results[0][0]
    assert f"peri/{family} history" in results[0][0]
    scale = np.linalg.norm(f_peri, axis=1).max()
    assert scale > 0.0
    for out, f, atoms in results:
        # compute bbpd/dilatation/atom and bbpd/plasticity/atom give LAMMPS's computes' values
        for key, ref_values in atoms_peri.items():
            assert np.abs(ref_values).max() > 0.0
            diff = np.abs(atoms[key] - ref_values).max() / np.abs(ref_values).max()
            print(f"{family}: {key} differs from LAMMPS's compute by {diff:.3g} of its largest value")
            assert diff < FORCE_RTOL
        if family == "eps":    # every atom has yielded
            assert np.all(atoms["c_lambda"] > 0.0)
        err = np.linalg.norm(f - f_peri, axis=1).max() / scale
        e_ref, e = pe_of(out_peri), pe_of(out)
        print(f"{family}: max per-atom force difference to peri/{family} {err:.3g} of the "
              f"largest force; energy peri {e_ref!r}, ours {e!r} ({abs(e - e_ref) / abs(e_ref):.3g})")
        assert err < FORCE_RTOL
        assert abs(e - e_ref) <= FORCE_RTOL * abs(e_ref)
    for _, f, atoms in results[1:]:
        np.testing.assert_array_equal(results[0][1], f)
        for key, values in atoms.items():
            np.testing.assert_array_equal(results[0][2][key], values)
    # the history matters: without it the forces are far from these
    _, f_plain, _ = loaded_forces(lmp, tmp_path, f"pair_style bbpd/{family} 3d\n"
                                  f"pair_coeff * * {coeffs(family, history=False)}\n", plugin=True,
                                  family=family)
    share = np.linalg.norm(f_plain - results[0][1], axis=1).max() / scale
    print(f"{family}: the {'viscous' if family == 'ves' else 'plastic'} part is {share:.3g} "
          "of the largest force")
    assert share > (VISCOUS_SHARE_MIN if family == "ves" else PLASTIC_SHARE_MIN)


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_two_types_equal_peri(lmp, tmp_path, family):
    """Two types with their own K, G and lambda, tau or Y (atom i's type decides its bonds'
    force state, as in peri/ves and peri/eps): forces equal to 1e-12 after the loading. No
    atom is pushed here: for a pair of atoms of different types closer than the short-range
    distance peri/* takes the K of the atom its half neighbour list lists first, bbpd/* each
    atom's own (doc/pair_bbpd_ves_eps.rst)."""
    x0, box = block(3)
    rng = np.random.default_rng(20261206)
    y = x0 + 1.0e-3 * DX * rng.uniform(-1.0, 1.0, x0.shape)
    assert short_range_pairs(x0, y) == 0
    types = np.where(x0[:, 0] > x0[:, 0].mean(), 2, 1)
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box, types=types)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    base = f"{BULK!r} {SHEAR!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"
    other = f"{2 * BULK!r} {0.5 * SHEAR!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"
    own = {"ves": (f"{LAMBDA} {TAU!r}", f"0.8 {3 * TAU!r}"), "eps": (f"{YIELD}", f"{3 * YIELD}")}[family]
    lines = (f"pair_coeff 1 1 {base} {own[0]}\npair_coeff 2 2 {other} {own[1]}\n"
             f"pair_coeff 1 2 {base} {own[0]}\n")
    _, f_peri, _ = loaded_forces(lmp, tmp_path, f"pair_style peri/{family}\n" + lines, plugin=False,
                                 family=family)
    _, f, _ = loaded_forces(lmp, tmp_path, f"pair_style bbpd/{family} 3d\n" + lines, plugin=True,
                            family=family)
    err = np.linalg.norm(f - f_peri, axis=1).max() / np.linalg.norm(f_peri, axis=1).max()
    print(f"{family}, two types: {err:.3g} of the largest force")
    assert err < FORCE_RTOL


EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def cylinder(family, steps=300, scale=0.6):
    """The ported example (examples/peri-FAMILY-dropin), smaller and shorter; its history
    relaxes within the run (VES: tau of 20 steps) and dumps the starting positions."""
    script_text = (EXAMPLES / f"peri-{family}-dropin" / f"in.bbpd.{family}").read_text()
    for name, value in (("steps", steps), ("scale", scale)):
        line = next(l for l in script_text.splitlines() if l.startswith(f"variable        {name} index"))
        script_text = script_text.replace(line, f"variable        {name} index {value}")
    if family == "ves":
        script_text = script_text.replace("0.25 0.5 0.001", f"0.25 0.5 {TAU!r}")
    return script_text.replace("run             ${steps}", "write_dump all custom start.dump id x y z "
                               "modify sort id format float %.17g\nrun             ${steps}")


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_cylinder_bitwise_on_1_2_4_ranks(lmp, tmp_path, family):
    """The ported cylinder (smaller, shattering: bonds break, atoms migrate between ranks with
    their bonds' history) ends in the same bits on 1, 2 and 4 MPI ranks."""
    states = []
    for nprocs in (1, 2, 4):
        out = lmp(cylinder(family) + END_DUMP, nprocs=nprocs).output
        assert ref.thermo_tables(out)[-1]["c_dmean"][-1] > 0.05    # bonds broke
        states.append(end_state(tmp_path))
    for other in states[1:]:
        for key in KEYS:
            np.testing.assert_array_equal(states[0][key], other[key])


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_cylinder_bitwise_on_2_threads_and_compact_storage(lmp, tmp_path, family):
    """2 OpenMP threads (each row writes only its own atom's history) and 'bond/storage
    compact' end the cylinder in the bits of 1 thread and the default storage."""
    states = []
    for threads, storage in ((1, ""), (2, ""), (1, " bond/storage compact")):
        script_text = cylinder(family).replace("units           si",
                                               f"package omp {threads}\nunits           si", 1)
        script_text = script_text.replace(f"pair_style      bbpd/{family} 3d",
                                          f"pair_style      bbpd/{family} 3d{storage}")
        out = lmp(script_text + END_DUMP).output
        assert f"1 MPI tasks x {threads} OpenMP threads" in out
        states.append(end_state(tmp_path))
    assert states[0]["c_1"].mean() > 0.05
    for other in states[1:]:
        for key in KEYS:
            np.testing.assert_array_equal(states[0][key], other[key])


def resumed_script(restart_file, steps, tail):
    """the cylinder continued from restart_file for steps, with the run's own tail"""
    return (f"plugin load bbpdplugin.so\nread_restart {restart_file}\nneighbor 0.0010 bin\n"
            f"lattice sc 0.0005\nvariable steps index {steps}\nfix 1 all nve" + tail + END_DUMP)


def assert_same_end(straight, restarted):
    assert straight["c_1"].mean() > 0.05
    for key in KEYS:
        np.testing.assert_array_equal(straight[key], restarted[key])


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_cylinder_restart_equals_continuous_run(lmp, tmp_path, family):
    """Across write_restart/read_restart (new process on 1 rank; on 2 ranks with a 'balance'
    by recursive bisection, and on 4 ranks after a second evaluation of the step, 'run 0',
    then the balance): the bonds' history, the plastic multipliers, the weighted volumes and
    the last dilatations come back and move with their atoms, and the run continues in the
    same bits as without the restart. (rcb: shift balancing rounds positions unless the box
    length is a power of two, for any pair style, test_balance.py.)"""
    script_text = cylinder(family, steps=300)
    _, tail = script_text.split("fix             1 all nve", 1)
    lmp(script_text + END_DUMP)
    straight = end_state(tmp_path)
    (tmp_path / "start.dump").rename(tmp_path / "start1.dump")
    lmp(cylinder(family, steps=150) + "write_restart state.restart\n")
    second = resumed_script("state.restart", 150, tail)
    rcb = "comm_style tiled\nbalance 1.0 rcb\n"
    for nprocs, extra in ((1, ""), (2, rcb), (4, "run 0\n" + rcb)):
        text = second.replace("run             ${steps}", extra + "run             ${steps}")
        lmp(text, nprocs=nprocs)
        assert_same_end(straight, end_state(tmp_path, "start1.dump"))


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_cylinder_resumes_from_a_restart_file_written_during_the_run(lmp, tmp_path, family):
    """Kill and resume: a run that writes restart files every 100 steps ('restart 100'), as a
    job that may be killed does; the file of step 200, read into a new process on 2 ranks,
    continues to step 300 in the bits of the run that was not interrupted."""
    script_text = cylinder(family, steps=300)
    _, tail = script_text.split("fix             1 all nve", 1)
    lmp(script_text.replace("run             ${steps}",
                            "restart         100 cyl.*.restart\nrun             ${steps}") + END_DUMP)
    straight = end_state(tmp_path)
    assert (tmp_path / "cyl.200.restart").is_file()
    (tmp_path / "start.dump").rename(tmp_path / "start1.dump")
    lmp(resumed_script("cyl.200.restart", 100, tail), nprocs=2)
    assert_same_end(straight, end_state(tmp_path, "start1.dump"))


@pytest.mark.parametrize("family", ["ves", "eps"])
def test_cylinder_follows_peri(lmp, tmp_path, family):
    """The smaller cylinder with peri/FAMILY and with bbpd/FAMILY: the same mean damage within
    2 % at every thermo step once bonds have broken."""
    ours = cylinder(family)
    theirs = (ours.replace("plugin load     bbpdplugin.so\n", "")
              .replace(f"pair_style      bbpd/{family} 3d", f"pair_style      peri/{family}")
              .replace("bbpd/damage/atom", "damage/atom"))
    tables = [ref.thermo_tables(lmp(s).output)[-1] for s in (theirs, ours)]
    d_ref, d = np.asarray(tables[0]["c_dmean"]), np.asarray(tables[1]["c_dmean"])
    assert d_ref[-1] > 0.05
    print(f"mean damage peri/{family}", list(d_ref), f"bbpd/{family}", list(d))
    broken = d_ref > 0.01
    np.testing.assert_allclose(d[broken], d_ref[broken], rtol=0.02)


VES_STYLE = "pair_style bbpd/ves 3d"
EPS_STYLE = "pair_style bbpd/eps 3d"
LPS_NUMBERS = "14.9e9 14.9e9 0.003015 0.001 0.25"
BAD = {
    "ves-negative-tau": (VES_STYLE, f"{LPS_NUMBERS} 0.5 -1.0e-3", "relaxation time tau must be > 0"),
    "ves-zero-tau": (VES_STYLE, f"{LPS_NUMBERS} 0.5 0.0", "relaxation time tau must be > 0"),
    "ves-lambda-above-1": (VES_STYLE, f"{LPS_NUMBERS} 1.5 1.0e-3", "must be in [0, 1]"),
    "ves-lambda-negative": (VES_STYLE, f"{LPS_NUMBERS} -0.1 1.0e-3", "must be in [0, 1]"),
    "ves-missing": (VES_STYLE, f"{LPS_NUMBERS} 0.5", "expected 'I J K G delta s00 alpha lambda tau'"),
    "ves-lps-numbers": (VES_STYLE, LPS_NUMBERS, "got 7 arguments"),
    "eps-yield-zero": (EPS_STYLE, f"{LPS_NUMBERS} 0.0", "yield stress must be > 0"),
    "eps-yield-negative": (EPS_STYLE, f"{LPS_NUMBERS} -1.0e8", "yield stress must be > 0"),
    "eps-missing": (EPS_STYLE, LPS_NUMBERS, "expected 'I J K G delta s00 alpha Y'"),
    "eps-too-many": (EPS_STYLE, f"{LPS_NUMBERS} 1.0e8 1", "got 9 arguments"),
}


# the history advances once per time step: solvers whose iterations are no time steps are refused
# (bbpd/lps itself minimizes and relaxes: tests/lammps/test_minimize.py, test_relax.py)
BAD_SOLVER = {
    f"{family}-{solver}": (f"pair_style bbpd/{family} 3d", numbers, extra, run, expected)
    for family, numbers in (("ves", f"{LPS_NUMBERS} 0.5 1.0e-3"), ("eps", f"{LPS_NUMBERS} 1.0e8"))
    for solver, extra, run, expected in (
        ("minimize", "", "minimize 0 1e-8 20 200", "cannot be used with minimize"),
        ("relax", "fix relax all bbpd/relax tol 1e-6", "run 10", "cannot be used with fix bbpd/relax"))
}


# the computes with a style that has no dilatation or plasticity
BAD_COMPUTE = {
    "plasticity-with-ves": (VES_STYLE, f"{LPS_NUMBERS} 0.5 1.0e-3", "plasticity/atom",
                            "requires pair style bbpd/eps"),
    "plasticity-with-lps": ("pair_style bbpd/lps 3d", LPS_NUMBERS, "plasticity/atom",
                            "requires pair style bbpd/eps"),
    "dilatation-with-pmb": ("pair_style bbpd/pmb 3d", "1.0e22 0.003015 0.001 0.25",
                            "dilatation/atom", "requires a state-based bbpd pair style"),
    "dilatation-arguments": (EPS_STYLE, f"{LPS_NUMBERS} 1.0e8", "dilatation/atom 1",
                             "it takes no arguments"),
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_input_stops_with_error(tmp_path, name):
    style, numbers, expected = BAD[name]
    text = script(BASE_3D, pair_style=style, pair_coeff=f"pair_coeff * * {numbers}")
    check_error_exit(run_case(tmp_path, text), expected)


@pytest.mark.parametrize("name", sorted(BAD_COMPUTE))
def test_computes_need_their_state(tmp_path, name):
    style, numbers, compute, expected = BAD_COMPUTE[name]
    text = script(BASE_3D, pair_style=style, pair_coeff=f"pair_coeff * * {numbers}",
                  extra=f"compute c all bbpd/{compute}\ncompute s all reduce sum c_c\n"
                        "thermo_style custom step c_s")
    check_error_exit(run_case(tmp_path, text), expected)


@pytest.mark.parametrize("name", sorted(BAD_SOLVER))
def test_solvers_without_time_steps_are_refused(tmp_path, name):
    style, numbers, extra, run, expected = BAD_SOLVER[name]
    text = script(BASE_3D, pair_style=style, pair_coeff=f"pair_coeff * * {numbers}", extra=extra,
                  run=run)
    check_error_exit(run_case(tmp_path, text), expected)
