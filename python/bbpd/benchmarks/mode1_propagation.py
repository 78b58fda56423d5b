# SPDX-License-Identifier: GPL-2.0-or-later
"""Mode-I crack growth under a stress wave (examples/mode1-propagation), against Freund's
equation of motion (bbpd.crack_motion); examples/mode1-propagation/README.md defines each
measure and has the commands.
"""

from pathlib import Path

import numpy as np

from bbpd import crack_motion, crack_tip, csvfile, freund, plots, readers, reference
from bbpd import jobs as jobmod
from bbpd.benchmarks import mode1
from bbpd.kernels import COLORS, KERNELS
from bbpd.markdown import table as md_table
from bbpd.provenance import cpu
from bbpd.runner import run_or_reuse
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "mode1-propagation" / "in.mode1-propagation"

E, RHO, H, T_D, SIGMA0 = mode1.E, mode1.RHO, mode1.H, mode1.T_D, mode1.SIGMA0
A = 5.0                     # initial tip, m
NU = reference.POISSON["plane/stress"]
G_C = 2.0                   # J/m^2 at sigma0 = 1 MPa: t_i = 1.70 t_c, theory runs 0.77-0.98 m
M = 5.0                     # delta/dx
T_END = 1.2e-3              # run length, > 3 t_c = 1.10e-3 s
DUMP_DT = 1.0e-5            # s between damage snapshots
SPEED_TIMES = (2.0, 2.4, 2.8)   # in units of t_c
SPEED_HALF_WINDOW = 0.15        # in units of t_c
DX_DEFAULT = (0.1, 0.05)
DX_FULL = (0.1, 0.05, 0.025)
CSV_COLUMNS = ("kernel", "dx", "Gc", "dt", "atoms", "loop_s", "ti_pd", "ti_theory",
               "ti_err_pct", "J_at_ti_over_Gc", "ti_tip_pd", "ti_tip_err_pct",
               "J_at_ti_tip_over_Gc", "tip_check_dx", "width_3tc_over_delta", "ext_pd_3tc", "ext_toughness_3tc",
               "ext_energy_3tc", "l2_toughness_pct", "l2_energy_pct") + tuple(
    f"v_{s:g}tc_over_cR" for s in SPEED_TIMES) + ("cpu",)
TEXT_COLUMNS = ("kernel", "cpu")


def problem(G_c=G_C, sigma0=SIGMA0):
    """The theory of bbpd.crack_motion for the model's constants (plane stress)."""
    return crack_motion.RampProblem(E, NU, RHO, G_c, sigma0, T_D, H, A, freund.PLANE_STRESS)


def initiation_time(t, damage_sum):
    """Time of the first output at which the damage sum exceeds its initial value (the
    notch's damage): the first broken bond.  None if no bond breaks."""
    rise = np.nonzero(damage_sum > damage_sum[0])[0]
    return None if rise.size == 0 else float(t[rise[0]])


def speed_at(t, l, t0, half_window):
    """Least-squares slope of l(t) over |t - t0| <= half_window."""
    w = np.abs(t - t0) <= half_window
    if w.sum() < 3:
        return float("nan")
    return float(np.polyfit(t[w], l[w], 1)[0])


def l2_extension_error(t, l, l_theory, window):
    """sqrt(int (l - l_th)^2 dt / int (l_th - a)^2 dt) over the window (trapezoid)."""
    w = (t >= window[0]) & (t <= window[1])
    num = np.trapz((l[w] - l_theory[w]) ** 2, t[w])
    den = np.trapz((l_theory[w] - A) ** 2, t[w])
    return float(np.sqrt(num / den))


def band_width(dump_path, dt, t_end, threshold=crack_tip.DEFAULT_THRESHOLD):
    """Largest |y| of the atoms with damage >= threshold ahead of x = a in the last snapshot
    at or before t_end."""
    last = None
    for step, cols in readers.dump_snapshots(dump_path):
        if step * dt <= t_end * (1.0 + 1e-12):
            last = cols
    crack = (last["c_damage"] >= threshold) & (last["x"] >= A)
    return float(np.abs(last["y"][crack]).max()) if crack.any() else 0.0


def measure(t_k, k_cols, t_tip, ext_tip, dx, G_c=G_C):
    """All the numbers of one run.  k_cols: K_I (dsif), J, K_I(J), K_II(J), damage sum near
    the tip; ext_tip: crack extension at the times t_tip."""
    prob = problem(G_c)
    t_c, t_end = prob.t_c, prob.t_end
    ti_th = prob.initiation_time()
    ti_pd = initiation_time(t_k, k_cols[4])
    l_pd = A + ext_tip
    res = {"dx": dx, "Gc": G_c, "ti_theory": ti_th, "t_c": t_c, "c_r": prob.c_r,
           "ti_pd": ti_pd if ti_pd is not None else float("nan"),
           "t_tip": t_tip, "l_pd": l_pd}
    res["ti_err_pct"] = 100.0 * (res["ti_pd"] - ti_th) / (ti_th - t_c)
    res["J_at_ti_over_Gc"] = (float(np.interp(res["ti_pd"], t_k, k_cols[1])) / G_c
                              if ti_pd is not None else float("nan"))
    moved = np.nonzero(l_pd > A + 0.5 * dx)[0]
    res["ti_tip_pd"] = float(t_tip[moved[0]]) if moved.size else float("nan")
    res["ti_tip_err_pct"] = 100.0 * (res["ti_tip_pd"] - ti_th) / (ti_th - t_c)
    res["J_at_ti_tip_over_Gc"] = float(np.interp(res["ti_tip_pd"], t_k, k_cols[1])) / G_c
    window = (ti_th, t_end)
    res["ext_pd_3tc"] = float(np.interp(t_end, t_tip, l_pd)) - A
    for crit in crack_motion.CRITERIA:
        l_th, _ = prob.tip_position(t_tip, crit)
        res[f"l_{crit}"] = l_th
        res[f"ext_{crit}_3tc"] = float(prob.tip_position(np.array([t_end]), crit)[0][0]) - A
        res[f"l2_{crit}_pct"] = 100.0 * l2_extension_error(t_tip, l_pd, l_th, window)
    for s in SPEED_TIMES:
        res[f"v_{s:g}tc_over_cR"] = speed_at(t_tip, l_pd, s * t_c,
                                             SPEED_HALF_WINDOW * t_c) / prob.c_r
    return res


# a run's wall-time limit: dx = 0.00625 m (a million atoms) took 18 min on 2 Zen 4 cores, longer
# on slower or shared machines
RUN_TIMEOUT_S = 4 * 3600


def run(workdir, kernel="gaussian", dx=0.05, G_c=G_C, dt=None, nprocs=1, t_end=T_END,
        reuse=False):
    """Run the example once and measure it (see measure()); reuse=True measures the
    outputs of an earlier run in workdir (same arguments) without running LAMMPS."""
    dt = mode1.default_dt(dx) if dt is None else dt
    workdir = Path(workdir)
    vars_ = {"kernel": kernel, "dx": dx, "Gc": G_c, "m": M, "dt": dt, "tend": t_end,
             "dumpdt": DUMP_DT, "E": E, "rho": RHO, "H": H, "a": A, "td": T_D,
             "sigma0": SIGMA0}
    output, wall = run_or_reuse(EXAMPLE, workdir, vars_, nprocs, RUN_TIMEOUT_S, reuse)
    loop_s, _ = readers.loop_time(output)
    d = np.loadtxt(workdir / "k.dat", comments="#", ndmin=2)
    t_k = d[:, 0] * dt
    tip = np.loadtxt(workdir / "tip.dat", comments="#", ndmin=2)
    t_tip, ext = tip[:, 0] * dt, tip[:, 3]
    res = measure(t_k, d[:, 1:].T, t_tip, ext, dx, G_c)
    t_py, _, _, ext_py = crack_tip.tip_history(workdir / "damage.dump", dt, (A, 0.0), M * dx)
    res["tip_check_dx"] = float(np.max(np.abs(np.interp(t_py, t_tip, ext) - ext_py))) / dx
    res["width_3tc_over_delta"] = band_width(workdir / "damage.dump", dt, res["t_c"]
                                             * freund.MODE1_VALIDITY_MULTIPLE) / (M * dx)
    res.update({"kernel": kernel, "dt": dt, "nprocs": nprocs, "wall_time": wall,
                "loop_s": loop_s, "atoms": int(round(10.0 / dx)) * int(round(2 * H / dx)),
                "t_k": t_k, "J": d[:, 2], "damage_sum": d[:, 5], "cpu": cpu()})
    return res


# --------------------------------------------------------------------------- outputs

def write_csv(path, rows, provenance):
    """The results CSV: the commands that made its rows (csvfile.provenance lines), then one
    row per run, the loop time's CPU in a column (appended rows may come from another machine)."""
    csvfile.write_csv(path, rows, list(provenance) + [
        "timing: LAMMPS loop time, 1 rank, on the CPU of column cpu"], CSV_COLUMNS, TEXT_COLUMNS,
        nan="nan")


def merge_rows(earlier, new):
    """earlier rows with the runs of new added; a new run replaces an earlier one of the same
    kernel and dx; sorted by dx (coarse first), then kernel as KERNELS lists them"""
    key = {(r["kernel"], r["dx"]): r for r in earlier}
    key.update({(r["kernel"], r["dx"]): r for r in new})
    order = {k: i for i, k in enumerate(KERNELS)}
    return sorted(key.values(), key=lambda r: (-r["dx"], order.get(r["kernel"], len(order))))


def write_histories(path, rows):
    """Tip histories of every run (for the figures): kernel, dx, t, l."""
    csvfile.write_csv(path, [{"kernel": r["kernel"], "dx": r["dx"], "t": t, "l": l} for r in rows
                             for t, l in zip(r["t_tip"], r["l_pd"])], nan="nan")


def read_histories(path):
    """{(kernel, dx): (t, l)} of write_histories' file"""
    hist = {}
    for r in csvfile.read_csv(path, ("kernel",))[1]:
        hist.setdefault((r["kernel"], r["dx"]), []).append((r["t"], r["l"]))
    return {key: tuple(np.array(v).T) for key, v in hist.items()}


def read_rows(path, histories=None):
    """The CSV written by write_csv as a list of dicts (kernel and cpu strings, the rest floats),
    given histories (write_histories' file) with each run's tip history as t_tip, l_pd"""
    rows = csvfile.read_csv(path, TEXT_COLUMNS)[1]
    if histories:
        hist = read_histories(histories)
        for r in rows:
            r["t_tip"], r["l_pd"] = hist[(r["kernel"], r["dx"])]
    return rows


def cpu_markdown(rows):
    """Which CPU timed which runs (the loop-time column; a grid may have been timed on two)."""
    return csvfile.loop_times_note(rows, "cpu", lambda r: f"{r['kernel']} at dx = {r['dx']:g} m")


def table_markdown(rows):
    """The README table of a results CSV (rows: dicts with the CSV's columns)."""
    prob = problem(rows[0]["Gc"]) if rows else problem()
    out = [[r["kernel"], f"{r['dx']:g}", int(r["atoms"]),
            f"{1e3 * r['ti_pd']:.4f}, {r['ti_err_pct']:+.1f}, {r['J_at_ti_over_Gc']:.2f}",
            f"{1e3 * r['ti_tip_pd']:.4f}, {r['ti_tip_err_pct']:+.1f}, {r['J_at_ti_tip_over_Gc']:.2f}",
            f"{r['ext_pd_3tc']:.2f}", f"{r['l2_toughness_pct']:.1f}", f"{r['l2_energy_pct']:.1f}",
            ", ".join(f"{r[f'v_{s:g}tc_over_cR']:.2f}" for s in SPEED_TIMES),
            f"{r['width_3tc_over_delta']:.2f}", f"{r['loop_s']:.1f}"] for r in rows]
    t_i = f"{1e3 * prob.initiation_time():.4f}, 0, 1"
    for crit, name in (("toughness", "K_Ic form"), ("energy", "energy form")):
        ext = prob.tip_position(np.array([prob.t_end]), crit)[0][0] - A
        v_th = [prob.tip_position(np.array([s * prob.t_c]), crit)[1][0] / prob.c_r for s in SPEED_TIMES]
        out.append([f"theory, {name}", "", "", t_i, t_i, f"{ext:.2f}", "", "",
                    ", ".join(f"{v:.2f}" for v in v_th), "", ""])
    table = md_table(["kernel", "dx (m)", "atoms", "first bond: t_i (ms), error (%), J/G_c",
                      "tip moved: t_i (ms), error (%), J/G_c", "extension at 3 t_c (m)",
                      "L2 of l(t), K_Ic form (%)", "L2 of l(t), energy form (%)",
                      "v/c_R at " + ", ".join(f"{s:g}" for s in SPEED_TIMES) + " t_c",
                      "crack half-width at 3 t_c (delta)", "loop time (s)"], out)
    return table + "\n\n" + cpu_markdown(rows) if rows and all("cpu" in r for r in rows) else table


FIGURE_NAMES = ("crack_extension.png", "crack_speed.png", "work_precision.png")


def figures(rows, folder, prefix=""):
    """l(t) and v(t) of every run (rows with kernel, dx, Gc, t_tip, l_pd) with the theory in
    both forms of the equation of motion, and the work-precision figure; returns the names."""
    prob = problem(rows[0]["Gc"])
    t_c = prob.t_c
    tt = np.linspace(0.0, prob.t_end, 600)
    dxs = sorted({r["dx"] for r in rows}, reverse=True)
    styles = dict(zip(dxs, (":", "--", "-", "-.")))
    names = [prefix + n for n in FIGURE_NAMES]
    with (plots.figure(Path(folder) / names[0], figsize=(7, 4.5), dpi=110) as (_, ax_l),
          plots.figure(Path(folder) / names[1], figsize=(7, 4.5), dpi=110) as (_, ax_v)):
        for crit, col in (("toughness", "black"), ("energy", "grey")):
            l_th, v_th = prob.tip_position(tt, crit)
            label = "Freund, K = K_Ic" if crit == "toughness" else "Freund, G = G_c"
            ax_l.plot(tt / t_c, l_th - A, color=col, lw=2.5, label=label)
            ax_v.plot(tt / t_c, v_th / prob.c_r, color=col, lw=2.5, label=label)
        for r in sorted(rows, key=lambda r: (r["kernel"], r["dx"])):
            t, l = np.asarray(r["t_tip"], dtype=float), np.asarray(r["l_pd"], dtype=float)
            style, color = styles.get(r["dx"], "-"), COLORS.get(r["kernel"])
            label = f"{r['kernel']}, dx = {r['dx']:g}"
            ax_l.plot(t / t_c, l - A, style, color=color, label=label)
            tv = np.linspace(t_c, prob.t_end - SPEED_HALF_WINDOW * t_c, 60)
            v = [speed_at(t, l, x, SPEED_HALF_WINDOW * t_c) for x in tv]
            ax_v.plot(tv / t_c, np.array(v) / prob.c_r, style, color=color, label=label)
        for ax, ylabel in ((ax_l, "crack extension l - a (m)"), (ax_v, "crack speed v / c_R")):
            ax.axvline(prob.t_end / t_c, color="k", lw=0.8, ls=":")
            ax.set(xlabel="t / t_c", ylabel=ylabel, xlim=(1.0, 3.2))
            ax.legend(fontsize=7, ncol=2)
        ax_v.set_ylim(0.0, 1.05)
        ax_v.set_title(f"v: slope of l(t) over +-{SPEED_HALF_WINDOW:g} t_c", fontsize=9)
    work_precision_figure(rows, Path(folder) / names[2])
    return names


def work_precision_figure(rows, path):
    """|t_i error| and the L2 error of l(t) (energy form) against the loop time, one line per
    kernel through its grids."""
    metrics = (("ti_err_pct", "|t_i error| (% of t_i - t_c), first bond"),
               ("l2_energy_pct", "L2 of l(t), energy form (%)"),
               ("l2_toughness_pct", "L2 of l(t), K_Ic form (%)"))
    with plots.figure(path, 1, 3, figsize=(11, 3.8), dpi=110) as (_, axes):
        for ax, (col, label) in zip(axes, metrics):
            for kernel in KERNELS:
                rs = sorted((r for r in rows if r["kernel"] == kernel), key=lambda r: -r["dx"])
                x = [r["loop_s"] for r in rs]
                y = [max(abs(r[col]), 1e-2) for r in rs]
                if rs:
                    ax.loglog(x, y, "o-", color=COLORS.get(kernel), label=kernel)
                for r, xi, yi in zip(rs, x, y):
                    ax.annotate(f"{r['dx']:g}", (xi, yi), fontsize=7)
            cpus = sorted({r.get("cpu", cpu()) for r in rows})
            ax.set_xlabel("loop time (s), 1 rank\n" + "; ".join(cpus), fontsize=7)
            ax.set_ylabel(label, fontsize=8)
            ax.legend(fontsize=7)


# --------------------------------------------------------------------------- report

REPORT_TITLE = "Mode-I crack growth against Freund's equation of motion"
REPORT_SETUP = ("The stationary Mode-I plate with fracture on: G_c = 2 J/m^2 at sigma0 = 1 MPa, "
                "plane stress, m = 5, unbreakable bands 0.5 m wide along the edges; t_i from "
                "K_I(t_i) = sqrt(E G_c) with eq. 42 (the model's constants), l(t) from Freund's "
                "equation of motion in the K_Ic form (k(v) K* = K_Ic) and the energy form "
                "(v = c_R (1 - K_Ic^2/K*^2)), t <= 3 t_c; tip from compute bbpd/crack/tip; "
                "see examples/mode1-propagation/README.md.")


def section(specs, results, figdir, notes):
    """The section of REPORT.md (bbpd.report.document.write_report) from the report's runs."""
    return jobmod.section(REPORT_TITLE, REPORT_SETUP, specs, results, table_markdown, None,
                          lambda rows: figures(rows, figdir, prefix="mode1_propagation_"),
                          notes)


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/bbpd-mode1-propagation", nprocs=1, kernels=KERNELS,
                    dx=DX_DEFAULT, reuse=True, csv="results CSV to write (or, with --append, add "
                    "to)", append="keep the CSV's rows and tip histories; a run of the same "
                    "kernel and dx replaces its row",
                    figures="folder for crack_extension.png and crack_speed.png")
    ap.add_argument("--full", action="store_true", help=f"dx = {DX_FULL}")
    ap.add_argument("--Gc", type=float, default=G_C)
    args = ap.parse_args(argv)
    dxs = DX_FULL if args.full else args.dx
    command = cli.command("mode1_propagation", argv, drop=("--reuse",))
    rows = []
    for dx in dxs:
        for kernel in args.kernels:
            res = run(Path(args.work) / f"{kernel}_{dx}", kernel, dx, args.Gc,
                      nprocs=args.nprocs, reuse=args.reuse)
            rows.append(res)
            print(f"{kernel} dx {dx:g}: t_i error {res['ti_err_pct']:+.1f} %, L2 of l(t) "
                  f"{res['l2_toughness_pct']:.1f} / {res['l2_energy_pct']:.1f} %", flush=True)
    if args.csv:
        histories = Path(args.csv).with_name("tip_histories.csv")
        provenance, earlier, this = csvfile.continue_csv(args.csv if args.append else None,
                                                         command, lambda p: read_rows(p, histories))
        if earlier:
            rows = merge_rows(earlier, rows)
        write_csv(args.csv, rows, provenance + [this])
        write_histories(histories, rows)
        if args.figures:
            figures(read_rows(args.csv, histories), args.figures)


if __name__ == "__main__":
    main()


# --------------------------------------------------------------------------- README findings
# A halving of dx "settles" the extension at 3 t_c when it moves it by less than this share
# of the gap between the two forms' predictions: the remaining change could then not carry
# the crack from one form to the other.
SETTLED_SHARE_OF_GAP = 0.1
# the crack band "does not shrink" with the horizon when the finest grid's widest band keeps
# this share of the next coarser grid's (a band set by the horizon would halve)
WIDTH_KEPT = 0.75


def finest_rows(rows):
    """each kernel's run on its finest grid (a finer grid may have run one kernel only)"""
    return [min((r for r in rows if r["kernel"] == k), key=lambda r: r["dx"])
            for k in KERNELS if any(r["kernel"] == k for r in rows)]


def extension_changes(rows):
    """{kernel: [extension change at 3 t_c per halving of dx, coarse first]}"""
    out = {}
    for k in sorted({r["kernel"] for r in rows}):
        ext = [r["ext_pd_3tc"] for r in sorted((r for r in rows if r["kernel"] == k),
                                               key=lambda r: -r["dx"])]
        out[k] = [b - a for a, b in zip(ext, ext[1:])]
    return out


def growth_verdict(rows):
    """Per kernel on its finest grid: {'settled': the last halving of dx moved the extension at
    3 t_c by less than SETTLED_SHARE_OF_GAP of the gap between the two forms of Freund's
    equation, 'nearest': the form ('toughness' or 'energy') the finest extension lies nearest,
    'last': that change (m), 'gap': the gap (m)}"""
    gap = abs(rows[0]["ext_energy_3tc"] - rows[0]["ext_toughness_3tc"])
    out = {}
    finest = {r["kernel"]: r for r in finest_rows(rows)}
    for k, ch in extension_changes(rows).items():
        fine = finest[k]
        near = min(("toughness", "energy"), key=lambda c: abs(fine["ext_pd_3tc"]
                                                              - fine[f"ext_{c}_3tc"]))
        last = abs(ch[-1]) if ch else float("inf")
        out[k] = dict(settled=last < SETTLED_SHARE_OF_GAP * gap, nearest=near, last=last, gap=gap)
    return out


def band_kept(rows):
    """kernels whose widest crack band at 3 t_c on the finest grid keeps WIDTH_KEPT of its width
    (in metres) on the next coarser grid: a band set by the horizon would halve"""
    out = []
    for k in sorted({r["kernel"] for r in rows}):
        w = [r["width_3tc_over_delta"] * M * r["dx"]
             for r in sorted((r for r in rows if r["kernel"] == k), key=lambda r: -r["dx"])]
        if len(w) > 1 and w[-1] >= WIDTH_KEPT * w[-2]:
            out.append(k)
    return out
