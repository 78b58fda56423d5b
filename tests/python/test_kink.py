"""Tests for bbpd.kink: the three kink criteria and the Williams displacement field."""

import math

import numpy as np
import pytest

from bbpd import crack_path, kink

TIGHT = 1e-9
ANGLE_TOL = 1e-5          # deg: a maximiser is found to ~sqrt(machine epsilon) rad
MIXES_DEG = (0.0, 10.0, 22.5, 45.0, 67.5, 80.0, 90.0)
# pure Mode II (K_I = 0, K_II > 0), from closed forms or the literature:
MODE2_HOOP_STRESS = 2.0 * math.degrees(math.atan(-1.0 / math.sqrt(2.0)))   # -70.5288
MODE2_HOOP_STRAIN_NU_THIRD = -63.6          # the value quoted for BBPD's in-plane nu = 1/3
MODE2_HPU = -75.2                           # Hussain, Pu & Underwood 1974 (quoted to 0.1 deg)


def loads(psi_deg, K=1.0):
    psi = math.radians(psi_deg)
    return (0.0 if psi_deg == 90.0 else K * math.cos(psi)), K * math.sin(psi)


def test_hoop_stress_closed_form_is_the_stationary_tensile_direction():
    assert kink.hoop_stress_angle(0.0, 1.0) == pytest.approx(MODE2_HOOP_STRESS, abs=TIGHT)
    assert MODE2_HOOP_STRESS == pytest.approx(-70.53, abs=0.005)
    for psi in MIXES_DEG:
        KI, KII = loads(psi)
        t = math.radians(kink.hoop_stress_angle(KI, KII))
        s_rr, s_tt, s_rt = kink.williams_stresses(t, KI, KII)
        assert abs(s_rt) < TIGHT and s_tt > 0.0
        # and it is the global maximum of s_tt (the numerical scan agrees)
        assert kink._argmax_deg(lambda x: kink.williams_stresses(x, KI, KII)[1]) == \
            pytest.approx(math.degrees(t), abs=ANGLE_TOL)
        assert KI * math.sin(t) + KII * (3 * math.cos(t) - 1) == pytest.approx(0.0, abs=TIGHT)


@pytest.mark.parametrize("name", ["stress", "strain", "energy"])
def test_sign_convention_and_scale_invariance(name):
    f = {"stress": kink.hoop_stress_angle,
         "strain": lambda a, b: kink.hoop_strain_angle(a, b, 1 / 3, kink.PLANE_STRESS),
         "energy": kink.max_energy_release_angle}[name]
    assert f(1.0, 0.0) == 0.0
    previous = 0.0
    for psi in MIXES_DEG[1:]:
        KI, KII = loads(psi)
        theta = f(KI, KII)
        assert theta < previous < 1e-12          # positive K_II kinks to negative theta, more so
        assert f(KI, -KII) == pytest.approx(-theta, abs=ANGLE_TOL)   # with more Mode II
        assert f(7.3 * KI, 7.3 * KII) == pytest.approx(theta, abs=ANGLE_TOL)
        previous = theta


def test_hoop_strain_pure_mode2_and_bbpd_poisson_ratios():
    ps = kink.hoop_strain_angle(0.0, 1.0, kink.BBPD_POISSON[kink.PLANE_STRESS], kink.PLANE_STRESS)
    pe = kink.hoop_strain_angle(0.0, 1.0, kink.BBPD_POISSON[kink.PLANE_STRAIN], kink.PLANE_STRAIN)
    assert ps == pytest.approx(MODE2_HOOP_STRAIN_NU_THIRD, abs=0.05)
    assert pe == pytest.approx(ps, abs=ANGLE_TOL)  # plane strain nu = 1/4 is plane stress nu' = 1/3
    for psi in MIXES_DEG:
        KI, KII = loads(psi)
        # nu = 0: the hoop strain is the hoop stress over E
        assert kink.hoop_strain_angle(KI, KII, 0.0, kink.PLANE_STRESS) == \
            pytest.approx(kink.hoop_stress_angle(KI, KII), abs=ANGLE_TOL)
        # the strain criterion kinks less than the stress one for nu > 0
        if psi > 0:
            assert abs(kink.hoop_strain_angle(KI, KII, 1 / 3, kink.PLANE_STRESS)) < \
                abs(kink.hoop_stress_angle(KI, KII))


def test_hoop_strain_is_hookes_law_of_the_williams_stresses():
    E, nu, t = 1.0, 0.3, np.linspace(-3.0, 3.0, 13)
    s_rr, s_tt, _ = kink.williams_stresses(t, 0.6, 0.8)
    assert np.allclose(kink.hoop_strain(t, 0.6, 0.8, nu, kink.PLANE_STRESS), (s_tt - nu * s_rr) / E)
    s_zz = nu * (s_rr + s_tt)                 # plane strain: e_zz = 0
    assert np.allclose(kink.hoop_strain(t, 0.6, 0.8, nu, kink.PLANE_STRAIN),
                       (s_tt - nu * (s_rr + s_zz)) / E)


def test_energy_release_rate_criterion():
    assert kink.max_energy_release_angle(0.0, 1.0) == pytest.approx(MODE2_HPU, abs=0.05)
    for psi in MIXES_DEG:
        KI, KII = loads(psi)
        hpu = kink.max_energy_release_angle(KI, KII)
        # the first-order (Cotterell-Rice) K* give exactly the hoop-stress angle
        assert kink.max_energy_release_angle(KI, KII, "first-order") == \
            pytest.approx(kink.hoop_stress_angle(KI, KII), abs=1e-5)
        assert hpu <= kink.hoop_stress_angle(KI, KII) + ANGLE_TOL
        # G(0) = K_I^2 + K_II^2: a straight extension releases the parent crack's G
        assert kink.energy_release_rate(0.0, KI, KII) == pytest.approx(KI**2 + KII**2, rel=TIGHT)
        # at the maximum the kink opens and G is no smaller than straight ahead
        k1, _ = kink.kinked_sifs(math.radians(hpu), KI, KII)
        assert k1 >= 0.0
        assert kink.energy_release_rate(math.radians(hpu), KI, KII) >= KI**2 + KII**2 - TIGHT
    with pytest.raises(ValueError, match="approximation"):
        kink.kinked_sifs(0.1, 1.0, 0.0, "exact")


def test_bad_arguments():
    with pytest.raises(ValueError, match="both zero"):
        kink.hoop_stress_angle(0.0, 0.0)
    with pytest.raises(ValueError, match="closes"):
        kink.max_energy_release_angle(-1.0, 0.5)
    # faces without contact: negative K_I kinks beyond the pure-Mode-II angle, and the closed
    # form still marks the stationary tensile direction
    t = kink.hoop_stress_angle(-0.4, 1.0, closed=True)
    assert t < kink.hoop_stress_angle(0.0, 1.0)
    _, s_tt, s_rt = kink.williams_stresses(math.radians(t), -0.4, 1.0)
    assert abs(s_rt) < TIGHT and s_tt > 0.0
    assert kink.hoop_strain_angle(-0.4, 1.0, 0.0, kink.PLANE_STRESS, closed=True) == \
        pytest.approx(t, abs=ANGLE_TOL)
    with pytest.raises(ValueError, match="plane"):
        kink.hoop_strain_angle(1.0, 1.0, 0.3, "3d")
    with pytest.raises(ValueError, match="Poisson"):
        kink.hoop_strain_angle(1.0, 1.0, 0.5, kink.PLANE_STRESS)


@pytest.mark.parametrize("plane", kink.PLANES)
def test_williams_displacement_gives_the_williams_stresses(plane):
    """Strains of the displacement field by central differences, through Hooke's law, equal the
    closed-form near-tip stresses (rotated to Cartesian); the crack faces are traction-free and
    open by the textbook amount."""
    mu, nu, KI, KII = 3.0, kink.BBPD_POISSON[plane], 0.7, -0.4
    lam = 2 * mu * nu / (1 - 2 * nu) if plane == kink.PLANE_STRAIN else 2 * mu * nu / (1 - nu)
    h = 1e-6
    r = 0.37
    for t in np.linspace(-2.9, 2.9, 11):
        x, y = r * math.cos(t), r * math.sin(t)
        dux = [(np.subtract(*kink.williams_displacement([x + h, x - h], [y, y], KI, KII, mu, nu, plane)[k])) / (2 * h)
               for k in (0, 1)]
        duy = [(np.subtract(*kink.williams_displacement([x, x], [y + h, y - h], KI, KII, mu, nu, plane)[k])) / (2 * h)
               for k in (0, 1)]
        exx, eyy, exy = dux[0], duy[1], 0.5 * (duy[0] + dux[1])
        sxx = lam * (exx + eyy) + 2 * mu * exx
        syy = lam * (exx + eyy) + 2 * mu * eyy
        sxy = 2 * mu * exy
        s_rr, s_tt, s_rt = np.array(kink.williams_stresses(t, KI, KII)) / math.sqrt(2 * math.pi * r)
        c, s = math.cos(t), math.sin(t)
        assert sxx == pytest.approx(s_rr * c * c + s_tt * s * s - 2 * s_rt * s * c, abs=1e-6)
        assert syy == pytest.approx(s_rr * s * s + s_tt * c * c + 2 * s_rt * s * c, abs=1e-6)
        assert sxy == pytest.approx((s_rr - s_tt) * s * c + s_rt * (c * c - s * s), abs=1e-6)
    # traction-free faces
    for face in (math.pi, -math.pi):
        _, s_tt, s_rt = kink.williams_stresses(face, KI, KII)
        assert abs(s_tt) < TIGHT and abs(s_rt) < TIGHT
    # face opening and sliding: (kappa + 1) K/mu sqrt(r/(2 pi))
    kappa = kink.kolosov(nu, plane)
    up = kink.williams_displacement(-r, 1e-300, KI, KII, mu, nu, plane)
    lo = kink.williams_displacement(-r, -1e-300, KI, KII, mu, nu, plane)
    scale = (kappa + 1) / mu * math.sqrt(r / (2 * math.pi))
    assert up[1] - lo[1] == pytest.approx(scale * KI, rel=TIGHT)
    assert up[0] - lo[0] == pytest.approx(scale * KII, rel=TIGHT)


def test_mixity_and_criteria_table():
    assert kink.mixity_angle(1.0, 0.0) == 0.0
    assert kink.mixity_angle(0.0, 2.0) == 90.0
    angles = kink.criteria_angles(0.0, 1.0)
    assert angles["hoop_stress"] < angles["hoop_strain"] < 0.0
    assert angles["energy"] < angles["hoop_stress"]


# ---------------------------------------------------------------- crack path from a damage field
def synthetic_crack(alpha, kink_deg, dx=1.0, n=60, width=0.8):
    """Square grid with damage 0.5 on the atoms within `width` dx of a notch from the left edge
    to the tip at the origin (direction alpha) and of a straight kink at kink_deg from it, and
    an unconnected damaged blob."""
    g = (np.arange(-n, n) + 0.5) * dx
    x, y = (a.ravel() for a in np.meshgrid(g, g))
    xt, yt = crack_path.tip_frame(x, y, (0.0, 0.0), alpha)
    notch = (xt <= 0) & (np.abs(yt) <= width * dx)
    k = math.radians(kink_deg)
    along = xt * math.cos(k) + yt * math.sin(k)
    across = -xt * math.sin(k) + yt * math.cos(k)
    branch = (along >= 0) & (along <= 30 * dx) & (np.abs(across) <= width * dx)
    blob = np.hypot(x - 40 * dx, y - 40 * dx) < 3 * dx
    return x, y, np.where(notch | branch | blob, 0.5, 0.1)


@pytest.mark.parametrize("alpha", [0.0, 22.5])
@pytest.mark.parametrize("kink_deg", [-63.6, -30.0, 0.0, 20.0])
def test_kink_angle_of_a_synthetic_crack(alpha, kink_deg):
    x, y, phi = synthetic_crack(alpha, kink_deg)
    res = crack_path.kink_angles(x, y, phi, (0.0, 0.0), alpha, 1.0, (10.0, 20.0), seed=5.0)
    for d in (10.0, 20.0):
        angle, spread, count = res[d]
        assert angle == pytest.approx(kink_deg, abs=1.5), (d, res)   # grid rounding of the band
        assert spread < 6.0 and count >= 2
    assert res["extension"] == pytest.approx(30.0, abs=1.5)


def test_unconnected_damage_and_no_crack():
    x, y, phi = synthetic_crack(0.0, -45.0)
    mask = crack_path.grown_crack(x, y, phi, (0.0, 0.0), 1.0, seed=5.0)
    assert not mask[np.hypot(x - 40, y - 40) < 3].any()          # the blob is not the crack
    res = crack_path.kink_angles(x, y, np.zeros_like(x), (0.0, 0.0), 0.0, 1.0, (10.0,), seed=5.0)
    assert res[10.0] is None and res["extension"] == 0.0


def test_branched_crack_shows_in_the_spread():
    x, y, a = synthetic_crack(0.0, -40.0)
    _, _, b = synthetic_crack(0.0, 40.0)
    res = crack_path.kink_angles(x, y, np.maximum(a, b), (0.0, 0.0), 0.0, 1.0, (15.0,), seed=5.0)
    assert res[15.0][1] > 30.0


def test_readme_markers_are_replaced_in_place():
    """Several tables share the end marker: each body goes between its own pair."""
    from bbpd import markers
    text = ("a\n<!-- bbpd:table kink -->\nold1\n<!-- /bbpd:table -->\nb\n"
            "<!-- bbpd:table kink-kw -->\nold2\n<!-- /bbpd:table -->\nc\n")
    new = {"kink": "new1", "kink-kw": "new2"}
    out = markers.replace("README.md", text, lambda kind, name: new.get(name))
    assert out == text.replace("old1", "new1").replace("old2", "new2")
    assert markers.replace("README.md", out, lambda kind, name: new.get(name)) == out
