# SPDX-License-Identifier: GPL-2.0-or-later
"""Stationary Mode-I semi-infinite crack (Bouaraquia & Mabssout 2026, sec. 4.2.1).

Runs examples/mode1-semi-infinite/in.mode1 (compute bbpd/dsif every step) and compares
K_I(t) with Freund's solution (eq. 42) for t <= 3 t_c with the errors of eqs. 44-45, in the two
conventions of examples/mode1-semi-infinite/README.md: the paper's (nu = 0.3, C_d = 5944 m/s)
and the BBPD model's own constants ('consistent': plane stress nu = 1/3, i.e. eq. 42 with
nu' = 1/4 and C_d = 5434 m/s). The README has the commands.
"""

import time
from pathlib import Path

import numpy as np

from bbpd import freund, metrics, readers
from bbpd.csvfile import write_csv
from bbpd.jobs import ROOT
from bbpd.reference import POISSON
from bbpd.kernels import COLORS, KERNELS
from bbpd.markdown import cell
from bbpd.markdown import table as md_table
from bbpd.provenance import machine
from bbpd.plots import plot_k
from bbpd.runner import run_or_reuse
from bbpd.benchmarks import cli

EXAMPLE = ROOT / "examples" / "mode1-semi-infinite" / "in.mode1"

# paper sec. 4.2.1
E = 210.0e9
RHO = 8000.0
H = 2.0
NU_PAPER = 0.3
T_D = 3.36e-4
DT_PAPER = 5.0e-6
DX_PAPER_DT = 0.05     # finest grid at which the paper's dt stays well inside the stable bound
SIGMA0 = 1.0e6         # any value: the model is linear
T_END = 1.2e-3         # run length, > 3 t_c in both conventions

# paper Tables 2 and 3: (peak %, L2 %)
PAPER_TABLE2 = {0.1: (9.82, 17.70), 0.05: (0.21, 2.86), 0.025: (0.17, 2.74)}
PAPER_TABLE3 = {"constant": (14.20, 15.48), "triangular": (5.99, 6.56), "gaussian": (0.21, 2.86)}

CONVENTIONS = ("paper", "consistent")


def default_dt(dx):
    """The paper's 5e-6 s down to dx = 0.05 m; below, scaled with dx (the stable bound is
    proportional to dx at fixed m): 5e-6 s at 0.025 m would be 0.87 of the velocity-Verlet
    limit and above eq. 25's bound."""
    return DT_PAPER * min(1.0, dx / DX_PAPER_DT)


def reference(convention, model="plane/stress", E=E, rho=RHO, H=H, sigma0=SIGMA0, t_d=T_D, nu=None):
    """(K_exact(t), t_c) of eq. 42 in one convention; nu is the model's Poisson's ratio where
    it is free (the LPS styles), else the one the bond-based model implies."""
    if convention == "paper":
        nu_eq, c_d = NU_PAPER, freund.dilatational_wave_speed(E, NU_PAPER, rho, freund.PLANE_STRAIN)
    elif convention == "consistent":
        nu = POISSON[model] if nu is None else nu
        if model == "plane/stress":
            nu_eq = freund.equivalent_plane_stress_poisson(nu)
            c_d = freund.dilatational_wave_speed(E, nu, rho, freund.PLANE_STRESS)
        else:
            nu_eq, c_d = nu, freund.dilatational_wave_speed(E, nu, rho, freund.PLANE_STRAIN)
    else:
        raise ValueError(f"convention must be one of {CONVENTIONS}, got {convention!r}")

    def exact(t):
        return freund.mode1_ramp_dsif(t, nu_eq, sigma0, c_d, t_d, H)

    return exact, freund.crack_arrival_time(H, c_d)


def errors(t, k_paper, k_consistent, model="plane/stress", **material):
    """Eqs. 44-45 (in %) over 0 <= t <= 3 t_c for both conventions."""
    out = {}
    for conv, k in (("paper", k_paper), ("consistent", k_consistent)):
        exact, t_c = reference(conv, model, **material)
        window = (0.0, freund.MODE1_VALIDITY_MULTIPLE * t_c)
        out[conv] = {"peak": 100.0 * metrics.peak_relative_error(t, k, exact, window),
                     "l2": 100.0 * metrics.l2_relative_error(t, k, exact, window),
                     "t_c": t_c}
    return out


def run(workdir, kernel="gaussian", dx=0.05, model="plane/stress", dt=None, nprocs=1,
        efactor=1.0, tipshift=0.5, r1=1.0, r2=2.0, t_end=T_END, family="bond", nu=NU_PAPER, m=None):
    """Run in.mode1 once; return errors (%) in both conventions, wall time and series.
    family 'lps' runs the state-based style of the kernel with Poisson's ratio nu (the
    bond-based family ignores nu: its ratio is the model's)."""
    dt = default_dt(dx) if dt is None else dt
    workdir = Path(workdir)
    vars_ = {"kernel": kernel, "dx": dx, "model": model, "dt": dt, "tend": t_end,
             "Efactor": efactor, "tipshift": tipshift, "r1": r1, "r2": r2,
             "E": E, "rho": RHO, "H": H, "td": T_D, "sigma0": SIGMA0, "nu_paper": NU_PAPER,
             "family": family, "nu": nu}
    if m is not None:
        vars_["m"] = m
    nu_model = nu if family == "lps" else None
    output, wall = run_or_reuse(EXAMPLE, workdir, vars_, nprocs)
    loop_s, _ = readers.loop_time(output)
    # k.dat: K_I (paper constants), K_I (consistent), K_II (consistent)
    t, k_paper, k_cons, k_ii = readers.k_history(workdir / "k.dat", dt)
    res = {"kernel": kernel, "dx": dx, "model": model, "family": family, "nu": nu_model,
           "dt": dt, "nprocs": nprocs,
           "wall_time": wall, "loop_time": loop_s,
           "dt_fraction_of_limit": readers.pair_setup(output)["dt_fraction"],
           "atoms": int(round(10.0 / dx)) * int(round(2 * H / dx)),
           "t": t, "k_paper": k_paper, "k_consistent": k_cons, "k_ii": k_ii}
    res.update(errors(t, k_paper, k_cons, model, nu=nu_model))
    jcols = readers.j_history(workdir / "k.dat")
    if jcols is not None:    # K_I from the J-integral (interaction integral), both conventions
        res["j"], res["k_j"], res["kii_j"] = jcols
        res["jintegral"] = errors(t, res["k_j"], res["k_j"], model, nu=nu_model)
    # K_II must vanish by symmetry until the lateral edges matter (they are 5 m away)
    w = t <= freund.MODE1_VALIDITY_MULTIPLE * res["consistent"]["t_c"]
    res["kii_over_ki"] = float(np.max(np.abs(k_ii[w])) / np.max(np.abs(k_cons[w])))
    return res


# --------------------------------------------------------------------------- tables

TABLE3_DX = 0.05    # m, the paper's Table 3


def _kmax_ratio(res, key, exact):
    """max K over 0 <= t <= 3 t_c divided by max K_exact there."""
    t = np.asarray(res["t"], dtype=float)
    w = t <= 3.0 * res["consistent"]["t_c"]
    return float(np.max(np.asarray(res[key], dtype=float)[w]) / np.max(exact(t[w])))


def row(res):
    """The CSV row of one run (examples/mode1-semi-infinite/results/mode1.csv)."""
    exact, _ = reference("consistent", res.get("model", "plane/stress"))
    j = (res.get("jintegral") or {}).get("consistent") or {}
    jp = (res.get("jintegral") or {}).get("paper") or {}
    kii_j = None
    if "kii_j" in res:    # K_II/K_I of the interaction integral over the window: 0 by symmetry
        t = np.asarray(res["t"], dtype=float)
        w = t <= 3.0 * res["consistent"]["t_c"]
        kii_j = float(np.max(np.abs(np.asarray(res["kii_j"], dtype=float)[w]))
                      / np.max(np.abs(np.asarray(res["k_j"], dtype=float)[w])))
    return {"kernel": res["kernel"], "dx_m": res["dx"],
            "paper_peak": res["paper"]["peak"], "paper_l2": res["paper"]["l2"],
            "consistent_peak": res["consistent"]["peak"],
            "consistent_l2": res["consistent"]["l2"],
            "j_peak": j.get("peak"), "j_l2": j.get("l2"),
            "kmax_ratio": _kmax_ratio(res, "k_consistent", exact),
            "kmax_ratio_j": _kmax_ratio(res, "k_j", exact) if "k_j" in res else None,
            "j_paper_peak": jp.get("peak"), "j_paper_l2": jp.get("l2"),
            "kii_over_ki": res.get("kii_over_ki"), "kii_j_over_k_j": kii_j, "dt_s": res["dt"],
            "atoms": res.get("atoms"), "run_time_s": res["wall_time"]}


def _pair(r, a, b):
    return f"{cell(r[a])} / {cell(r[b])}"


def table2(rows):
    """The paper's Table 2 (the Gaussian kernel at every dx) beside ours, from row()s; a dx of
    the paper's that did not run has its row, with '-' for ours."""
    header = ["dx (m)", "atoms", "paper's Table 2 peak / L2", "ours, paper convention peak / L2",
              "ours, consistent peak / L2", "dt (s)", "run time (s)"]
    gauss = {round(r["dx_m"], 6): r for r in rows if r["kernel"] == "gaussian"}
    cells = []
    for dx in sorted(set(gauss) | set(PAPER_TABLE2), reverse=True):
        ref, r = PAPER_TABLE2.get(dx), gauss.get(dx)
        ours = ([_pair(r, "paper_peak", "paper_l2"), _pair(r, "consistent_peak", "consistent_l2"),
                 f"{r['dt_s']:g}", cell(r["run_time_s"], ".1f")] if r else ["-"] * 4)
        cells.append([f"{dx:g}", f"{round(10 / dx)} x {round(4 / dx)}",
                      "-" if ref is None else f"{ref[0]:.2f} / {ref[1]:.2f}"] + ours)
    return md_table(header, cells)


def table3(rows):
    """The paper's Table 3 (the kernels at TABLE3_DX) beside ours, from row()s."""
    at = {r["kernel"]: r for r in rows if abs(r["dx_m"] - TABLE3_DX) < 1e-12}
    header = ["kernel", "paper's Table 3 peak / L2", "ours, paper convention peak / L2",
              "ours, consistent peak / L2", "run time (s)"]
    cells = [[k, f"{PAPER_TABLE3[k][0]:.2f} / {PAPER_TABLE3[k][1]:.2f}",
              _pair(at[k], "paper_peak", "paper_l2"),
              _pair(at[k], "consistent_peak", "consistent_l2"), cell(at[k]["run_time_s"], ".1f")]
             for k in KERNELS if k in at]
    return md_table(header, cells)


def jtable(rows):
    """K_I by extrapolation and from the J-integral, every run of row()s."""
    header = ["kernel", "dx (m)", "extrapolation peak / L2", "J: peak / L2",
              "K_max ratio: extrapolation / J", "run time (s)"]
    cells = [[r["kernel"], f"{r['dx_m']:g}", _pair(r, "consistent_peak", "consistent_l2"),
              _pair(r, "j_peak", "j_l2"), f"{cell(r['kmax_ratio'], '.3f')} / "
              f"{cell(r['kmax_ratio_j'], '.3f')}", cell(r["run_time_s"], ".1f")]
             for r in sorted(rows, key=lambda r: (-r["dx_m"], KERNELS.index(r["kernel"])))]
    return md_table(header, cells)


TIP_STUDY = ((0.5, 1.0, 2.0), (0.5, 1.0, 3.0), (0.5, 2.0, 3.0), (0.5, 2.0, 4.0),
             (-0.5, 1.0, 2.0), (0.0, 0.5, 1.5), (0.0, 1.5, 2.5), (0.0, 2.5, 4.5))


def tip_study(work, dx=0.05, kernel="gaussian", nprocs=1):
    """How K moves with the tip position and r1, r2 (README table): a row per TIP_STUDY case."""
    exact, _ = reference("consistent")
    rows = []
    for shift, r1, r2 in TIP_STUDY:
        res = run(Path(work) / f"tip_{shift}_{r1}_{r2}", kernel, dx, nprocs=nprocs,
                  tipshift=shift, r1=r1, r2=r2)
        c, p = res["consistent"], res["paper"]
        rows.append({"tipshift_dx": shift, "r1_dx": r1, "r2_dx": r2,
                     "kmax_ratio": _kmax_ratio(res, "k_consistent", exact),
                     "consistent_peak": c["peak"], "consistent_l2": c["l2"],
                     "paper_peak": p["peak"], "paper_l2": p["l2"], "run_time_s": res["wall_time"]})
        print(f"tip x - a {shift:+.1f} dx, r1 r2 {r1:g} {r2:g} dx: K_max/K_max,exact "
              f"{rows[-1]['kmax_ratio']:.3f}, peak / L2 consistent {c['peak']:.2f} / {c['l2']:.2f}, "
              f"paper {p['peak']:.2f} / {p['l2']:.2f}", flush=True)
    return rows


RESOLUTION_COLORS = ("tab:purple", "tab:red", "tab:green", "tab:blue", "tab:brown")


def figures(rows2, rows3, folder):
    """Fig. 9 (the Gaussian's results by dx, rows2) and Fig. 10 (by kernel at TABLE3_DX, rows3):
    K_I(t) against eq. 42 in both conventions; returns the paths written."""
    norm = SIGMA0 * np.sqrt(H)
    exact, t_c = reference("consistent")
    exact_p, _ = reference("paper")
    tt = np.linspace(0.0, T_END, 600)
    refs = [("eq. 42, BBPD constants (consistent)", tt * 1e3, exact(tt) / norm, "--", "black"),
            ("eq. 42, paper's constants (nu = 0.3)", tt * 1e3, exact_p(tt) / norm, "-.", "grey")]
    rows2 = dict(sorted(rows2.items(), reverse=True))
    colors = {**dict(zip(rows2, RESOLUTION_COLORS * len(rows2))), **COLORS}
    out = []
    for name, rows, label, title in (
            ("fig9_resolutions.png", rows2, lambda dx: f"dx = {dx:g} m",
             "Fig. 9: Mode-I K_I(t), Gaussian kernel, m = 5, three grids"),
            ("fig10_kernels.png", rows3, lambda k: k,
             f"Fig. 10: Mode-I K_I(t), dx = {TABLE3_DX:g} m, m = 5, three kernels")):
        if rows:
            out.append(plot_k(Path(folder) / name, [
                (f"{label(key)} (consistent L2 {r['consistent']['l2']:.2f} %)", r["t"] * 1e3,
                 r["k_consistent"] / norm, colors[key]) for key, r in rows.items()],
                refs, (0.0, 3.0 * t_c * 1e3), title, "t (ms)", r"$K_I/(\sigma_0\sqrt{H})$"))
    return out


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/bbpd-mode1", nprocs=1, dx=[0.1, 0.05, 0.025],
                    figures="folder for Fig. 9 and Fig. 10 PNGs")
    ap.add_argument("--model", default="plane/stress")
    ap.add_argument("--table2", action="store_true")
    ap.add_argument("--table3", action="store_true")
    ap.add_argument("--tips", action="store_true", help="tip position / r1, r2 study")
    ap.add_argument("--tips-csv", metavar="PATH",
                    help="write the tip study to PATH as CSV (the README's table is generated "
                         "from examples/mode1-semi-infinite/results/tips.csv)")
    args = ap.parse_args(argv)
    def runs(cases):    # {key: run} of {key: (kernel, dx)}
        return {key: run(Path(args.work) / f"{k}_{dx}", k, dx, args.model, nprocs=args.nprocs)
                for key, (k, dx) in cases.items()}
    rows2 = runs({dx: ("gaussian", dx) for dx in args.dx}) if args.table2 else {}
    rows3 = runs({k: (k, TABLE3_DX) for k in KERNELS}) if args.table3 else {}
    if rows2:
        print(table2([row(r) for r in rows2.values()]))
    if rows3:
        print(table3([row(r) for r in rows3.values()]))
    if args.tips or args.tips_csv:
        rows = tip_study(args.work, nprocs=args.nprocs)
        if args.tips_csv:
            write_csv(args.tips_csv, rows, [f"made by: {cli.command('mode1', argv).strip()} on "
                                            f"{time.strftime('%Y-%m-%d %H:%M')}",
                                            "Gaussian kernel, dx = 0.05 m, plane/stress",
                                            f"machine: {machine()}"])
    if args.figures:
        figures(rows2, rows3, args.figures)


if __name__ == "__main__":
    main()
