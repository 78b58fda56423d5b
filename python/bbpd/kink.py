# SPDX-License-Identifier: GPL-2.0-or-later
"""Kink angle of a straight crack under mixed-mode loading (K_I, K_II), three criteria, and
the Williams near-tip displacement field that loads the kink test (examples/kink-mixed-mode;
its README states the criteria).

Frame and sign convention: crack-tip polar coordinates (r, theta), the tip at the origin, the
crack along the negative x axis (faces at theta = +-pi), theta counter-clockwise from +x. K_II >
0 is the usual sense (the upper face slides towards +x relative to the lower one) and kinks the
crack to NEGATIVE theta; every function returns theta_c in degrees with this sign, and
theta_c(K_I, -K_II) = -theta_c(K_I, K_II). K_I < 0 (faces pressed together) is refused unless
closed=True: then the criteria are evaluated for faces that pass through each other, as a
peridynamic notch without contact does.

(i) Maximum hoop stress (Erdogan & Sih 1963): the root of s_rt = 0 with s_tt > 0 of the leading
    Williams stresses (e.g. Anderson, Fracture Mechanics, ch. 2); pure Mode II -70.53 deg.
(ii) Maximum hoop strain: e_tt from the same stresses and Hooke's law, maximised numerically.
    Plane strain is plane stress with nu' = nu/(1 - nu), so BBPD's two Poisson ratios (1/3 in
    plane stress, 1/4 in plane strain) give the same angle: pure Mode II -63.61 deg.
(iii) Maximum energy release rate G = (K_I*^2 + K_II*^2)/E' of an infinitesimal kink, among
    the kinks that open, with K* of Hussain, Pu & Underwood 1974 ('hpu', in this module's sign
    convention, theta -> -theta against their paper): pure Mode II -75.23 deg. The exact
    kinked-crack factors (Amestoy & Leblond 1992, not coded here) put it near -77 deg, so this
    criterion is uncertain by about 2 deg. The 'first-order' factors (Cotterell & Rice 1980:
    s_tt and s_rt rotated onto the kink) give exactly the hoop-stress angle (the unit tests
    check it), so the comparison uses 'hpu'.
"""

import math

import numpy as np
from scipy.optimize import minimize_scalar

from bbpd import dsif

PLANE_STRESS = "plane/stress"
PLANE_STRAIN = "plane/strain"
PLANES = (PLANE_STRESS, PLANE_STRAIN)
# Poisson ratio implied by a bond-based model (one micromodulus: lambda = mu)
BBPD_POISSON = {PLANE_STRESS: 1.0 / 3.0, PLANE_STRAIN: 0.25}

SCAN_POINTS = 3601        # 0.1 deg scan of (-180, 180) before the bounded refinement
REFINE_XTOL = 1e-10       # rad
ENERGY_APPROXIMATIONS = ("hpu", "first-order")


def _check_plane(plane):
    if plane not in PLANES:
        raise ValueError(f"plane must be one of {PLANES}, not {plane!r}")


def _check_loads(KI, KII, closed=False):
    """closed=True admits K_I < 0: the faces of a crack without contact (a peridynamic notch
    whose faces pass through each other) still see the Williams field of negative K_I."""
    if KI == 0.0 and KII == 0.0:
        raise ValueError("K_I and K_II are both zero: no kink direction")
    if KI < 0.0 and not closed:
        raise ValueError("K_I < 0 closes the crack faces; the criteria here assume an open crack "
                         "(closed=True evaluates them for faces without contact)")


def williams_stresses(theta, KI, KII):
    """sqrt(2 pi r) (s_rr, s_tt, s_rt) of the leading Williams terms at angle theta (rad)."""
    h, t3 = 0.5 * np.asarray(theta), 1.5 * np.asarray(theta)
    s_rr = (KI * (5 * np.cos(h) - np.cos(t3)) + KII * (-5 * np.sin(h) + 3 * np.sin(t3))) / 4
    s_tt = (KI * (3 * np.cos(h) + np.cos(t3)) - 3 * KII * (np.sin(h) + np.sin(t3))) / 4
    s_rt = (KI * (np.sin(h) + np.sin(t3)) + KII * (np.cos(h) + 3 * np.cos(t3))) / 4
    return s_rr, s_tt, s_rt


def _argmax_deg(f):
    """Global maximiser of f on (-pi, pi) in degrees: a scan, then a bounded refinement."""
    t = np.linspace(-math.pi, math.pi, SCAN_POINTS)[1:-1]
    k = int(np.argmax(f(t)))
    lo, hi = t[max(k - 1, 0)], t[min(k + 1, len(t) - 1)]
    res = minimize_scalar(lambda x: -float(f(x)), bounds=(lo, hi), method="bounded",
                          options={"xatol": REFINE_XTOL})
    return math.degrees(res.x)


def hoop_stress_angle(KI, KII, closed=False):
    """Kink angle (deg) of the maximum hoop stress criterion (Erdogan & Sih 1963)."""
    _check_loads(KI, KII, closed)
    if KII == 0.0:
        return 0.0
    return math.degrees(2.0 * math.atan((KI - math.sqrt(KI**2 + 8.0 * KII**2)) / (4.0 * KII)))


def hoop_strain(theta, KI, KII, nu, plane):
    """E sqrt(2 pi r) e_tt at angle theta (rad) from the Williams stresses and Hooke's law."""
    _check_plane(plane)
    s_rr, s_tt, _ = williams_stresses(theta, KI, KII)
    if plane == PLANE_STRESS:
        return s_tt - nu * s_rr
    return (1.0 + nu) * ((1.0 - nu) * s_tt - nu * s_rr)


def hoop_strain_angle(KI, KII, nu, plane, closed=False):
    """Kink angle (deg) of the maximum hoop strain criterion for Poisson ratio nu."""
    _check_loads(KI, KII, closed)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"Poisson ratio {nu} outside (-1, 1/2)")
    if KII == 0.0:
        return 0.0
    return _argmax_deg(lambda t: hoop_strain(t, KI, KII, nu, plane))


def kinked_sifs(theta, KI, KII, approximation="hpu"):
    """(K_I*, K_II*) at the tip of an infinitesimal kink at angle theta (rad)."""
    t = np.asarray(theta, dtype=float)
    if approximation == "hpu":
        q = t / math.pi
        g = 4.0 / (3.0 + np.cos(t) ** 2) * ((1.0 - q) / (1.0 + q)) ** (q / 2.0)
        return (g * (KI * np.cos(t) - 1.5 * KII * np.sin(t)),
                g * (KII * np.cos(t) + 0.5 * KI * np.sin(t)))
    if approximation == "first-order":
        _, s_tt, s_rt = williams_stresses(t, KI, KII)
        return s_tt, s_rt
    raise ValueError(f"approximation must be one of {ENERGY_APPROXIMATIONS}")


def energy_release_rate(theta, KI, KII, approximation="hpu"):
    """E' G(theta) = K_I*^2 + K_II*^2 of a kink at angle theta (rad)."""
    k1, k2 = kinked_sifs(theta, KI, KII, approximation)
    return k1**2 + k2**2


def max_energy_release_angle(KI, KII, approximation="hpu", closed=False):
    """Kink angle (deg) of the maximum energy release rate criterion, among the kinks that
    open (K_I* > 0; for pure Mode II, G is even in theta and this picks the opening side)."""
    _check_loads(KI, KII, closed)
    if KII == 0.0:
        return 0.0

    def opening_g(t):
        k1, k2 = kinked_sifs(t, KI, KII, approximation)
        return np.where(k1 > 0.0, k1**2 + k2**2, -1.0)
    return _argmax_deg(opening_g)


def criteria_angles(KI, KII, nu=BBPD_POISSON[PLANE_STRESS], plane=PLANE_STRESS, closed=False):
    """The three criteria's angles (deg) for one mix: {'hoop_stress', 'hoop_strain', 'energy'}."""
    return {"hoop_stress": hoop_stress_angle(KI, KII, closed),
            "hoop_strain": hoop_strain_angle(KI, KII, nu, plane, closed),
            "energy": max_energy_release_angle(KI, KII, closed=closed)}


def kolosov(nu, plane):
    """kappa: 3 - 4 nu in plane strain, (3 - nu)/(1 + nu) in plane stress."""
    _check_plane(plane)
    return 3.0 - 4.0 * nu if plane == PLANE_STRAIN else (3.0 - nu) / (1.0 + nu)


def williams_displacement(x, y, KI, KII, mu, nu, plane):
    """Leading-term displacement (u_x, u_y) at (x, y) in the crack-tip frame (tip at the
    origin, crack along -x): bbpd.dsif.williams_displacement at r, theta of (x, y)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return dsif.williams_displacement(KI, KII, np.hypot(x, y), np.arctan2(y, x), mu,
                                      kolosov(nu, plane))


def mixity_angle(KI, KII):
    """Mode-mix angle psi = arctan(K_II/K_I) in degrees: 0 pure Mode I, 90 pure Mode II."""
    return math.degrees(math.atan2(KII, KI))
