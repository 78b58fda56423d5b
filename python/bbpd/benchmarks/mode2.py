# SPDX-License-Identifier: GPL-2.0-or-later
"""Mode-II central crack under uniform shear (Bouaraquia & Mabssout 2026, sec. 4.2.2): K_II(t)
of examples/mode2-central-crack/in.mode2 against the early-time analytic reference of
bbpd.freund (examples/mode2-central-crack/README.md derives its window and has the commands).
"""

from pathlib import Path

import numpy as np
import scipy.sparse as sparse

from bbpd import freund, metrics, readers
from bbpd.jobs import ROOT
from bbpd.reference import POISSON
from bbpd.kernels import KERNELS
from bbpd.markdown import cell
from bbpd.markdown import table as md_table
from bbpd.plots import plot_k
from bbpd.runner import run_or_reuse
from bbpd.benchmarks import cli

EXAMPLE = ROOT / "examples" / "mode2-central-crack" / "in.mode2"

# paper sec. 4.2.2 (plate 104 x 40 mm, 2a = 24 mm)
E = 73.5e9
NU = 0.25
RHO = 2450.0
HALF_HEIGHT = 0.020
HALF_LENGTH = 0.052
A = 0.012
TAU = 1.0e6             # any value: the model is linear (in.mode2 uses the same)
LOADED_EDGES = 2        # +tau on the top edge, -tau on the bottom edge
DT_REF, DX_REF = 5.0e-8, 0.5e-3    # ~0.48 of the velocity-Verlet limit; scaled with dx
T_END = 12.0e-6


def default_dt(dx):
    return DT_REF * dx / DX_REF


def wave_speeds(model="plane/strain"):
    nu = POISSON[model]
    cond = freund.PLANE_STRESS if model == "plane/stress" else freund.PLANE_STRAIN
    return freund.shear_wave_speed(E, nu, RHO), freund.dilatational_wave_speed(E, nu, RHO, cond)


def window(model="plane/strain", half_length=HALF_LENGTH):
    c_s, c_d = wave_speeds(model)
    return freund.mode2_validity_window(HALF_HEIGHT, A, half_length, c_s, c_d)


def reference(model="plane/strain", td=0.0):
    """K_II(t) of the semi-infinite crack loaded by the incident shear waves (from t = 0)."""
    c_s, c_d = wave_speeds(model)
    t0 = window(model).t_start
    amp = freund.crack_plane_amplitude(TAU, LOADED_EDGES)
    if td > 0.0:
        return lambda t: freund.mode2_ramp_dsif(np.asarray(t) - t0, amp, c_s, c_d, td)
    return lambda t: freund.mode2_step_dsif(np.asarray(t) - t0, amp, c_s, c_d)


def normalise(k):
    return freund.normalised_mode2(k, TAU, A)


def errors(t, k_ii, model="plane/strain", td=0.0):
    """Eqs. 44-45 (in %) against the reference over its validity window."""
    w = window(model)
    win = (w.t_start, w.t_end_ignoring_corners)
    exact = reference(model, td)
    return {"peak": 100.0 * metrics.peak_relative_error(t, k_ii, exact, win),
            "l2": 100.0 * metrics.l2_relative_error(t, k_ii, exact, win),
            "window": win}


def run(workdir, kernel="gaussian", dx=0.5e-3, model="plane/strain", td=0.0, dt=None,
        nprocs=1, t_end=T_END, half_length=HALF_LENGTH, tipshift=0.5, r1=1.0, r2=2.0):
    """Run in.mode2 once; return errors (%), symmetry checks, wall time and series."""
    dt = default_dt(dx) if dt is None else dt
    workdir = Path(workdir)
    vars_ = {"kernel": kernel, "dx": dx, "model": model, "dt": dt, "tend": t_end, "td": td,
             "Lx": 2.0 * half_length, "tipshift": tipshift, "r1": r1, "r2": r2}
    output, wall = run_or_reuse(EXAMPLE, workdir, vars_, nprocs)
    loop_s, _ = readers.loop_time(output)
    # k.dat: K_II right tip, K_I right tip, K_II left tip; J columns at the right tip
    t, k_ii, k_i, k_ii_left = readers.k_history(workdir / "k.dat", dt)
    res = {"kernel": kernel, "dx": dx, "model": model, "td": td, "dt": dt, "nprocs": nprocs,
           "wall_time": wall, "loop_time": loop_s,
           "t": t, "k_ii": k_ii, "k_i": k_i, "k_ii_left": k_ii_left}
    res.update(errors(t, k_ii, model, td))
    w = (t >= res["window"][0]) & (t <= res["window"][1])
    scale = np.max(np.abs(k_ii[w]))
    res["left_right"] = float(np.max(np.abs(k_ii_left[w] - k_ii[w])) / scale)
    res["ki_over_kii"] = float(np.max(np.abs(k_i[w])) / scale)
    res["k_end"] = float(normalise(k_ii[w][-1]))
    res["k_end_exact"] = float(normalise(reference(model, td)(t[w][-1])))
    jcols = readers.j_history(workdir / "k.dat")
    if jcols is not None:    # K_II from the J-integral (interaction integral)
        res["j"], res["k_i_j"], res["k_ii_j"] = jcols
        res["jintegral"] = errors(t, res["k_ii_j"], model, td)
        res["jintegral"]["k_end"] = float(normalise(res["k_ii_j"][w][-1]))
    return res


# --------------------------------------------------------------------------- classical check
#
# An independent check of the analytic reference: classical plane-strain elastodynamics of the
# same plate by explicit finite elements (bilinear squares of side h, 2x2 Gauss points, lumped
# mass, central differences), the crack as a row of split nodes for |x| < a, the edge
# tractions as consistent nodal forces.  K comes from the face jumps of the split nodes,
# K(r) = mu jump sqrt(2 pi / r)/(kappa + 1), extrapolated linearly in r to the tip from
# FE_FIT_RANGE (outside the few elements where the mesh cannot follow sqrt(r)).  mode = 2 is
# this benchmark; mode = 1 (normal tractions) checks the same machinery against Freund's
# mode-I solution.

FE_FIT_RANGE = (2.0e-3, 6.0e-3)    # m: 8-24 elements at h = 0.25 mm
FE_CFL = 0.3                       # dt = FE_CFL h / c_d


def _q4_stiffness(lam, mu, h):
    d = np.array([[lam + 2 * mu, lam, 0.0], [lam, lam + 2 * mu, 0.0], [0.0, 0.0, mu]])
    xn, yn = np.array([-1, 1, 1, -1]), np.array([-1, -1, 1, 1])
    ke = np.zeros((8, 8))
    for gx in (-1, 1):
        for gy in (-1, 1):
            xi, eta = gx / np.sqrt(3.0), gy / np.sqrt(3.0)
            b = np.zeros((3, 8))
            b[0, 0::2] = b[2, 1::2] = xn * (1 + eta * yn) / (2 * h)    # dN/dx
            b[1, 1::2] = b[2, 0::2] = yn * (1 + xi * xn) / (2 * h)     # dN/dy
            ke += b.T @ d @ b * h * h / 4
    return ke


def classical_fe(mode=2, h=0.25e-3, t_end=10.0e-6, every=4):
    """Classical FE K(t) at the right tip: returns t, K (same load and plate as in.mode2)."""
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    nx, ny = int(round(2 * HALF_LENGTH / h)), int(round(2 * HALF_HEIGHT / h))
    x = -HALF_LENGTH + h * np.arange(nx + 1)
    node = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    j0 = ny // 2
    split = np.where(np.abs(x) < A - 1e-9 * h)[0]          # crack nodes; the tips stay shared
    lower = -np.ones(nx + 1, dtype=int)
    lower[split] = node.size + np.arange(split.size)
    nnode = node.size + split.size
    jj, ii = np.meshgrid(np.arange(ny), np.arange(nx), indexing="ij")
    conn = np.stack([node[jj, ii], node[jj, ii + 1], node[jj + 1, ii + 1], node[jj + 1, ii]],
                    axis=-1).reshape(-1, 4)
    below = (jj.ravel() + 1 == j0)                          # elements under the crack row
    for c, col in ((3, ii.ravel()), (2, ii.ravel() + 1)):
        use = below & (lower[col] >= 0)
        conn[use, c] = lower[col[use]]
    dofs = np.stack([2 * conn, 2 * conn + 1], axis=2).reshape(-1, 8)
    ke = _q4_stiffness(lam, mu, h)
    k = sparse.coo_matrix((np.tile(ke.ravel(), len(conn)),
                           (np.repeat(dofs, 8, axis=1).ravel(), np.tile(dofs, (1, 8)).ravel())),
                          shape=(2 * nnode, 2 * nnode)).tocsr()
    mass = np.zeros(nnode)
    np.add.at(mass, conn.ravel(), RHO * h * h / 4)
    mass = np.repeat(mass, 2)
    comp = 0 if mode == 2 else 1
    force = np.zeros(2 * nnode)
    w = np.full(nx + 1, h)
    w[[0, -1]] = h / 2
    force[2 * node[ny] + comp] += TAU * w
    force[2 * node[0] + comp] -= TAU * w
    _, c_d = wave_speeds()
    dt = FE_CFL * h / c_d
    itip = int(np.argmin(np.abs(x - A)))
    behind = np.arange(1, int(FE_FIT_RANGE[1] / h + 1.5))
    r = behind * h
    up, lo = 2 * node[j0, itip - behind] + comp, 2 * lower[itip - behind] + comp
    fit = (r >= FE_FIT_RANGE[0] - 1e-9 * h) & (r <= FE_FIT_RANGE[1] + 1e-9 * h)
    kappa = 3 - 4 * NU
    u, v = np.zeros(2 * nnode), np.zeros(2 * nnode)
    ts, ks = [], []
    for n in range(1, int(np.ceil(t_end / dt)) + 1):
        v += dt * (force - k @ u) / mass
        u += dt * v
        if n % every == 0:
            k_r = mu * (u[up] - u[lo]) * np.sqrt(2 * np.pi / r) / (kappa + 1)
            ts.append(n * dt)
            ks.append(np.polyfit(r[fit], k_r[fit], 1)[1])
    return np.array(ts), np.array(ks)


def classical_reference(mode=2):
    """The analytic early-time K of the semi-infinite crack for classical_fe(mode)."""
    if mode == 2:
        return reference()
    amp, c_d = freund.crack_plane_amplitude(TAU, LOADED_EDGES), wave_speeds()[1]
    return lambda t: freund.mode1_step_dsif(t, NU, amp, c_d, HALF_HEIGHT)


def classical_window(mode=2):
    """From the wave's arrival to the first diffracted wave from the other tip."""
    c_s, c_d = wave_speeds()
    start = HALF_HEIGHT / (c_s if mode == 2 else c_d)
    return start, start + 2.0 * A / c_d


WINDOW_END_US = 9.77    # t_start + 2a/c_d (README, "Reference")


def row(res):
    """The CSV row of one run (examples/mode2-central-crack/results/mode2.csv)."""
    j = res.get("jintegral") or {}
    natoms = int(round(2 * HALF_LENGTH / res["dx"])) * int(round(2 * HALF_HEIGHT / res["dx"]))
    return {"kernel": res["kernel"], "dx_m": res["dx"], "atoms": natoms, "peak": res["peak"],
            "l2": res["l2"], "k_end": res["k_end"], "k_end_exact": res["k_end_exact"],
            "ratio_end": res["k_end"] / res["k_end_exact"], "j_peak": j.get("peak"),
            "j_l2": j.get("l2"),
            "j_ratio_end": (j["k_end"] / res["k_end_exact"]) if "k_end" in j else None,
            "left_right": res.get("left_right"), "ki_over_kii": res.get("ki_over_kii"),
            "dt_s": res["dt"], "run_time_s": res["wall_time"]}


def _sorted(rows):
    return sorted(rows, key=lambda r: (-r["dx_m"], KERNELS.index(r["kernel"])))


def table(rows):
    """K_II by extrapolation against the reference, from row()s."""
    header = ["kernel", "dx (mm)", "atoms", "peak (%)", "L2 (%)",
              f"K_II/(tau sqrt(pi a)) at {WINDOW_END_US} us, ours / reference", "run time (s)"]
    return md_table(header, [[r["kernel"], f"{r['dx_m'] * 1e3:g}", f"{r['atoms']:,.0f}",
                              cell(r["peak"]), cell(r["l2"]),
                              f"{r['k_end']:.3f} / {r['k_end_exact']:.3f}",
                              cell(r["run_time_s"], ".1f")] for r in _sorted(rows)])


def jtable(rows):
    """K_II by extrapolation and from the J-integral, from row()s."""
    header = ["kernel", "dx (mm)", "extrapolation: peak / L2 (%)",
              f"extrapolation: ratio at {WINDOW_END_US} us", "J: peak / L2 (%)",
              f"J: ratio at {WINDOW_END_US} us", "run time (s)"]
    return md_table(header, [[r["kernel"], f"{r['dx_m'] * 1e3:g}",
                              f"{r['peak']:.2f} / {r['l2']:.2f}", f"{r['ratio_end']:.3f}",
                              f"{cell(r['j_peak'])} / {cell(r['j_l2'])}",
                              cell(r["j_ratio_end"], ".3f"), cell(r["run_time_s"], ".1f")]
                             for r in _sorted(rows)])


def figure(rows, path, td=0.0):
    w = window()
    tt = np.linspace(0.0, T_END, 400)
    series = [(f"{k} dx = {dx * 1e3:g} mm", r["t"] * 1e6, normalise(r["k_ii"]), None)
              for (k, dx), r in rows.items()]
    plot_k(path, series, [("semi-infinite crack, 2 tau", tt * 1e6, normalise(reference(td=td)(tt)),
                           "--", "black")], (0.0, w.t_end_ignoring_corners * 1e6), "Mode-II K_II(t)",
           "t (us)", "K_II / (tau sqrt(pi a))")


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/bbpd-mode2", nprocs=1, kernels=KERNELS, dx=[1.0e-3, 0.5e-3],
                    figures="folder for the Fig. 12 PNG")
    ap.add_argument("--td", type=float, default=0.0, help="load rise time (0: step)")
    ap.add_argument("--fe", type=float, nargs="*", metavar="H",
                    help="classical FE check of the reference at these element sizes")
    args = ap.parse_args(argv)
    for h in args.fe or []:
        for mode in (1, 2):
            t, k = classical_fe(mode, h)
            win = classical_window(mode)
            exact = classical_reference(mode)
            print(f"classical FE mode {mode} h = {h:.3g} m: K/K_exact at the window end "
                  f"{np.interp(win[1], t, k) / exact(win[1]):.4f}; peak, L2 error (%) "
                  f"{100 * metrics.peak_relative_error(t, k, exact, win):.2f} "
                  f"{100 * metrics.l2_relative_error(t, k, exact, win):.2f}")
    rows = {(k, dx): run(Path(args.work) / f"{k}_{dx}", k, dx, td=args.td, nprocs=args.nprocs)
            for dx in args.dx for k in args.kernels}
    print(table([row(r) for r in rows.values()]))
    print(jtable([row(r) for r in rows.values()]))
    if args.figures and rows:
        figure(rows, Path(args.figures) / "fig12_kernels.png", args.td)


if __name__ == "__main__":
    main()
