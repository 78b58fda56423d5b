"""The model's own wave speeds on its grid (bbpd.reference.grid_wave_speeds).

The long-wave limit of the dynamic matrix D(k) / k^2 holds the grid's elastic constants; the
calibration tests (tests/lammps/test_calibration.py) tie the same lattice sum, read as an
energy, to the pair style. Here the speeds are checked against that energy, computed from the
bonds of a deformed block (refmodel.Bonds, another formula), and against the continuum
as the horizon holds more spacings.
"""
import math

import numpy as np
import pytest

from bbpd import freund
from bbpd import reference as ref
import refmodel

E, RHO, DX = 72.0e9, 2440.0, 1.0e-3
STRAIN = 1.0e-6
# the long-wave speeds carry (k delta)^2 ~ 1e-6 of dispersion; the energies are exact sums
ENERGY_RTOL = 1.0e-5


def centre_energy(kernel, m, strain):
    """Energy density of the centre atom of a square block under u = strain . x."""
    n = 2 * m + 5
    x0 = refmodel.square_lattice((n, n), DX)
    centre = int(np.argmin(np.linalg.norm(x0 - x0.mean(axis=0), axis=1)))
    delta = m * DX
    bonds = refmodel.Bonds(x0, DX**2, kernel, ref.micromodulus(kernel, "plane/stress", E, delta),
                      delta, DX)
    return float(bonds.energy_density(x0 + x0 @ strain.T)[centre])


@pytest.mark.parametrize("kernel", ref.KERNELS)
@pytest.mark.parametrize("m", (3, 4))
def test_long_wave_speeds_are_the_grid_elastic_constants(kernel, m):
    # along x: rho c_d^2 = C11, rho c_s^2 = C66; central bonds give C12 = C66 (Cauchy), so
    # uniform expansion stores (C11 + C66) e^2 and pure shear eps_12 = e stores 2 C66 e^2
    c_d, c_s = ref.grid_wave_speeds(kernel, "plane/stress", E, RHO, m, DX)
    iso = STRAIN * np.diag([1.0, 1.0, 0.0])
    shear = STRAIN * np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    c66 = centre_energy(kernel, m, shear) / (2.0 * STRAIN**2)
    c11 = centre_energy(kernel, m, iso) / STRAIN**2 - c66
    assert RHO * c_s**2 == pytest.approx(c66, rel=ENERGY_RTOL)
    assert RHO * c_d**2 == pytest.approx(c11, rel=ENERGY_RTOL)


@pytest.mark.parametrize("kernel", ref.KERNELS)
def test_grid_speeds_tend_to_the_continuum(kernel):
    nu = ref.POISSON["plane/stress"]
    c_d0 = freund.dilatational_wave_speed(E, nu, RHO, freund.PLANE_STRESS)
    c_s0 = freund.shear_wave_speed(E, nu, RHO)
    c_r0 = freund.rayleigh_wave_speed(c_s0, c_d0)
    errors = []
    for m in (4, 20):
        c_d, c_s = ref.grid_wave_speeds(kernel, "plane/stress", E, RHO, m, DX / m)
        errors.append(abs(freund.rayleigh_wave_speed(c_s, c_d) / c_r0 - 1.0))
    assert errors[1] < 1.0e-3 < errors[0] or errors[1] < errors[0] < 1.0e-2
    # and the grid grows isotropic: the shear speed along the diagonal approaches that along x
    aniso = [abs(ref.grid_wave_speeds(kernel, "plane/stress", E, RHO, m, DX / m, (1, 1, 0))[1]
                 / ref.grid_wave_speeds(kernel, "plane/stress", E, RHO, m, DX / m)[1] - 1.0)
             for m in (4, 20)]
    assert aniso[1] < 0.25 * aniso[0]


def test_short_waves_are_slower_than_long_ones():
    # the model disperses: a wave two horizons long runs slower than the long-wave limit
    m = 4
    long_d, long_s = ref.grid_wave_speeds("gaussian", "plane/stress", E, RHO, m, DX)
    short_d, short_s = ref.grid_wave_speeds("gaussian", "plane/stress", E, RHO, m, DX,
                                            wavelength=2.0 * m * DX)
    assert short_d < 0.95 * long_d and short_s < 0.95 * long_s


def test_family_is_the_pair_styles():
    # |xi| < m + 1/2 spacings: 4 m^2 pi-ish partners, symmetric, no self bond
    fam = ref.grid_family(4)
    assert len(fam) == 68    # lattice points with 0 < |xi| < 4.5 on the square grid
    assert np.all(np.linalg.norm(fam, axis=1) > 0)
    assert {tuple(v) for v in fam} == {tuple(-v) for v in fam}
    assert math.isclose(fam[:, 2].max(), 0.0)
