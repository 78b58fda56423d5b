"""Tests for bbpd.crack_motion: Freund's equation of motion for a Mode-I crack."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from bbpd import crack_motion as cm
from bbpd import freund

# BBPD plane stress (nu = 1/3) with the paper's steel (sec. 4.2.1)
E, NU, RHO = 210e9, 1.0 / 3.0, 8000.0
H, TD, A, SIGMA0 = 2.0, 3.36e-4, 5.0, 1.0e6
C_D = freund.dilatational_wave_speed(E, NU, RHO, freund.PLANE_STRESS)
C_S = freund.shear_wave_speed(E, NU, RHO)
C_R = freund.rayleigh_wave_speed(C_S, C_D)
K_IC = 1.0e6
TIGHT = 1e-9
ODE_MATCH = 1e-7   # relative agreement of the integrated l(t) with a closed form


def test_k_of_zero_and_rayleigh_speed():
    assert cm.universal_k(0.0, C_R, C_D) == 1.0
    assert cm.universal_k(C_R, C_R, C_D) == 0.0
    v = np.linspace(0.0, C_R, 50)
    assert np.all(np.diff(cm.universal_k(v, C_R, C_D)) < 0.0)   # decreasing
    with pytest.raises(ValueError):
        cm.universal_k(1.01 * C_R, C_R, C_D)


def test_energy_factor_limits():
    assert cm.energy_factor(0.0, C_R) == 1.0
    assert cm.energy_factor(C_R, C_R) == 0.0


@pytest.mark.parametrize("criterion", cm.CRITERIA)
def test_no_growth_at_or_below_toughness(criterion):
    ks = np.array([0.0, 0.3, 0.999, 1.0]) * K_IC
    assert np.all(cm.crack_speed(ks, K_IC, C_R, C_D, criterion) == 0.0)


@pytest.mark.parametrize("criterion", cm.CRITERIA)
def test_speed_tends_to_rayleigh_speed(criterion):
    v = cm.crack_speed(np.array([1.01, 2.0, 10.0, 1e3, 1e6]) * K_IC, K_IC, C_R, C_D, criterion)
    assert np.all(np.diff(v) > 0.0)
    assert v[-1] == pytest.approx(C_R, rel=1e-5)
    assert np.all(v < C_R)


def test_toughness_speed_solves_k_v_kstar_equal_kic():
    for ratio in (1.001, 1.3, 2.0, 5.0, 50.0):
        v = cm.crack_speed(ratio * K_IC, K_IC, C_R, C_D, cm.TOUGHNESS)
        assert cm.universal_k(v, C_R, C_D) * ratio * K_IC == pytest.approx(K_IC, rel=TIGHT)


def test_energy_speed_is_freunds_form():
    ratio = 1.7
    v = cm.crack_speed(ratio * K_IC, K_IC, C_R, C_D, cm.ENERGY)
    assert v == pytest.approx(C_R * (1.0 - 1.0 / ratio ** 2), rel=TIGHT)
    assert cm.energy_factor(v, C_R) * (ratio * K_IC) ** 2 == pytest.approx(K_IC ** 2, rel=TIGHT)


def test_fracture_toughness_plane_conditions():
    G_c = 3.0
    assert cm.fracture_toughness(E, NU, G_c, freund.PLANE_STRESS) == pytest.approx(
        math.sqrt(E * G_c), rel=TIGHT)
    assert cm.fracture_toughness(E, 0.25, G_c, freund.PLANE_STRAIN) == pytest.approx(
        math.sqrt(E * G_c / (1 - 0.25 ** 2)), rel=TIGHT)


def _step_kstar(t0, amp):
    def k_star(t, l=None):
        return amp * np.sqrt(np.clip(np.asarray(t, dtype=float) - t0, 0.0, None))
    return k_star


def test_step_load_initiation_time():
    t0, amp = 1e-4, 5e7
    k_star = _step_kstar(t0, amp)
    t_i = cm.initiation_time(k_star, K_IC, 0.0, 1e-2)
    assert t_i == pytest.approx(t0 + (K_IC / amp) ** 2, rel=TIGHT)
    assert cm.initiation_time(k_star, 1e3 * K_IC, 0.0, 1e-2) is None


def test_step_load_energy_criterion_matches_closed_form():
    t0, amp = 1e-4, 5e7
    t_i = t0 + (K_IC / amp) ** 2
    t_end = t_i + 2e-3
    t, l, v = cm.tip_history(_step_kstar(t0, amp), K_IC, C_R, C_D, A, t_i, t_end, cm.ENERGY)
    l_exact, v_exact = cm.step_energy_history(t, t0, t_i, A, C_R)
    assert np.allclose(l - A, l_exact - A, rtol=ODE_MATCH, atol=ODE_MATCH * (l[-1] - A))
    assert np.allclose(v, v_exact, rtol=TIGHT, atol=TIGHT * C_R)
    assert l[-1] - A > 0.5 * C_R * (t_end - t_i)   # it really runs


def test_step_load_toughness_criterion_matches_quadrature():
    """l(t) - a = integral of the closed-form speed (quadratic root) from t_i."""
    t0, amp = 0.0, 5e7
    t_i = (K_IC / amp) ** 2
    t_end = 6.0 * t_i
    k_star = _step_kstar(t0, amp)
    t, l, v = cm.tip_history(k_star, K_IC, C_R, C_D, A, t_i, t_end, cm.TOUGHNESS)

    def speed(s):
        r2 = t_i / s   # (K_Ic/K*)^2
        beta = C_R / C_D
        return C_R * 0.5 * ((2 - r2 * beta) - math.sqrt(r2) * math.sqrt(4 * (1 - beta)
                                                                          + r2 * beta ** 2))
    for k in (50, 200, len(t) - 1):
        ext, _ = quad(speed, t_i, t[k], epsabs=0.0, epsrel=1e-12)
        assert l[k] - A == pytest.approx(ext, rel=ODE_MATCH)
    # slower than the energy criterion at the same K* (A(v) > 1 for v > 0)
    _, l_energy, _ = cm.tip_history(k_star, K_IC, C_R, C_D, A, t_i, t_end, cm.ENERGY)
    assert l[-1] < l_energy[-1]


def test_ramp_initiation_closed_form_matches_root_of_eq42():
    for G_c in (0.5, 1.0, 3.0, 8.0):   # inside and after the ramp
        prob = cm.RampProblem(E, NU, RHO, G_c, SIGMA0, TD, H, A, freund.PLANE_STRESS)
        t_i = prob.initiation_time()
        assert prob.k_star(t_i) == pytest.approx(prob.k_ic, rel=1e-9)
        t_num = cm.initiation_time(prob.k_star, prob.k_ic, 0.0, 10 * prob.t_c)
        assert t_i == pytest.approx(t_num, rel=1e-9)


def test_ramp_problem_uses_model_speeds_and_runs():
    prob = cm.RampProblem(E, NU, RHO, 1.0, SIGMA0, TD, H, A, freund.PLANE_STRESS)
    assert prob.c_r == pytest.approx(C_R) and prob.c_d == pytest.approx(C_D)
    assert prob.nu_eq == pytest.approx(0.25)
    t = np.linspace(0.0, prob.t_end, 300)
    l, v = prob.tip_position(t)
    t_i = prob.initiation_time()
    assert np.all(l[t <= t_i] == A) and np.all(np.diff(l) >= 0.0)
    assert np.all(v < C_R) and v[-1] > 0.5 * C_R
    with pytest.raises(ValueError):
        cm.RampProblem(E, NU, RHO, 1e3, SIGMA0, TD, H, A, freund.PLANE_STRESS).history()


def test_constant_kinetic_law_is_the_energy_form():
    law = cm.KineticLaw([0.3, 0.6], [1.0, 1.0])
    ks = np.array([0.5, 1.0, 1.3, 2.0, 10.0]) * K_IC
    assert np.allclose(cm.crack_speed(ks, K_IC, C_R, C_D, cm.KINETIC, law),
                       cm.crack_speed(ks, K_IC, C_R, C_D, cm.ENERGY), rtol=1e-12, atol=1e-9)


def test_kinetic_speed_solves_the_law():
    # G_run rising from G_c to 2 G_c at half the Rayleigh speed: a slower crack than the
    # energy form, and (1 - u) (K*/K_Ic)^2 = law(u) at the speed found
    law = cm.KineticLaw([0.25, 0.5], [1.5, 2.0])
    ks = np.array([1.2, 1.6, 2.5, 4.0]) * K_IC
    v = cm.crack_speed(ks, K_IC, C_R, C_D, cm.KINETIC, law)
    u = v / C_R
    assert np.allclose((1.0 - u) * (ks / K_IC) ** 2, law(u), rtol=1e-10)
    assert np.all(v < cm.crack_speed(ks, K_IC, C_R, C_D, cm.ENERGY))
    assert np.all(np.diff(v) > 0.0)


@pytest.mark.parametrize("u,g", [([0.5, 0.3], [2.0, 1.5]), ([0.3, 0.5], [2.0, 1.5]),
                                 ([1.2], [2.0]), ([], [])])
def test_kinetic_law_rejects_what_has_no_unique_speed(u, g):
    if u == [0.5, 0.3]:
        cm.KineticLaw(u, g)    # unsorted is fine: it sorts
        return
    with pytest.raises(ValueError):
        cm.KineticLaw(u, g)


def test_kinetic_criterion_needs_its_law():
    with pytest.raises(ValueError):
        cm.crack_speed(2.0 * K_IC, K_IC, C_R, C_D, cm.KINETIC)
    with pytest.raises(ValueError):
        cm.crack_speed(2.0 * K_IC, K_IC, C_R, C_D, cm.ENERGY, cm.KineticLaw([0.5], [2.0]))
