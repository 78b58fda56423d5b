"""compute bbpd/dsif against prescribed crack-face displacement fields.

The atoms are displaced (displace_atoms, no time integration) by a field whose values on the
two face rows are the Williams crack-face displacements of given K_I, K_II (theta = +-pi) plus
an r^(3/2) term and a rigid translation. The two-point extrapolation (eq. 39) is exact for
such a field, so the compute must return K_I, K_II to round-off. mu and kappa of the field
come from E and nu written here (Williams formula, python/bbpd/dsif.williams_displacement),
not from the compute's code.
"""
import math
import re

import pytest

from bbpd import dsif
from bbpd.runner import LammpsError
from scenes import idle_compute_is_harmless, peri_preamble

DX = 1.0              # grid spacing (m): nodes at (i + 1/2, j + 1/2)
HALF = 20             # plate [-20, 20]^2 around the origin, 1600 atoms
DELTA = 3.0 * DX
YOUNGS = 70.0e9
K_I, K_II = 3.0e6, -1.2e6           # Pa sqrt(m)
B_I, B_II = 4.0e-6, 2.5e-6          # r^(3/2) coefficients (m^-1/2)
SHIFT = (1.0e-3, -2.0e-3)           # rigid translation (m)
IMPLIED_NU = {"plane/stress": 1.0 / 3.0, "plane/strain": 0.25}
RTOL = 1.0e-9


def kolosov(nu, plane):
    return (3.0 - nu) / (1.0 + nu) if plane == "stress" else 3.0 - 4.0 * nu


def face_amplitudes(E, nu, plane):
    """Single-face displacement per sqrt(r) on the upper face: (sliding, opening)."""
    mu = E / (2.0 * (1.0 + nu))
    kappa = kolosov(nu, plane)
    u1, u2 = dsif.williams_displacement(K_I, K_II, 1.0, math.pi, mu, kappa)
    return float(u1), float(u2)


def field_script(model="plane/stress", tip=(0.5, 0.0), direction=(1.0, 0.0), E=YOUNGS, nu=None,
          plane=None):
    """Lattice, pair style and the face field for a tip and crack direction."""
    nu = IMPLIED_NU[model] if nu is None else nu
    plane = plane or model.split("/")[1]
    a1, a2 = face_amplitudes(E, nu, plane)
    tx, ty = tip
    dx_, dy_ = direction
    nx_, ny_ = -dy_, dx_
    # local coordinates: s along the crack direction, q across it; r = -s behind the tip
    # reference positions: displace_atoms moves x before it evaluates the y variable
    s = f"((f_ref[1]-{tx!r})*{dx_!r}+(f_ref[2]-{ty!r})*{dy_!r})"
    q = f"((f_ref[1]-{tx!r})*{nx_!r}+(f_ref[2]-{ty!r})*{ny_!r})"
    r = f"(({s}<0)*abs({s}))"
    sgn = f"({q}/abs({q}))"
    slide = f"({sgn}*({a1!r}*sqrt({r})+{B_II!r}*{r}^1.5))"
    opening = f"({sgn}*({a2!r}*sqrt({r})+{B_I!r}*{r}^1.5))"
    return peri_preamble(2, lattice=f"sq {DX} origin 0.5 0.5 0.0", plugin=False) + f"""\
region plate block {-HALF} {HALF} {-HALF} {HALF} -0.5 0.5 units box
create_box 1 plate
create_atoms 1 region plate
set group all density 2450
set group all volume {DX * DX * DX}
pair_style bbpd/gaussian {model} thickness {DX}
pair_coeff * * {E!r} none {DELTA}
fix ref all store/state 0 x y
variable ux atom {SHIFT[0]!r}+{slide}*{dx_!r}+{opening}*{nx_!r}
variable uy atom {SHIFT[1]!r}+{slide}*{dy_!r}+{opening}*{ny_!r}
displace_atoms all move v_ux v_uy 0.0 units box
"""


def run_k(lmp, body, compute_args, nprocs=1, steps=0):
    script = ("plugin load bbpdplugin.so\n" + body +
              f"compute K all bbpd/dsif {compute_args}\n"
              "thermo_style custom step c_K[1] c_K[2]\n"
              "thermo_modify format float %.17g\n"
              f"run {steps}\n"
              'print "KVALUES $(c_K[1]:%.17g) $(c_K[2]:%.17g)"\n')
    out = lmp(script, nprocs=nprocs).output
    m = re.search(r"^KVALUES (\S+) (\S+)", out, re.M)
    assert m, out[-2000:]
    return float(m.group(1)), float(m.group(2))


@pytest.mark.parametrize("model", ["plane/stress", "plane/strain"])
def test_face_field_gives_k_exactly(lmp, model):
    # defaults: E from the pair style, nu implied by the model, r1 = dx, r2 = 2 dx
    ki, kii = run_k(lmp, field_script(model), "tip 0.5 0.0")
    assert ki == pytest.approx(K_I, rel=RTOL)
    assert kii == pytest.approx(K_II, rel=RTOL)


def test_nu_plane_and_E_keywords(lmp):
    # field of a plane-strain nu = 0.3 solid; the pair is plane stress (nu = 1/3)
    ki, kii = run_k(lmp, field_script("plane/stress", nu=0.3, plane="strain"),
                    "tip 0.5 0.0 nu 0.3 plane strain")
    assert (ki, kii) == pytest.approx((K_I, K_II), rel=RTOL)
    # K is linear in E at fixed displacements
    ki2, _ = run_k(lmp, field_script("plane/stress", nu=0.3, plane="strain"),
                   f"tip 0.5 0.0 nu 0.3 plane strain E {2.0 * YOUNGS!r}")
    assert ki2 == pytest.approx(2.0 * K_I, rel=RTOL)


def test_the_default_nu_matters_in_plane_strain_only(lmp):
    # plane stress: 2 mu/(kappa + 1) = E/4 for any nu, so nu 0.3 changes nothing
    body = field_script("plane/stress")
    assert run_k(lmp, body, "tip 0.5 0.0 nu 0.3")[0] == pytest.approx(K_I, rel=RTOL)
    # plane strain: 2 mu/(kappa + 1) = E/(4 (1 - nu^2))
    ki = run_k(lmp, field_script("plane/strain"), "tip 0.5 0.0 nu 0.3")[0]
    assert ki == pytest.approx(K_I * (1.0 - 0.25**2) / (1.0 - 0.3**2), rel=RTOL)


@pytest.mark.parametrize("tip,direction", [((-0.5, 0.0), (-1.0, 0.0)),     # left tip
                                           ((0.0, 0.5), (0.0, 1.0)),       # vertical crack
                                           ((0.0, -0.5), (0.0, -1.0))])
def test_crack_direction(lmp, tip, direction):
    args = f"tip {tip[0]} {tip[1]} direction {direction[0]} {direction[1]}"
    ki, kii = run_k(lmp, field_script(tip=tip, direction=direction), args)
    assert (ki, kii) == pytest.approx((K_I, K_II), rel=RTOL)


def test_r1_r2_keywords(lmp):
    ki, kii = run_k(lmp, field_script(), "tip 0.5 0.0 r1 2.0 r2 5.0")
    assert (ki, kii) == pytest.approx((K_I, K_II), rel=RTOL)


def test_mpi_faces_on_different_ranks(lmp):
    # processors 1 2 1 puts the upper and the lower face on different ranks
    serial = run_k(lmp, field_script(), "tip 0.5 0.0")
    body = field_script().replace("lattice", "processors 1 2 1\nlattice", 1)
    parallel = run_k(lmp, body, "tip 0.5 0.0", nprocs=2)
    assert parallel == pytest.approx(serial, rel=1e-14)
    assert serial == pytest.approx((K_I, K_II), rel=RTOL)


def test_variable_tip_is_followed(lmp):
    # equal-style tip: the field's tip at x = 0.5 until step 0, then the tip moves one column
    body = field_script() + "variable tx equal 0.5+1.0*(step>=1)\nvariable ty equal 0.0\n"
    assert run_k(lmp, body, "tip v_tx v_ty") == pytest.approx((K_I, K_II), rel=RTOL)
    ki, kii = run_k(lmp, body, "tip v_tx v_ty", steps=1)
    # no integrator: the atoms keep the field; B and D now sit at r_field = 0 and 1
    a1, a2 = face_amplitudes(YOUNGS, IMPLIED_NU["plane/stress"], "stress")
    mu, kappa = YOUNGS / (2.0 * (1.0 + 1.0 / 3.0)), 2.0
    expect_i = dsif.k_from_face_jump(0.0, 2.0 * (a2 + B_I), 1.0, 2.0, mu, kappa)
    expect_ii = dsif.k_from_face_jump(0.0, 2.0 * (a1 + B_II), 1.0, 2.0, mu, kappa)
    assert (ki, kii) == pytest.approx((expect_i, expect_ii), rel=RTOL)


def test_missing_node_error_names_the_point(lmp):
    with pytest.raises(LammpsError) as err:
        run_k(lmp, field_script(), "tip 100.0 0.0")
    assert "upper-face r1" in err.value.message and "face point (99" in err.value.message


def test_no_work_unless_invoked(lmp):
    assert idle_compute_is_harmless(lmp, field_script(), "compute K all bbpd/dsif tip 100.0 0.0")


def test_r2_must_exceed_r1(lmp):
    with pytest.raises(LammpsError, match="r2 > r1"):
        run_k(lmp, field_script(), "tip 0.5 0.0 r1 2.0 r2 1.0")


@pytest.mark.parametrize("kernel,nu", [("gaussian", 0.3), ("constant", 0.2)])
def test_lps_pair_gives_its_own_e_and_nu(lmp, kernel, nu):
    # the state-based styles' nu is free: the defaults must be pair_coeff's E and nu, not the
    # bond-based model's implied 1/4 (a plane-strain field of that nu, compute without E, nu)
    body = field_script("plane/strain", nu=nu).replace(
        f"pair_style bbpd/gaussian plane/strain thickness {DX}\npair_coeff * * {YOUNGS!r} none {DELTA}",
        f"pair_style bbpd/lps/{kernel} plane/strain thickness {DX}\n"
        f"pair_coeff * * {YOUNGS!r} {nu!r} none {DELTA}")
    assert "bbpd/lps/" in body
    ki, kii = run_k(lmp, body, "tip 0.5 0.0")
    assert (ki, kii) == pytest.approx((K_I, K_II), rel=RTOL)
