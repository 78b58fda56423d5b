# SPDX-License-Identifier: GPL-2.0-or-later
"""Analytic dynamic stress intensity factors (DSIFs) for the benchmarks of
section 4.2 of the paper (kernel-bbpd-dynamic-fracture.md).

All solutions are for a *stationary semi-infinite* crack in an unbounded
linear elastic body that is loaded, from time zero, by uniform crack-face
tractions.  This is the same problem as a plane stress wave whose front is
parallel to the crack plane and which reaches the crack plane at time zero
(scattering decomposition; Freund, *Dynamic Fracture Mechanics*, CUP 1990,
ch. 2, suddenly applied crack-face pressure): the crack faces must cancel
the traction that the incident wave carries across the crack plane.

Mode I (paper eqs. 41-43)
    Step load of amplitude sigma (Freund 1990, ch. 2; the paper's ref. [21])::

        K_I(t) = 2 sigma sqrt(C_d t (1 - 2 nu) / pi) / (1 - nu)

    and the ramp load of eq. 41 gives eq. 42 (Duhamel integral of the step).
    The factor sqrt(1 - 2 nu)/(1 - nu) is the *plane-strain* form and C_d is
    the plane-strain (= 3D) dilatational speed sqrt(E(1-nu)/(rho(1+nu)(1-2nu))).
    For plane stress, use the equivalent Poisson ratio nu/(1+nu) together with
    the plane-stress C_d (see :func:`equivalent_plane_stress_poisson`), or use
    the wave-speed form :func:`mode1_step_dsif_wave_speeds`, which holds for
    both plane conditions.

Mode II (independent reference for section 4.2.2)
    Step load of amplitude tau (shear traction carried by the incident plane
    shear wave across the crack plane)::

        K_II(t) = 4 tau sqrt(c_s t / pi) sqrt(1 - c_s^2 / c_d^2)
                = 2 tau sqrt(2 c_s t / (pi (1 - nu)))        (plane strain)

    Derivation (Wiener-Hopf, as Freund 1990 does for mode I): on y = 0 the
    Laplace/two-sided-Laplace transforms satisfy
    Sigma_yy = -mu s R(z)/(b^2 alpha) U_y (mode I) and
    Sigma_xy = -mu s R(z)/(b^2 beta) U_x (mode II), with slownesses a = 1/c_d,
    b = 1/c_s, alpha = sqrt(a^2 - z^2), beta = sqrt(b^2 - z^2) and
    R = (b^2 - 2 z^2)^2 + 4 z^2 alpha beta = 2 (b^2 - a^2)(c^2 - z^2) S(z).
    Factorising and applying the Abelian theorem gives
    K = 4 tau sqrt(t/pi) sqrt(b^2 - a^2) sqrt(w) / b^2, with w = a (mode I) or
    w = b (mode II).  With w = a this reproduces Freund's mode-I result above
    exactly; the same steps with kernel mu s beta reproduce Freund's mode-III
    result K_III = 2 tau sqrt(2 c_s t / pi).  The ramp version follows from the
    Duhamel integral, exactly as eq. 42 follows from the mode-I step.
"""

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

PLANE_STRAIN = "plane_strain"
PLANE_STRESS = "plane_stress"
THREE_D = "3d"
CONDITIONS = (PLANE_STRAIN, PLANE_STRESS, THREE_D)

POISSON_MIN = -1.0  # exclusive thermodynamic bounds on nu
POISSON_MAX = 0.5
RAMP_EXPONENT = 1.5  # t^(3/2) in eq. 42
RAMP_PREFACTOR = 4.0 / (3.0 * np.pi)  # 4/(3 pi) in eq. 42
STEP_PREFACTOR = 2.0  # 2 sigma sqrt(...) in Freund's step solution
DUHAMEL_SQRT_FACTOR = 2.0 / 3.0  # integral of sqrt(s) ds = (2/3) s^(3/2)
MODE2_PREFACTOR = 4.0  # 4 tau sqrt(c_s t/pi) sqrt(1 - c_s^2/c_d^2)
MODE1_VALIDITY_MULTIPLE = 3.0  # paper: valid for t <= 3 t_c
# Rayleigh root xi = c_R/c_s lies in (0.87, 0.96) for 0 <= nu <= 0.5 and the
# Rayleigh function is negative on (0, xi) and positive at xi = 1.
RAYLEIGH_BRACKET_LOW = 0.5
RAYLEIGH_BRACKET_HIGH = 1.0
ALLOWED_LOADED_EDGES = (1, 2)  # see crack_plane_amplitude


def _check_positive(**values):
    for name, value in values.items():
        if not np.isfinite(value) or value <= 0.0:
            raise ValueError(f"{name} must be finite and > 0, got {value!r}")


def _check_poisson(nu):
    if not np.isfinite(nu) or not POISSON_MIN < nu < POISSON_MAX:
        raise ValueError(f"Poisson ratio must lie in (-1, 0.5), got {nu!r}")


def _as_time(t):
    arr = np.asarray(t, dtype=float)
    if np.any(np.isnan(arr)):
        raise ValueError("time contains NaN")
    return arr


def _same_kind(template, value):
    """Return a float for scalar input, an array otherwise."""
    return float(value) if np.ndim(template) == 0 else value


def dilatational_wave_speed(E, nu, rho, condition=PLANE_STRAIN):
    """Dilatational (longitudinal) wave speed C_d.

    plane strain and 3D: sqrt(E (1 - nu) / (rho (1 + nu)(1 - 2 nu)));
    plane stress:        sqrt(E / (rho (1 - nu^2))).
    Eq. 42 uses the plane-strain/3D value (Freund's solution is plane strain).
    """
    _check_positive(E=E, rho=rho)
    _check_poisson(nu)
    if condition in (PLANE_STRAIN, THREE_D):
        return float(np.sqrt(E * (1.0 - nu) / (rho * (1.0 + nu) * (1.0 - 2.0 * nu))))
    if condition == PLANE_STRESS:
        return float(np.sqrt(E / (rho * (1.0 - nu * nu))))
    raise ValueError(f"condition must be one of {CONDITIONS}, got {condition!r}")


def shear_wave_speed(E, nu, rho):
    """Shear wave speed c_s = sqrt(mu/rho), mu = E / (2 (1 + nu))."""
    _check_positive(E=E, rho=rho)
    _check_poisson(nu)
    return float(np.sqrt(E / (2.0 * (1.0 + nu) * rho)))


def rayleigh_wave_speed(c_s, c_d):
    """Rayleigh wave speed from (2 - xi^2)^2 = 4 sqrt(1 - xi^2) sqrt(1 - k^2 xi^2),
    xi = c_R/c_s, k = c_s/c_d (valid for either plane condition)."""
    _check_positive(c_s=c_s, c_d=c_d)
    if c_s >= c_d:
        raise ValueError("shear speed must be smaller than dilatational speed")
    k2 = (c_s / c_d) ** 2

    def rayleigh(xi):
        x2 = xi * xi
        return (2.0 - x2) ** 2 - 4.0 * np.sqrt(1.0 - x2) * np.sqrt(1.0 - k2 * x2)

    return float(c_s * brentq(rayleigh, RAYLEIGH_BRACKET_LOW, RAYLEIGH_BRACKET_HIGH,
                              xtol=1e-15, rtol=1e-15))


def equivalent_plane_stress_poisson(nu):
    """Poisson ratio nu/(1+nu) that maps plane-stress elastodynamics onto the
    plane-strain equations (use it in eqs. 42/step with the plane-stress C_d)."""
    _check_poisson(nu)
    return nu / (1.0 + nu)


def crack_plane_amplitude(edge_traction, loaded_edges):
    """Traction carried across the crack plane by the incident field(s).

    One loaded edge (wave from one side, Freund's incident-wave problem):
    the amplitude equals the edge traction.  Two edges equidistant from the
    crack plane and loaded symmetrically (+-sigma or +-tau, as needed for
    equilibrium of a free plate): both plane waves reach the crack plane at
    the same instant and superpose, so the crack faces see twice the edge
    traction until the waves reflect.  Eq. 42 is written for the single-wave
    amplitude sigma0; check which case a model realises before comparing.
    """
    if loaded_edges not in ALLOWED_LOADED_EDGES:
        raise ValueError(f"loaded_edges must be one of {ALLOWED_LOADED_EDGES}")
    return float(edge_traction) * loaded_edges


def crack_arrival_time(H, c_d):
    """t_c = H / C_d: time for the longitudinal wave to reach the crack (eq. 42)."""
    _check_positive(c_d=c_d)
    if not np.isfinite(H) or H < 0.0:
        raise ValueError(f"H must be finite and >= 0, got {H!r}")
    return H / c_d


def mode1_validity_end(H, c_d):
    """Latest time 3 t_c at which eq. 42 is valid (reflection from the far edge)."""
    return MODE1_VALIDITY_MULTIPLE * crack_arrival_time(H, c_d)


def _mode1_factor(nu):
    """sqrt(1 - 2 nu)/(1 - nu): the plane-strain factor of eq. 42."""
    _check_poisson(nu)
    return np.sqrt(1.0 - 2.0 * nu) / (1.0 - nu)


def mode1_step_dsif(t, nu, sigma0, c_d, H):
    """Freund's mode-I DSIF for a step load sigma0 (plane strain), with
    t_bar = t - H/C_d; zero before the wave reaches the crack."""
    _check_positive(c_d=c_d)
    t_bar = _as_time(t) - crack_arrival_time(H, c_d)
    t_pos = np.clip(t_bar, 0.0, None)
    value = STEP_PREFACTOR * sigma0 * _mode1_factor(nu) * np.sqrt(c_d * t_pos / np.pi)
    return _same_kind(t, value)


def mode1_ramp_dsif(t, nu, sigma0, c_d, t_d, H):
    """Mode-I DSIF of eq. 42 for the ramp load of eq. 41 (plane strain C_d),
    with t_bar = t - t_c, t_c = H/C_d; zero for t_bar < 0."""
    _check_positive(c_d=c_d, t_d=t_d)
    t_bar = _as_time(t) - crack_arrival_time(H, c_d)
    x = np.clip(t_bar / t_d, 0.0, None)
    bracket = x ** RAMP_EXPONENT - np.clip(x - 1.0, 0.0, None) ** RAMP_EXPONENT
    value = (RAMP_PREFACTOR * _mode1_factor(nu) * sigma0
             * np.sqrt(np.pi * c_d * t_d) * bracket)
    return _same_kind(t, value)


def normalised_mode1(K, sigma0, H):
    """Eq. 43: K_I / (sigma0 sqrt(H))."""
    _check_positive(H=H)
    if sigma0 == 0.0:
        raise ValueError("sigma0 must be non-zero")
    return np.asarray(K, dtype=float) / (sigma0 * np.sqrt(H))


def _speed_ratio_factor(c_s, c_d):
    _check_positive(c_s=c_s, c_d=c_d)
    if c_s >= c_d:
        raise ValueError("shear speed must be smaller than dilatational speed")
    return np.sqrt(1.0 - (c_s / c_d) ** 2)


def mode1_step_dsif_wave_speeds(t_bar, sigma, c_s, c_d):
    """Mode-I step DSIF written with wave speeds (any plane condition):
    K_I = 4 sigma sqrt(c_d t/pi) (c_s/c_d) sqrt(1 - c_s^2/c_d^2), t = t_bar >= 0.
    Equal to Freund's nu-form in plane strain."""
    factor = _speed_ratio_factor(c_s, c_d)
    t_pos = np.clip(_as_time(t_bar), 0.0, None)
    value = (MODE2_PREFACTOR * sigma * np.sqrt(c_d * t_pos / np.pi)
             * (c_s / c_d) * factor)
    return _same_kind(t_bar, value)


def mode2_step_dsif(t_bar, tau, c_s, c_d):
    """Mode-II DSIF of a semi-infinite crack, crack faces suddenly loaded by
    uniform shear tau at t_bar = 0 (derivation in the module docstring);
    tau is the shear stress the incident field carries across the crack
    plane (see :func:`crack_plane_amplitude`):
    K_II = 4 tau sqrt(c_s t_bar / pi) sqrt(1 - c_s^2/c_d^2); zero for t_bar < 0.
    Use the plane-stress or plane-strain c_d matching the model."""
    factor = _speed_ratio_factor(c_s, c_d)
    t_pos = np.clip(_as_time(t_bar), 0.0, None)
    value = MODE2_PREFACTOR * tau * np.sqrt(c_s * t_pos / np.pi) * factor
    return _same_kind(t_bar, value)


def mode2_ramp_dsif(t_bar, tau, c_s, c_d, t_d):
    """Mode-II DSIF for the ramp tau * min(t_bar/t_d, 1) (Duhamel integral of
    :func:`mode2_step_dsif`): with K_step = A sqrt(t),
    K = A (2/3) [t^(3/2) - (t - t_d)_+^(3/2)] / t_d."""
    _check_positive(t_d=t_d)
    factor = _speed_ratio_factor(c_s, c_d)
    t_pos = np.clip(_as_time(t_bar), 0.0, None)
    coeff = MODE2_PREFACTOR * tau * np.sqrt(c_s / np.pi) * factor
    bracket = (t_pos ** RAMP_EXPONENT
               - np.clip(t_pos - t_d, 0.0, None) ** RAMP_EXPONENT)
    value = coeff * DUHAMEL_SQRT_FACTOR * bracket / t_d
    return _same_kind(t_bar, value)


def normalised_mode2(K, tau, a):
    """Section 4.2.2 normalisation: K_II / (tau sqrt(pi a))."""
    _check_positive(a=a)
    if tau == 0.0:
        raise ValueError("tau must be non-zero")
    return np.asarray(K, dtype=float) / (tau * np.sqrt(np.pi * a))


@dataclass(frozen=True)
class ModeIIWindow:
    """Times (from load application) bounding the semi-infinite-crack reference
    for a central crack 2a in a plate of half-height h and half-length l whose
    edges y = +-h carry a suddenly applied uniform shear traction.

    t_start           incident plane S wave reaches the crack plane: h/c_s.
    t_other_tip       P wave diffracted at the opposite tip arrives:
                      t_start + 2a/c_d (2a/c_R for the Rayleigh wave).
    t_edge_reflection P wave diffracted at this tip returns from the loaded
                      edge: t_start + 2h/c_d (the paper's "3 t_c" analogue).
    t_corner          P wave from a corner (l, h) of the loaded edge, emitted at
                      t = 0: sqrt((l - a)^2 + h^2)/c_d.
    """

    t_start: float
    t_other_tip: float
    t_other_tip_rayleigh: float
    t_edge_reflection: float
    t_corner: float

    @property
    def t_end(self):
        """Strict end: first arrival of any wave not in the reference problem."""
        return min(self.t_other_tip, self.t_edge_reflection, self.t_corner)

    @property
    def t_end_ignoring_corners(self):
        """End if the weak cylindrical corner waves are neglected."""
        return min(self.t_other_tip, self.t_edge_reflection)


def mode2_validity_window(h, a, half_length, c_s, c_d):
    """Validity window of :func:`mode2_step_dsif` for the central-crack plate
    (paper: L = 104 mm, H = 40 mm, 2a = 24 mm -> h = 20 mm, l = 52 mm, a = 12 mm)."""
    _check_positive(h=h, a=a, half_length=half_length)
    if a >= half_length:
        raise ValueError("crack half-length must be smaller than the plate half-length")
    c_r = rayleigh_wave_speed(c_s, c_d)
    t_start = h / c_s
    return ModeIIWindow(
        t_start=t_start,
        t_other_tip=t_start + 2.0 * a / c_d,
        t_other_tip_rayleigh=t_start + 2.0 * a / c_r,
        t_edge_reflection=t_start + 2.0 * h / c_d,
        t_corner=float(np.hypot(half_length - a, h)) / c_d,
    )
