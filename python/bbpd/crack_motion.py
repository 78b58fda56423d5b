# SPDX-License-Identifier: GPL-2.0-or-later
"""Mode-I crack growth under stress-wave loading: Freund's equation of motion.

Problem: the semi-infinite crack of :mod:`bbpd.freund` (tip at x = a, faces y = 0, x < a)
hit at t_c = H/C_d by a plane tensile wave whose front is parallel to the crack plane
(paper eqs. 41-42).  The crack is stationary until the initiation time t_i and then runs
along y = 0 with tip position l(t), speed v = dl/dt >= 0.

Stationary SIF of a crack at l, K*(t, l)
    The incident wave loads every point of the crack plane at the same instant t_c, so the
    scattered problem (crack faces x < l loaded by -sigma(t - t_c)) is invariant under a
    shift of x: a crack that "has always been at l" has the same SIF as the one at a,
    K*(t, l) = K_I(t) of eq. 42, whatever l.  Exact for the unbounded body; in the plate of
    the benchmark until the waves reflected from the edges reach the tip (t <= 3 t_c for
    the edge opposite the loaded one).

Equation of motion (Freund 1990, Dynamic Fracture Mechanics, ch. 7; Freund 1973,
J. Mech. Phys. Solids 21, 47-61)
    For any non-decreasing l(t) the dynamic SIF is K_I(t) = k(v) K*(t, l(t)): exact for the
    semi-infinite crack in an unbounded body, with k(v) a universal function of the speed
    (k(0) = 1, k(c_R) = 0).  Approximate: we use Freund's closed form
    k(v) ~ (1 - v/c_R) / sqrt(1 - v/c_d) of the exact k(v), 0 <= v <= c_R.  The energy release rate is G = A(v) K_I^2 / E' with
    A(v) k(v)^2 = g(v) ~ 1 - v/c_R.  Two growth criteria:

    toughness   K_I = K_Ic:     k(v) K* = K_Ic, solved in closed form (quadratic in v);
    energy      G = G_c:        g(v) K*^2 / E' = G_c, i.e. v = c_R (1 - K_Ic^2 / K*^2),
                                Freund's form (the rate-independent fracture energy that
                                bond breaking dissipates in BBPD).

    kinetic     G = G_run(v):   g(v) K*^2 / E' = G_c gamma(v/c_R), a fracture energy that
                                rises with speed as the model's own kinetic law, measured
                                in the steady strip (bbpd.benchmarks.strip; KineticLaw).

    with K_Ic = sqrt(E' G_c), E' = E (plane stress) or E/(1 - nu^2) (plane strain).
    Both give v = 0 while K* <= K_Ic and v -> c_R as K* -> infinity.  The ODE
    dl/dt = v(K*(t, l)) is integrated with scipy from (t_i, l = a); for this loading the
    right-hand side does not depend on l, so l(t) = a + integral of v(t).

Step load, K* = A sqrt(t - t_0) (closed forms, used by the tests): t_i = t_0 + (K_Ic/A)^2;
energy criterion: v = c_R (1 - s_i/s), l = a + c_R (s - s_i - s_i ln(s/s_i)) with
s = t - t_0, s_i = t_i - t_0.
"""

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from bbpd import freund

TOUGHNESS = "toughness"
ENERGY = "energy"
KINETIC = "kinetic"
CRITERIA = (TOUGHNESS, ENERGY)    # the two constant-toughness forms; KINETIC takes a law
ODE_RTOL = 1e-10    # the right-hand side is smooth after t_i: tight tolerances are cheap
ODE_ATOL_FRACTION = 1e-12   # absolute tolerance on l, as a fraction of c_R (t_end - t_i)
DENSE_POINTS = 4001   # samples of l(t) for interpolation
ROOT_XTOL = 1e-15   # brentq, relative to the time scale


def _check_speeds(c_r, c_d):
    freund._check_positive(c_r=c_r, c_d=c_d)
    if c_r >= c_d:
        raise ValueError("Rayleigh speed must be smaller than the dilatational speed")


def _check_criterion(criterion, law=None):
    if criterion not in CRITERIA + (KINETIC,):
        raise ValueError(f"criterion must be one of {CRITERIA + (KINETIC,)}, got {criterion!r}")
    if (criterion == KINETIC) != (law is not None):
        raise ValueError("the kinetic criterion, and it alone, takes a law (KineticLaw)")


class KineticLaw:
    """G_run/G_c against u = v/c_R: the energy release rate a crack needs to run at speed v,
    over G_c. Piecewise linear through (0, 1) (a crack at rest starts at G_c) and the
    measured points (u_i, g_i), constant beyond the last; it must not decrease (a steady
    state with G_run falling with speed is unstable, and the root below would not be unique)."""

    def __init__(self, u, g):
        u, g = np.asarray(u, dtype=float), np.asarray(g, dtype=float)
        if u.size == 0 or u.shape != g.shape:
            raise ValueError("a kinetic law needs matching, non-empty speeds and values")
        order = np.argsort(u)
        self.u = np.concatenate(([0.0], u[order]))
        self.g = np.concatenate(([1.0], g[order]))
        if np.any(self.u < 0.0) or np.any(self.u >= 1.0) or np.any(np.diff(self.u) <= 0.0):
            raise ValueError("kinetic-law speeds must be distinct and lie in (0, c_R)")
        if np.any(np.diff(self.g) < 0.0):
            raise ValueError("a kinetic law must not decrease with speed")

    def __call__(self, u):
        return np.interp(u, self.u, self.g)


def _kinetic_speed(ratio_sq, law):
    """u in [0, 1) with (1 - u) (K*/K_Ic)^2 = law(u); 0 where (K*/K_Ic)^2 <= 1"""
    if ratio_sq <= 1.0:
        return 0.0
    return brentq(lambda u: (1.0 - u) * ratio_sq - law(u), 0.0, 1.0, xtol=ROOT_XTOL)


def effective_modulus(E, nu, condition):
    """E' = E (plane stress) or E / (1 - nu^2) (plane strain, 3D)."""
    freund._check_positive(E=E)
    freund._check_poisson(nu)
    if condition == freund.PLANE_STRESS:
        return float(E)
    if condition in (freund.PLANE_STRAIN, freund.THREE_D):
        return float(E / (1.0 - nu * nu))
    raise ValueError(f"condition must be one of {freund.CONDITIONS}, got {condition!r}")


def fracture_toughness(E, nu, G_c, condition):
    """K_Ic = sqrt(E' G_c) (Irwin)."""
    freund._check_positive(G_c=G_c)
    return float(np.sqrt(effective_modulus(E, nu, condition) * G_c))


def universal_k(v, c_r, c_d):
    """Freund's approximation of the universal function k(v) = (1 - v/c_R)/sqrt(1 - v/c_d),
    0 <= v <= c_R; k(0) = 1, k(c_R) = 0."""
    _check_speeds(c_r, c_d)
    arr = np.asarray(v, dtype=float)
    if np.any(arr < 0.0) or np.any(arr > c_r):
        raise ValueError("crack speed must lie in [0, c_R]")
    return freund._same_kind(v, (1.0 - arr / c_r) / np.sqrt(1.0 - arr / c_d))


def energy_factor(v, c_r):
    """g(v) = A(v) k(v)^2 ~ 1 - v/c_R: G = g(v) G* (Freund 1990, ch. 7)."""
    freund._check_positive(c_r=c_r)
    arr = np.asarray(v, dtype=float)
    if np.any(arr < 0.0) or np.any(arr > c_r):
        raise ValueError("crack speed must lie in [0, c_R]")
    return freund._same_kind(v, 1.0 - arr / c_r)


def crack_speed(k_star, k_ic, c_r, c_d, criterion=TOUGHNESS, law=None):
    """Speed v at which the running crack meets the criterion, given the stationary SIF K*.

    toughness: k(v) K* = K_Ic.  With u = v/c_R, beta = c_R/c_d, r = K_Ic/K*:
    (1 - u)^2 = r^2 (1 - beta u), whose root in [0, 1] is
    u = [(2 - r^2 beta) - r sqrt(4 (1 - beta) + r^2 beta^2)] / 2.
    energy: (1 - u) K*^2 = K_Ic^2, u = 1 - r^2.
    kinetic: (1 - u) K*^2 = K_Ic^2 law(u), the root in [0, 1) (brentq).
    v = 0 wherever K* <= K_Ic (the crack does not move)."""
    _check_speeds(c_r, c_d)
    _check_criterion(criterion, law)
    freund._check_positive(k_ic=k_ic)
    ks = np.asarray(k_star, dtype=float)
    if criterion == KINETIC:
        u = np.vectorize(lambda k: _kinetic_speed((k / k_ic) ** 2, law))(ks)
        return freund._same_kind(k_star, c_r * u)
    running = ks > k_ic
    r = np.where(running, k_ic / np.where(running, ks, 1.0), 1.0)
    if criterion == ENERGY:
        u = 1.0 - r * r
    else:
        beta = c_r / c_d
        u = 0.5 * ((2.0 - r * r * beta) - r * np.sqrt(4.0 * (1.0 - beta) + r * r * beta * beta))
    u = np.where(running, np.clip(u, 0.0, 1.0), 0.0)
    return freund._same_kind(k_star, c_r * u)


def initiation_time(k_star, k_ic, t_start, t_end):
    """First t in (t_start, t_end] with K*(t) = K_Ic, for a K* that is zero at t_start and
    rises; None if K* stays below K_Ic up to t_end.  K* is sampled to bracket the first
    crossing and the root refined with brentq."""
    freund._check_positive(k_ic=k_ic)
    if not t_end > t_start:
        raise ValueError("t_end must be larger than t_start")
    samples = np.linspace(t_start, t_end, 2001)
    above = np.nonzero(np.asarray(k_star(samples)) >= k_ic)[0]
    if above.size == 0:
        return None
    j = above[0]
    if j == 0:
        return float(t_start)
    return float(brentq(lambda t: k_star(t) - k_ic, samples[j - 1], samples[j],
                        xtol=ROOT_XTOL * (t_end - t_start)))


def ramp_initiation_time(k_ic, nu_eq, sigma0, c_d, t_d, H):
    """t_i for the ramp load of eq. 41 in closed form when it falls inside the ramp
    (t_i - t_c <= t_d), where eq. 42 is K = C x^(3/2), x = (t - t_c)/t_d,
    C = 4/(3 pi) f(nu) sigma0 sqrt(pi c_d t_d): t_i = t_c + t_d (K_Ic/C)^(2/3).
    Later (K_Ic > C) the root of eq. 42 is found numerically."""
    amplitude = float(freund.mode1_ramp_dsif(freund.crack_arrival_time(H, c_d) + t_d,
                                             nu_eq, sigma0, c_d, t_d, H))
    t_c = freund.crack_arrival_time(H, c_d)
    if k_ic <= amplitude:
        return t_c + t_d * (k_ic / amplitude) ** (2.0 / 3.0)

    def k_star(t):
        return freund.mode1_ramp_dsif(t, nu_eq, sigma0, c_d, t_d, H)

    t_hi = t_c + t_d
    while k_star(t_hi) < k_ic:   # K grows like sqrt(t) after the ramp: doubling brackets it
        t_hi = t_c + 2.0 * (t_hi - t_c)
    return float(brentq(lambda t: k_star(t) - k_ic, t_c + t_d, t_hi,
                        xtol=ROOT_XTOL * (t_hi - t_c)))


def tip_history(k_star, k_ic, c_r, c_d, l0, t_i, t_end, criterion=TOUGHNESS, t_eval=None,
                law=None):
    """Integrate dl/dt = v(K*(t, l)) from l(t_i) = l0 to t_end.

    k_star(t, l): stationary SIF of a crack with its tip at l (for the plane wave parallel
    to the crack plane it does not depend on l, see the module docstring).
    Returns (t, l, v) arrays at t_eval (default: 400 points over [t_i, t_end])."""
    _check_criterion(criterion, law)
    if not t_end > t_i:
        raise ValueError("t_end must be larger than t_i")
    if t_eval is None:
        t_eval = np.linspace(t_i, t_end, 400)
    t_eval = np.asarray(t_eval, dtype=float)

    def rhs(t, y):
        return [crack_speed(k_star(t, y[0]), k_ic, c_r, c_d, criterion, law)]

    sol = solve_ivp(rhs, (t_i, t_end), [l0], t_eval=t_eval, rtol=ODE_RTOL,
                    atol=ODE_ATOL_FRACTION * c_r * (t_end - t_i), method="DOP853")
    if not sol.success:
        raise RuntimeError(f"crack-tip ODE failed: {sol.message}")
    l = sol.y[0]
    v = np.array([crack_speed(k_star(t, x), k_ic, c_r, c_d, criterion, law)
                  for t, x in zip(sol.t, l)])
    return sol.t, l, v


def step_energy_history(t, t0, t_i, l0, c_r):
    """Closed form for K* = A sqrt(t - t0) and the energy criterion (t >= t_i):
    v = c_R (1 - s_i/s), l = l0 + c_R (s - s_i - s_i ln(s/s_i)), s = t - t0."""
    s = np.asarray(t, dtype=float) - t0
    s_i = t_i - t0
    if np.any(s < s_i):
        raise ValueError("times must not precede t_i")
    v = c_r * (1.0 - s_i / s)
    l = l0 + c_r * (s - s_i - s_i * np.log(s / s_i))
    return l, v


class RampProblem:
    """The benchmark's loading: eq. 42 with (nu_eq, C_d) of the model, K_Ic from G_c.

    nu_eq is the Poisson ratio of the plane-strain equations that the model's in-plane
    equations equal (nu/(1+nu) in plane stress); c_d, c_s, c_r are the model's speeds."""

    def __init__(self, E, nu, rho, G_c, sigma0, t_d, H, a, condition):
        self.condition = condition
        if condition == freund.PLANE_STRESS:
            self.nu_eq = freund.equivalent_plane_stress_poisson(nu)
        else:
            self.nu_eq = nu
        self.c_d = freund.dilatational_wave_speed(E, nu, rho, condition)
        self.c_s = freund.shear_wave_speed(E, nu, rho)
        self.c_r = freund.rayleigh_wave_speed(self.c_s, self.c_d)
        self.k_ic = fracture_toughness(E, nu, G_c, condition)
        self.E_eff = effective_modulus(E, nu, condition)
        self.G_c, self.sigma0, self.t_d, self.H, self.a = G_c, sigma0, t_d, H, a
        self.t_c = freund.crack_arrival_time(H, self.c_d)
        self.t_end = freund.mode1_validity_end(H, self.c_d)

    def k_star(self, t, l=None):
        """K*(t, l) = eq. 42 (independent of l for this loading)."""
        return freund.mode1_ramp_dsif(t, self.nu_eq, self.sigma0, self.c_d, self.t_d, self.H)

    def initiation_time(self):
        return ramp_initiation_time(self.k_ic, self.nu_eq, self.sigma0, self.c_d,
                                    self.t_d, self.H)

    def history(self, criterion=TOUGHNESS, t_end=None, t_eval=None, law=None):
        """(t, l, v) from t_i to t_end (default 3 t_c); l = a before t_i."""
        t_end = self.t_end if t_end is None else t_end
        t_i = self.initiation_time()
        if t_i >= t_end:
            raise ValueError("the crack does not start inside the window: lower G_c")
        return tip_history(self.k_star, self.k_ic, self.c_r, self.c_d, self.a, t_i, t_end,
                           criterion, t_eval, law)

    def tip_position(self, t, criterion=TOUGHNESS, law=None):
        """l(t) at any times (a before t_i), from a dense solution."""
        t = np.asarray(t, dtype=float)
        t_i = self.initiation_time()
        if t.max() <= t_i:
            return np.full_like(t, self.a), np.zeros_like(t)
        t_end = float(t.max())
        tt, l, v = self.history(criterion, t_end=t_end,
                                t_eval=np.linspace(t_i, t_end, DENSE_POINTS), law=law)
        return np.where(t <= t_i, self.a, np.interp(t, tt, l)), np.where(
            t <= t_i, 0.0, np.interp(t, tt, v))
