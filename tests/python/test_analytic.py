"""Tests for bbpd.freund, bbpd.metrics, bbpd.dsif and bbpd.plots."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from bbpd import dsif, freund, metrics

# Paper section 4.2.1 (mode I) and 4.2.2 (mode II) data.
E1, NU1, RHO1 = 210e9, 0.3, 8000.0
H1, TD1, SIGMA0 = 2.0, 3.36e-4, 1.0e6
E2, NU2, RHO2 = 73.5e9, 0.25, 2450.0
H2, A2, HALF_L2 = 20e-3, 12e-3, 52e-3
TAU = 1.0e6
QUAD_RTOL = 1e-10
TIGHT = 1e-9


def lame(E, nu):
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    return lam, mu


# ---------------------------------------------------------------- wave speeds
def test_wave_speeds_match_lame_constants():
    lam, mu = lame(E1, NU1)
    c_d = freund.dilatational_wave_speed(E1, NU1, RHO1, freund.PLANE_STRAIN)
    assert c_d == pytest.approx(math.sqrt((lam + 2 * mu) / RHO1), rel=TIGHT)
    assert freund.dilatational_wave_speed(E1, NU1, RHO1, freund.THREE_D) == c_d
    lam_ps = 2 * lam * mu / (lam + 2 * mu)
    c_ps = freund.dilatational_wave_speed(E1, NU1, RHO1, freund.PLANE_STRESS)
    assert c_ps == pytest.approx(math.sqrt((lam_ps + 2 * mu) / RHO1), rel=TIGHT)
    assert c_ps < c_d
    assert freund.shear_wave_speed(E1, NU1, RHO1) == pytest.approx(math.sqrt(mu / RHO1))


def test_rayleigh_speed_poisson_solid():
    # nu = 0.25 plane strain (lambda = mu): c_R/c_s = sqrt(2 - 2/sqrt(3)).
    c_s = freund.shear_wave_speed(E2, NU2, RHO2)
    c_d = freund.dilatational_wave_speed(E2, NU2, RHO2)
    assert freund.rayleigh_wave_speed(c_s, c_d) / c_s == pytest.approx(
        math.sqrt(2 - 2 / math.sqrt(3)), rel=1e-10)


# --------------------------------------------------------------------- mode I
@pytest.fixture
def mode1():
    c_d = freund.dilatational_wave_speed(E1, NU1, RHO1)
    return dict(nu=NU1, sigma0=SIGMA0, c_d=c_d, t_d=TD1, H=H1)


def test_eq42_zero_before_arrival_and_continuous_at_td(mode1):
    t_c = freund.crack_arrival_time(H1, mode1["c_d"])
    assert freund.mode1_ramp_dsif(0.5 * t_c, **mode1) == 0.0
    eps = 1e-9 * TD1
    left = freund.mode1_ramp_dsif(t_c + TD1 - eps, **mode1)
    right = freund.mode1_ramp_dsif(t_c + TD1 + eps, **mode1)
    assert left > 0.0
    assert right == pytest.approx(left, rel=1e-7)
    # value at t_d equals the first branch (4/(3 pi)) f sigma0 sqrt(pi C_d t_d)
    f = math.sqrt(1 - 2 * NU1) / (1 - NU1)
    expected = 4 / (3 * math.pi) * f * SIGMA0 * math.sqrt(math.pi * mode1["c_d"] * TD1)
    assert freund.mode1_ramp_dsif(t_c + TD1, **mode1) == pytest.approx(expected, rel=TIGHT)


def duhamel(step, t_bar, t_d):
    """(1/t_d) int_0^min(t_bar, t_d) step(t_bar - s) ds: ramp response."""
    upper = min(t_bar, t_d)
    val, _ = quad(lambda s: step(t_bar - s), 0.0, upper, epsabs=0.0, epsrel=QUAD_RTOL,
                  limit=200)
    return val / t_d


@pytest.mark.parametrize("ratio", [0.3, 1.0, 1.7, 4.0])
def test_eq42_equals_duhamel_integral_of_step(mode1, ratio):
    t_c = freund.crack_arrival_time(H1, mode1["c_d"])
    step_args = {k: mode1[k] for k in ("nu", "sigma0", "c_d", "H")}

    def step(tb):
        return freund.mode1_step_dsif(t_c + tb, **step_args)

    t_bar = ratio * TD1
    assert freund.mode1_ramp_dsif(t_c + t_bar, **mode1) == pytest.approx(
        duhamel(step, t_bar, TD1), rel=1e-8)


def test_ramp_tends_to_delayed_step(mode1):
    t_c = freund.crack_arrival_time(H1, mode1["c_d"])
    t_bar = 100 * TD1
    step_args = {k: mode1[k] for k in ("nu", "sigma0", "c_d", "H")}
    assert freund.mode1_ramp_dsif(t_c + t_bar, **mode1) == pytest.approx(
        freund.mode1_step_dsif(t_c + t_bar - TD1 / 2, **step_args), rel=1e-5)


def test_mode1_nu_form_equals_wave_speed_form():
    t_bar = np.linspace(0.0, 1e-3, 7)
    for nu in (0.1, 0.25, 0.3, 0.4):
        c_d = freund.dilatational_wave_speed(E1, nu, RHO1, freund.PLANE_STRAIN)
        c_s = freund.shear_wave_speed(E1, nu, RHO1)
        a = freund.mode1_step_dsif(t_bar, nu, SIGMA0, c_d, 0.0)
        b = freund.mode1_step_dsif_wave_speeds(t_bar, SIGMA0, c_s, c_d)
        np.testing.assert_allclose(a, b, rtol=1e-12)
        # plane stress: equivalent Poisson ratio with the plane-stress C_d
        c_ps = freund.dilatational_wave_speed(E1, nu, RHO1, freund.PLANE_STRESS)
        nu_eff = freund.equivalent_plane_stress_poisson(nu)
        np.testing.assert_allclose(freund.mode1_step_dsif(t_bar, nu_eff, SIGMA0, c_ps, 0.0),
                                   freund.mode1_step_dsif_wave_speeds(t_bar, SIGMA0, c_s, c_ps),
                                   rtol=1e-12)


def test_mode1_normalisation_and_validity(mode1):
    assert freund.mode1_validity_end(H1, mode1["c_d"]) == pytest.approx(3 * H1 / mode1["c_d"])
    np.testing.assert_allclose(freund.normalised_mode1([2.0, 4.0], 2.0, 4.0), [0.5, 1.0])


# -------------------------------------------------------------------- mode II
@pytest.fixture
def speeds2():
    return (freund.shear_wave_speed(E2, NU2, RHO2),
            freund.dilatational_wave_speed(E2, NU2, RHO2, freund.PLANE_STRAIN))


def test_mode2_step_plane_strain_closed_form(speeds2):
    c_s, c_d = speeds2
    t_bar = 3e-6
    expected = 2 * TAU * math.sqrt(2 * c_s * t_bar / (math.pi * (1 - NU2)))
    assert freund.mode2_step_dsif(t_bar, TAU, c_s, c_d) == pytest.approx(expected, rel=1e-12)
    assert freund.mode2_step_dsif(-1e-6, TAU, c_s, c_d) == 0.0


def test_mode2_vs_mode1_ratio(speeds2):
    # Same derivation with alpha -> beta: K_II/K_I = sqrt(c_d/c_s) at equal load.
    c_s, c_d = speeds2
    t_bar = np.array([1e-6, 5e-6])
    ratio = (freund.mode2_step_dsif(t_bar, TAU, c_s, c_d)
             / freund.mode1_step_dsif(t_bar, NU2, TAU, c_d, 0.0))
    np.testing.assert_allclose(ratio, math.sqrt(c_d / c_s), rtol=1e-12)


@pytest.mark.parametrize("ratio", [0.25, 1.0, 2.5])
def test_mode2_ramp_equals_duhamel_integral(speeds2, ratio):
    c_s, c_d = speeds2
    t_d = 2e-6
    t_bar = ratio * t_d

    def step(tb):
        return freund.mode2_step_dsif(tb, TAU, c_s, c_d)

    assert freund.mode2_ramp_dsif(t_bar, TAU, c_s, c_d, t_d) == pytest.approx(
        duhamel(step, t_bar, t_d), rel=1e-8)


def test_mode2_validity_window_paper_plate(speeds2):
    c_s, c_d = speeds2
    w = freund.mode2_validity_window(H2, A2, HALF_L2, c_s, c_d)
    assert w.t_start == pytest.approx(H2 / c_s)
    assert w.t_corner == pytest.approx(math.sqrt(0.04 ** 2 + 0.02 ** 2) / c_d)
    assert w.t_other_tip == pytest.approx(w.t_start + 2 * A2 / c_d)
    assert w.t_other_tip_rayleigh > w.t_other_tip
    assert w.t_end == w.t_corner  # corner P wave is first for this plate
    assert w.t_end_ignoring_corners == pytest.approx(w.t_other_tip)
    assert w.t_start < w.t_end


def test_crack_plane_amplitude():
    assert freund.crack_plane_amplitude(3.0, 1) == 3.0
    assert freund.crack_plane_amplitude(3.0, 2) == 6.0
    with pytest.raises(ValueError):
        freund.crack_plane_amplitude(3.0, 3)


@pytest.mark.parametrize("call", [
    lambda: freund.dilatational_wave_speed(E1, 0.5, RHO1),
    lambda: freund.dilatational_wave_speed(E1, NU1, RHO1, "axisymmetric"),
    lambda: freund.dilatational_wave_speed(-E1, NU1, RHO1),
    lambda: freund.mode1_ramp_dsif(1.0, NU1, SIGMA0, 5000.0, 0.0, H1),
    lambda: freund.mode1_ramp_dsif(np.nan, NU1, SIGMA0, 5000.0, TD1, H1),
    lambda: freund.mode2_step_dsif(1.0, TAU, 6000.0, 3000.0),
    lambda: freund.mode2_validity_window(H2, HALF_L2, A2, 3000.0, 6000.0),
    lambda: freund.rayleigh_wave_speed(3000.0, 3000.0),
])
def test_freund_bad_input(call):
    with pytest.raises(ValueError):
        call()


# -------------------------------------------------------------------- metrics
def test_metrics_known_values():
    t = np.array([0.0, 1.0, 2.0, 3.0])
    exact = np.array([0.0, 1.0, 2.0, 2.0])
    num = np.array([0.0, 1.0, 2.2, 1.8])
    assert metrics.peak_relative_error(t, num, exact) == pytest.approx(0.1)
    # sqrt((0.04 + 0.04) / (1 + 4 + 4))
    assert metrics.l2_relative_error(t, num, exact) == pytest.approx(math.sqrt(0.08 / 9))
    assert metrics.l2_relative_error(t, exact, exact) == 0.0


def test_metrics_window_and_callable():
    t = np.linspace(0.0, 4.0, 41)
    num = np.where(t <= 2.0, 2 * t, 0.0)  # wrong only after t = 2

    def exact(x):
        return 2 * x

    assert metrics.l2_relative_error(t, num, exact, window=(0.0, 2.0)) == pytest.approx(0.0)
    assert metrics.l2_relative_error(t, num, exact) > 0.5
    assert metrics.peak_relative_error(t, num, exact, window=(1.0, 2.0)) == pytest.approx(0.0)


@pytest.mark.parametrize("num, exact, window", [
    ([0.0, np.nan, 1.0], [0.0, 1.0, 1.0], None),
    ([0.0, 1.0, 1.0], [0.0, np.inf, 1.0], None),
    ([0.0, 1.0], [0.0, 1.0, 1.0], None),
    ([0.0, 1.0, 1.0], [0.0, 0.0, 0.0], None),
    ([0.0, 1.0, 1.0], [0.0, 1.0, 1.0], (5.0, 6.0)),
    ([0.0, 1.0, 1.0], [0.0, 1.0, 1.0], (2.0, 1.0)),
])
def test_metrics_bad_input(num, exact, window):
    t = [0.0, 1.0, 2.0]
    with pytest.raises(ValueError):
        metrics.l2_relative_error(t, num, exact, window)
    with pytest.raises(ValueError):
        metrics.peak_relative_error(t, num, exact, window)


# ----------------------------------------------------------------------- dsif
CONDITIONS = [freund.PLANE_STRAIN, freund.PLANE_STRESS]
DX = 1e-3
R1, R2 = DX, 2 * DX


def test_kolosov_values():
    assert dsif.kolosov_constant(0.25, freund.PLANE_STRAIN) == pytest.approx(2.0)
    assert dsif.kolosov_constant(0.25, freund.PLANE_STRESS) == pytest.approx(2.2)
    assert dsif.shear_modulus(E2, NU2) == pytest.approx(29.4e9)


def face_jumps(k_i, k_ii, r, mu, kappa):
    up1, up2 = dsif.williams_displacement(k_i, k_ii, r, np.pi, mu, kappa)
    lo1, lo2 = dsif.williams_displacement(k_i, k_ii, r, -np.pi, mu, kappa)
    return up1 - lo1, up2 - lo2, up1, up2


@pytest.mark.parametrize("condition", CONDITIONS)
def test_williams_field_is_elastostatic(condition):
    """Independent check of williams_displacement: Navier equations
    lap(u) + 2/(kappa-1) grad div u = 0 and sigma_ij sqrt(2 pi r) -> K on theta=0."""
    mu = dsif.shear_modulus(E2, NU2)
    kappa = dsif.kolosov_constant(NU2, condition)
    k_i, k_ii = 2.0e6, -0.7e6
    lam = mu * (3 - kappa) / (kappa - 1)
    h = 1e-6
    x0, y0 = 3e-4, 2e-4

    def u(x, y):
        return np.array(dsif.williams_displacement(k_i, k_ii, np.hypot(x, y),
                                                   np.arctan2(y, x), mu, kappa))

    lap = (u(x0 + h, y0) + u(x0 - h, y0) + u(x0, y0 + h) + u(x0, y0 - h) - 4 * u(x0, y0)) / h**2
    uxx = (u(x0 + h, y0) - 2 * u(x0, y0) + u(x0 - h, y0)) / h**2
    uyy = (u(x0, y0 + h) - 2 * u(x0, y0) + u(x0, y0 - h)) / h**2
    uxy = (u(x0 + h, y0 + h) - u(x0 + h, y0 - h) - u(x0 - h, y0 + h) + u(x0 - h, y0 - h)) / (4 * h**2)
    grad_div = np.array([uxx[0] + uxy[1], uxy[0] + uyy[1]])
    residual = lap + 2 / (kappa - 1) * grad_div
    assert np.max(np.abs(residual)) < 1e-5 * np.max(np.abs(lap))

    r = 1e-4  # stresses ahead of the tip (theta = 0) by central differences
    h = 1e-4 * r
    du_dx = (u(r + h, 0.0) - u(r - h, 0.0)) / (2 * h)
    du_dy = (u(r, h) - u(r, -h)) / (2 * h)
    eps11, eps22, gam12 = du_dx[0], du_dy[1], du_dy[0] + du_dx[1]
    sigma22 = lam * (eps11 + eps22) + 2 * mu * eps22
    sigma12 = mu * gam12
    assert sigma22 * math.sqrt(2 * math.pi * r) == pytest.approx(k_i, rel=1e-6)
    assert sigma12 * math.sqrt(2 * math.pi * r) == pytest.approx(k_ii, rel=1e-6)


@pytest.mark.parametrize("condition", CONDITIONS)
@pytest.mark.parametrize("k_i, k_ii", [(1.5e6, 0.0), (0.0, 2.5e6), (1.5e6, -0.8e6)])
def test_extrapolation_exact_on_williams_field(condition, k_i, k_ii):
    mu = dsif.shear_modulus(E2, NU2)
    kappa = dsif.kolosov_constant(NU2, condition)
    s1, o1, up1_1, up2_1 = face_jumps(k_i, k_ii, R1, mu, kappa)
    s2, o2, up1_2, up2_2 = face_jumps(k_i, k_ii, R2, mu, kappa)
    assert dsif.k_from_face_jump(o1, o2, R1, R2, mu, kappa) == pytest.approx(k_i, rel=1e-12, abs=1e-6)
    assert dsif.k_from_face_jump(s1, s2, R1, R2, mu, kappa) == pytest.approx(k_ii, rel=1e-12, abs=1e-6)
    # the paper's literal single-face form gives the same values
    assert dsif.k_from_face_displacement(up2_1, up2_2, R1, R2, mu, kappa) == pytest.approx(
        k_i, rel=1e-12, abs=1e-6)
    assert dsif.k_from_face_displacement(up1_1, up1_2, R1, R2, mu, kappa) == pytest.approx(
        k_ii, rel=1e-12, abs=1e-6)


def test_extrapolation_removes_r32_term_and_vectorises():
    mu = dsif.shear_modulus(E2, NU2)
    kappa = dsif.kolosov_constant(NU2, freund.PLANE_STRAIN)
    k_series = np.array([0.0, 1e6, 2e6, 3e6])
    higher = 4e-3  # r^(3/2) coefficient: ~10 % of the opening at r1 for K = 1 MPa sqrt(m)

    def opening(r):
        return (k_series * (kappa + 1) / mu * np.sqrt(r / (2 * np.pi))
                + higher * r ** 1.5)

    np.testing.assert_allclose(
        dsif.k_from_face_jump(opening(R1), opening(R2), R1, R2, mu, kappa),
        k_series, rtol=1e-12, atol=1e-6)
    # a single point (no extrapolation) is biased by that term: the test can fail
    single_point = opening(R1) * mu / (kappa + 1) * np.sqrt(2 * np.pi / R1)
    assert np.all(np.abs(single_point - k_series) > 1.0)


def test_single_face_value_is_half_the_jump():
    # Guards the factor 2: feeding the jump into the single-face formula doubles K.
    mu = dsif.shear_modulus(E2, NU2)
    kappa = dsif.kolosov_constant(NU2, freund.PLANE_STRESS)
    _, o1, _, _ = face_jumps(1e6, 0.0, R1, mu, kappa)
    _, o2, _, _ = face_jumps(1e6, 0.0, R2, mu, kappa)
    assert dsif.k_from_face_displacement(o1, o2, R1, R2, mu, kappa) == pytest.approx(2e6)


@pytest.mark.parametrize("call", [
    lambda: dsif.kolosov_constant(0.25, "3d"),
    lambda: dsif.kolosov_constant(0.6, freund.PLANE_STRAIN),
    lambda: dsif.k_from_face_jump(1.0, 1.0, R2, R1, 1.0, 2.0),
    lambda: dsif.k_from_face_jump(1.0, 1.0, 0.0, R1, 1.0, 2.0),
    lambda: dsif.k_from_face_jump(np.nan, 1.0, R1, R2, 1.0, 2.0),
    lambda: dsif.k_from_face_jump([1.0, 2.0], [1.0], R1, R2, 1.0, 2.0),
    lambda: dsif.k_from_face_jump(1.0, 1.0, R1, R2, -1.0, 2.0),
])
def test_dsif_bad_input(call):
    with pytest.raises(ValueError):
        call()


# ---------------------------------------------------------------------- plots
def test_plot_k_writes_png(tmp_path, speeds2):
    from bbpd import plots

    c_s, c_d = speeds2
    t = np.linspace(0.0, 5e-6, 50)
    k = freund.normalised_mode2(freund.mode2_step_dsif(t, TAU, c_s, c_d), TAU, A2)
    out = plots.plot_k(tmp_path / "k.png", [("noisy", t, 1.05 * k, None)],
                       [("exact", t, k, "--", "black")], (0.0, 4e-6), "K(t)", "t (s)", "K")
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 1000
    with pytest.raises(ValueError):
        plots.plot_k(tmp_path / "empty.png", [], [], (), "", "", "")
