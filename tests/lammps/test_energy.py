"""compute bbpd/energy: the energy account closes while bonds break.

Elastic + kinetic + broken-bond energy - external work must stay constant to the time
integrator's error, here within 1 % of the broken-bond energy, in three scenes that put energy
in in three ways: the pre-stretched strip between fixed grips (no work: examples/strip-steady-
crack), the Mode-I plate under a traction of fix addforce (examples/mode1-propagation) and the
Kalthoff-Winkler plate under a prescribed velocity, held and then released
(examples/kalthoff-winkler). Each has a negative control: the account without the term that
scene depends on is off by far more than the tolerance. The values have the same bits on 1, 2
and 4 ranks, and an account continued after write_restart / read_restart has the same bits as
an uninterrupted one.
"""
import numpy as np
import pytest

from bbpd.jobs import ROOT
from bbpd.runner import run_lammps
from scenes import peri_preamble

TOLERANCE = 0.01    # of the broken-bond energy
EVERY = 10          # steps between outputs of the account
ACCOUNT = ("compute eacc all bbpd/energy\n"
           f"fix eout all ave/time {EVERY} 1 {EVERY} c_eacc[1] c_eacc[2] c_eacc[3] c_eacc[4] "
           "c_eacc[5] file energy.dat format \" %.17g\"\n")

STRIP = ROOT / "examples" / "strip-steady-crack" / "in.strip"
MODE1 = ROOT / "examples" / "mode1-propagation" / "in.mode1-propagation"
KW = ROOT / "examples" / "kalthoff-winkler" / "in.kalthoff_winkler"
# a small strip: 8 x 2 horizons (H = 10 delta would take 4x as long), the crack crosses it; its
# absorbing ends off, so that nothing does work
STRIP_SMALL = {"H": 0.005, "L": 0.02, "a": 0.005, "Delta": 2.5, "damp": 0.0}


# where the account starts: before the run that breaks bonds (the strip's pre-stretch comes
# before it, between two 'run 0')
START = {STRIP: "\nfix             out", MODE1: "\ntimestep", KW: "\ntimestep"}


def with_account(example):
    """the example's input with the account written every EVERY steps from its main run on"""
    text = example.read_text()
    at = text.index(START[example])
    return text[:at + 1] + ACCOUNT + text[at + 1:]


def account(tmp_path, example, nprocs=1, **vars):
    """rows: step U K B W balance"""
    run_lammps(with_account(example), tmp_path, nprocs=nprocs, vars=vars)
    return np.loadtxt(tmp_path / "energy.dat", ndmin=2)


def check_balance(rows, dropped=None):
    """max drift of the balance over the run, over the final broken-bond energy"""
    U, K, B, W = rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4]
    terms = {"U": U, "K": K, "B": B, "W": -W}
    if dropped:
        terms.pop(dropped)
    total = sum(terms.values())
    return np.max(np.abs(total - total[0])) / B[-1]


def test_strip_closes_without_work(tmp_path):
    rows = account(tmp_path, STRIP, **STRIP_SMALL)
    assert rows[-1, 3] > 0.0
    assert np.allclose(rows[:, 5], rows[:, 1] + rows[:, 2] + rows[:, 3] - rows[:, 4], rtol=1e-12)
    # the grips do no work: what W holds is the integrator's bounded difference
    assert np.max(np.abs(rows[:, 4])) < 1e-2 * rows[-1, 3]
    assert check_balance(rows) < TOLERANCE
    assert check_balance(rows, dropped="B") > 0.5    # negative control


def test_strip_damped_ends_absorb(tmp_path):
    # with the example's absorbing ends the damping's work is negative, and the account holds
    rows = account(tmp_path, STRIP, **dict(STRIP_SMALL, damp=1.0))
    assert rows[-1, 4] < -0.01 * rows[-1, 3]
    assert check_balance(rows) < TOLERANCE
    assert check_balance(rows, dropped="W") > 0.05    # negative control


def test_strip_crack_crosses(tmp_path):
    text = STRIP.read_text() + 'print "TIP-FINAL $(c_tip[1]:%.10g)"\n'
    proc = run_lammps(text, tmp_path, vars=STRIP_SMALL)
    tip = float(proc.output.split("TIP-FINAL ")[1].split()[0])
    assert tip > STRIP_SMALL["L"] - STRIP_SMALL["H"]


def test_mode1_traction_work(tmp_path):
    rows = account(tmp_path, MODE1, dx=0.1)
    B, W = rows[-1, 3], rows[-1, 4]
    assert B > 0.0 and W > 10 * B    # the traction put in far more than the crack took
    assert check_balance(rows) < TOLERANCE
    assert check_balance(rows, dropped="W") > 10.0    # negative control


def test_kalthoff_winkler_prescribed_velocity(tmp_path):
    # held for 20 us, then released: the layer goes on under fix nve, a second run
    rows = account(tmp_path, KW, dx=0.002, thold=2.0e-5)
    B, W = rows[-1, 3], rows[-1, 4]
    assert B > 0.0 and W > B
    assert check_balance(rows) < TOLERANCE
    assert check_balance(rows, dropped="W") > 1.0    # negative control
    # after the release nothing does work on the plate
    t = rows[:, 0] * 0.002 / 1e-3 * 8.7e-8
    late = rows[t > 2.2e-5]
    assert np.ptp(late[:, 4]) < 1e-3 * B


@pytest.mark.parametrize("nprocs", [2, 4])
def test_same_bits_on_any_rank_count(tmp_path, nprocs):
    one = account(tmp_path / "1", STRIP, **STRIP_SMALL)
    many = account(tmp_path / str(nprocs), STRIP, nprocs=nprocs, **STRIP_SMALL)
    assert one.shape == many.shape and np.array_equal(one, many)


# a small pre-stretched plate, bonds breaking, written out and read back in mid-run
RESTART_BODY = peri_preamble(2, lattice="sq 2.5e-4 origin 0.5 0.5 0.0") + """\
region box block 0 0.01 -0.0025 0.0025 -0.5 0.5 units box
create_box 1 box
create_atoms 1 region box
set group all density 2440
set group all volume 1.5625e-11
pair_style bbpd/gaussian plane/stress thickness 2.5e-4
pair_coeff * * 72e9 3.8 0.001
fix notch all bbpd/notch segment -2.5e-4 0.0 0.004 0.0
region grips block INF INF -0.00225 0.00225 INF INF side out units box
group grips region grips
group free subtract all grips
"""
RESTART_DYNAMICS = """\
neighbor 2.5e-5 bin
neigh_modify every 1 delay 0 check yes
fix nve free nve
fix 2d all enforce2d
fix push free addforce 1.0e8 0.0 0.0
compute eacc all bbpd/energy
timestep 2.0e-8
thermo_style custom step c_eacc[1] c_eacc[3] c_eacc[5]
"""
FINAL = ('print "ACCOUNT $(c_eacc[1]:%.17g) $(c_eacc[2]:%.17g) $(c_eacc[3]:%.17g) '
         '$(c_eacc[4]:%.17g) $(c_eacc[5]:%.17g)"\n')


def final_account(proc):
    return [float(v) for v in proc.output.split("ACCOUNT ")[-1].split()[:5]]


def test_restart_continues_the_account(tmp_path):
    start = (RESTART_BODY + RESTART_DYNAMICS + "run 0\nvariable uy atom 1.6e-4*y\n"
             "displace_atoms all move 0 v_uy 0 units box\n")
    whole = run_lammps(start + "run 400\n" + FINAL, tmp_path / "whole")
    first = run_lammps(start + "run 200\nwrite_restart half.restart\n", tmp_path / "split")
    again = (peri_preamble(2, plugin=True).split("units si")[0] +
             "read_restart half.restart\n" + "fix notch all bbpd/notch segment -2.5e-4 0.0 0.004 0.0\n"
             "region grips block INF INF -0.00225 0.00225 INF INF side out units box\n"
             "group grips region grips\ngroup free subtract all grips\n" + RESTART_DYNAMICS +
             "run 200\n" + FINAL)
    second = run_lammps(again, tmp_path / "split")
    got, expected = final_account(second), final_account(whole)
    assert expected[2] > 0.0 and expected[3] != 0.0    # bonds broke; the push did work
    assert got == expected
    assert first.error is None
