"""fix bbpd/relax: quasi-static load steps by adaptive dynamic relaxation, with bonds that break
only between converged states.

The plate of tests/lammps/test_minimize.py (40 x 20 mm, 6 mm hole, delta = 2 mm = 3 Delta,
Gaussian kernel, E = 72 GPa, Gc = 3.8 J/m^2), both grips held by fix setforce, the right one
moved by displace_atoms between runs (one run = one load step):
- elastic (Gc none): a load step relaxed to tol = 1e-10 is the minimum that LAMMPS's own
  minimizer finds (energy and grip reaction), an answer no relaxation wrote;
- breaking only in converged states: at a grip displacement where the elastic equilibrium
  has 4 bonds past breaking (minimize holds and counts them), the load step breaks exactly
  those; negative control: a force evaluation in the displaced, unrelaxed state (run 0
  without the fix) breaks hundreds at the grip;
- a crack that runs at fixed load is followed (relaxations after breaking), with the same bits
  on 1, 2 and 4 ranks, and continued from a restart file with the same bits;
- bad input ends in an ERROR that says what to change.
"""
import re

import pytest

from bbpd.runner import LammpsError
from scenes import HOLED_PLATE_DELTA, HOLED_PLATE_DX, HOLED_PLATE_H, holed_plate

DX, DELTA, H = HOLED_PLATE_DX, HOLED_PLATE_DELTA, HOLED_PLATE_H    # the plate of scenes.holed_plate
DU_HELD = 3.5e-6    # the equilibrium has 4 bonds past breaking (measured: minimize's report)
DU_CRACK = 4.0e-6   # per load step: the crack starts at the hole and runs across in the second


def plate(gc="3.8", body="", density=2700.0, bonds=""):
    return holed_plate(f"bbpd/gaussian plane/stress thickness {H}", f"* * 72.0e9 {gc} {DELTA}{bonds}",
                       density) + f"""
fix             lgrip left setforce 0.0 0.0 0.0
fix             rgrip right setforce 0.0 0.0 0.0
fix             2d all enforce2d
compute         damage all bbpd/damage/atom
compute         dmax all reduce max c_damage
compute         eacc all bbpd/energy
thermo_style    custom step pe c_dmax c_eacc[1]
run             0
{body}"""


RELAX = "fix relax all bbpd/relax tol {tol}\n"
STEP = ("displace_atoms  right move {du} 0.0 0.0 units box\nrun 100000\n"
        "print \"LOAD $(f_relax[1]) $(c_eacc[1]:%.17g) $(f_lgrip[1]:%.17g) $(f_relax[2]) $(f_relax[3]) "
        "$(f_relax[4]) $(f_relax[6]:%.17g) $(f_relax[7]) $(c_dmax:%.17g)\"\n")


def loads(out):
    """per load step: step, elastic energy (an exact sum), reaction, iterations, relaxations, broken, residual, converged,
    max damage"""
    return [[float(v) for v in m.split()] for m in re.findall(r"^LOAD (.*)$", out, re.M)]


def test_elastic_load_step_is_the_minimum(lmp):
    out = lmp(plate("none", RELAX.format(tol=1e-10) + STEP.format(du=DU_HELD))).output
    (step, pe, reaction, its, nrelax, broken, res, conv, dmax), = loads(out)
    assert conv == 1.0 and res <= 1e-10 and nrelax == 1 and broken == 0
    assert re.search(r"bbpd/relax: load step 1 converged at step \d+: \d+ iterations", out)
    ref = lmp(plate("none", f"displace_atoms right move {DU_HELD} 0.0 0.0 units box\n"
                    "minimize 0.0 1.0e-12 10000 100000\n"
                    "print \"MIN $(c_eacc[1]:%.17g) $(f_lgrip[1]:%.17g)\"\n")).output
    pe_min, reaction_min = map(float, re.search(r"^MIN (\S+) (\S+)$", ref, re.M).groups())
    assert abs(pe - pe_min) <= 1e-9 * pe_min
    assert abs(reaction - reaction_min) <= 1e-6 * abs(reaction_min)


def test_bonds_break_only_in_the_converged_state(lmp):
    held = lmp(plate(body=f"displace_atoms right move {DU_HELD} 0.0 0.0 units box\n"
                          "minimize 0.0 1.0e-10 2000 20000\n")).output
    n = int(re.search(r"minimize held (\d+) bonds past breaking", held).group(1))
    assert n == 4
    out = lmp(plate(body=RELAX.format(tol=1e-8) + STEP.format(du=DU_HELD))).output
    (step, pe, reaction, its, nrelax, broken, res, conv, dmax), = loads(out)
    assert conv == 1.0 and broken == n and nrelax == 2    # relaxed again after they broke
    # negative control: the displaced state before relaxing breaks bonds at the grip
    raw = lmp(plate(body=f"displace_atoms right move {DU_HELD} 0.0 0.0 units box\nrun 0\n"
                         "run 0\n")).output
    assert int(re.findall(r"total bonds \d+ \((\d+) broken\)", raw)[-1]) > 100


CRACK = RELAX.format(tol=1e-6) + STEP.format(du=DU_CRACK) * 2


@pytest.fixture(scope="module")
def crack_serial(tmp_path_factory):
    from bbpd.runner import run_lammps
    return loads(run_lammps(plate(body=CRACK), tmp_path_factory.mktemp("serial")).output)


def test_crack_runs_at_fixed_load(crack_serial):
    first, second = crack_serial
    assert first[7] == second[7] == 1.0
    assert 0 < first[5] < 1000 and second[5] > 1000    # initiation, then a run across
    assert second[4] > 2 and second[8] > 0.5
    assert second[2] < 0.1 * first[2]    # the grip reaction falls: the plate is cut


@pytest.mark.parametrize("nprocs", [2, 4])
def test_same_bits_on_any_rank_count(lmp, crack_serial, nprocs):
    rows = loads(lmp(plate(body=CRACK), nprocs=nprocs).output)
    # the reaction is LAMMPS's sum over the ranks (fix setforce), not an exact one
    same = lambda rows: [r[:2] + r[3:] for r in rows]
    assert same(rows) == same(crack_serial)
    assert [r[2] for r in rows] == pytest.approx([r[2] for r in crack_serial], rel=1e-12)


def test_restart_continues_the_load_steps(lmp, tmp_path, crack_serial):
    lmp(plate(body=RELAX.format(tol=1e-6) + STEP.format(du=DU_CRACK) + "write_restart qs.restart\n"))
    resumed = lmp("plugin load bbpdplugin.so\nread_restart qs.restart\n"
                  f"neighbor {DX} bin\n"
                  "fix lgrip left setforce 0.0 0.0 0.0\nfix rgrip right setforce 0.0 0.0 0.0\n"
                  "fix 2d all enforce2d\ncompute damage all bbpd/damage/atom\n"
                  "compute dmax all reduce max c_damage\ncompute eacc all bbpd/energy\n"
                  "thermo_style custom step pe c_dmax c_eacc[1]\n"
                  + RELAX.format(tol=1e-6) + "run 0\n" + STEP.format(du=DU_CRACK)).output
    assert loads(resumed) == crack_serial[1:]


@pytest.mark.parametrize("body,message", [
    ("fix relax all bbpd/relax tol 0.0\n", "tol must be > 0"),
    ("fix relax all bbpd/relax tol -1.0e-6\n", "tol must be > 0"),
    ("fix relax all bbpd/relax\n", "expected 'fix ID group bbpd/relax tol TOL'"),
    ("group none subtract all all\nfix relax none bbpd/relax tol 1.0e-6\n",
     "no atom of group none has a bond"),
])
def test_bad_input_is_an_error(lmp, body, message):
    with pytest.raises(LammpsError) as e:
        lmp(plate(body=body + "run 10\n"))
    assert message in e.value.message


def test_zero_density_is_an_error(lmp):
    with pytest.raises(LammpsError) as e:
        lmp(plate(density=0.0, body=RELAX.format(tol=1e-6) + "run 10\n"))
    assert "density" in e.value.message
