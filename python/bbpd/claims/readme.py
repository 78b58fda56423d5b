# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of the top-level README.md: the benchmark summary (from every benchmark's reference
CSV) and the quick start's step times (doc/results/quickstart_times.csv)."""
from bbpd.kernels import KERNELS

from . import kw, mode1, mode2
from .text import md_table, mm, name, sci, span

DISPERSION_KDX = 2.5    # the k dx of the c/v the summary quotes (report.tables.DISP_KDX[-1])


def _dispersion(data):
    rows = {r["kernel"]: r for r in data.rows("dispersion")}
    cv = ", ".join(f"{name(k)} {rows[k][f'phase_kdx{DISPERSION_KDX:g}']:.3f}" for k in KERNELS
                   if k in rows)
    dev = max(r["max_dev_discrete_dt"] for r in rows.values())
    return ("| 1D wave dispersion (sec. 4.1, Figs. 4–6), `examples/dispersion-1d` | dispersion "
            "curves of eqs. 29–38; Gaussian least dispersive; negative group velocity for the "
            "constant kernel | measured ω(k) from LAMMPS runs + FFTW agrees with the discrete "
            "relation our code integrates (with C_v and the time step) to "
            f"{sci(dev)} up to k dx = 2.5 for all kernels; c/v at k dx = {DISPERSION_KDX:g}: "
            f"{cv} | Gaussian least dispersive: reproduced. Negative v_g appears only for eq. 31 "
            "as printed; with the partial-volume weights (what the code integrates) v_g ≥ 0 |")


def _mode1(data):
    t2, t3 = mode1.paper()
    at = mode1._at(data, mode1.TABLE3_DX)
    g = mode1._gauss(data)
    rows = data.rows(mode1.NAME)
    ours = " < ".join(name(k) for k in sorted(at, key=lambda k: at[k]["consistent_l2"]))
    theirs = " < ".join(name(k) for k in sorted(at, key=lambda k: t3[k][1]))
    diffs = [abs(at[k][c] - t3[k][i]) for k in at if k != "gaussian"
             for i, c in ((0, "consistent_peak"), (1, "consistent_l2"))]
    cells = ", ".join(f"{name(k)} {at[k]['consistent_peak']:.2f} / {at[k]['consistent_l2']:.2f}"
                      for k in ("gaussian", "triangular", "constant"))
    return ("| Mode-I semi-infinite crack (sec. 4.2.1, Tables 2–3) | Gaussian peak / L2 error "
            f"{t3['gaussian'][0]:.2f} / {t3['gaussian'][1]:.2f} % at Δx = 0.05; constant "
            f"{t3['constant'][0]:.2f} / {t3['constant'][1]:.2f}, triangular "
            f"{t3['triangular'][0]:.2f} / {t3['triangular'][1]:.2f} | consistent constants, "
            f"Δx = 0.05: {cells} %; Gaussian L2 "
            + " → ".join(f"{r['consistent_l2']:.2f}" for r in g) + " % at Δx = "
            + ", ".join(f"{r['dx_m']:g}" for r in g) + "; K_I from the J-integral within "
            f"{max(r['j_peak'] for r in rows):.1f} % (peak) for every kernel and grid, Gaussian "
            f"{max(r['j_peak'] for r in rows if r['kernel'] == 'gaussian'):.1f} % | kernel "
            f"ranking {ours} " + ("reproduced" if ours == theirs else f"(paper: {theirs})")
            + f"; triangular and constant within {max(diffs):.1f} points of the paper |")


def _mode2(data):
    grids = mode2._grids(data)
    gauss = [mode2._at(data, dx)["gaussian"]["j_peak"] for dx in grids]
    best = sum(min(mode2._at(data, dx).items(), key=lambda kr: kr[1]["j_peak"])[0] == "gaussian"
               for dx in grids)
    worst = sum(max(mode2._at(data, dx).items(), key=lambda kr: kr[1]["j_peak"])[0] == "constant"
                for dx in grids)
    return ("| Mode-II central crack (sec. 4.2.2, Fig. 12) | \"good agreement, particularly for "
            "the Gaussian\" against a J-integral curve | against an analytic early-time reference "
            "(checked by classical FE): displacement extrapolation "
            f"{mode2.excess(data)} too high at the end of the window for every kernel, not "
            f"shrinking with Δx; K_II from our J-integral "
            f"{span([r['j_peak'] for r in data.rows(mode2.NAME)], '.1f', ' %')} (peak), "
            "converging to the reference (Gaussian " + " → ".join(f"{v:.1f}" for v in gauss)
            + " % at Δx = " + ", ".join(mm(dx) for dx in grids) + " mm) | with the extrapolation "
            "**not reproduced**; with the J-integral reproduced: the excess lives in the "
            "near-tip extrapolation, not in the peridynamic field; by the peak error of J the "
            f"Gaussian is closest at {best} of {len(grids)} grids, the constant farthest at "
            f"{worst} of {len(grids)} |")


def _kw(data):
    paper, exp = kw._consts()
    at = kw._at(data, 1.0e-3)
    g = [r for r in kw._gauss(data) if r["dx_m"] < 1.0e-3]
    order = " < ".join(name(k) for k in sorted(at, key=lambda k: at[k]["damage_band_us"]))
    paper_order = " < ".join(name(k) for k in sorted(at, key=lambda k: paper[k]))
    angles = [r["angle_deg"] for r in at.values()]
    return ("| Kalthoff–Winkler (sec. 4.2.3, Figs. 14–15) | initiation "
            + " / ".join(f"{paper[k]:.1f}" for k in KERNELS) + " µs (constant / triangular / "
            "Gaussian); Gaussian closest to the experiment's 70° | damage band leaves the tips "
            "at " + " / ".join(f"{at[k]['damage_band_us']:.1f}" for k in KERNELS)
            + f" µs (1 mm; order {order}), first broken bond at "
            f"{span([r['first_bond_us'] for r in at.values()], '.1f')} µs; angle "
            + " / ".join(f"{at[k]['angle_deg']:.1f}" for k in KERNELS) + "° at 1 mm"
            + "".join(f", Gaussian {r['angle_deg']:.1f}° at {mm(r['dx_m'])} mm" for r in g)
            + "; cracks exact mirror images; a spall crack opens at the far edge (the held "
            "impact velocity) | order of initiation "
            + ("reproduced" if order == paper_order else "not reproduced")
            + f"; angles {span([exp - a for a in angles], '.0f')}° flatter than the experiment. "
            "[Loading study](examples/kalthoff-winkler/README.md#loading-study) (v0, ramp, "
            "release, layer): no loading gives the experiment's angle and the paper's "
            "initiation time together |")


def benchmarks(data):
    return "\n".join(["| benchmark | paper | ours | verdict |", "|---|---|---|---|",
                      _dispersion(data), _mode1(data), _mode2(data), _kw(data)])


def quickstart_times(data):
    rows = data.rows("quickstart_times")
    table = md_table(["command", "step", "wall time (s)"],
                     [[f"`{r['command']}`", r["step"], f"{r['wall_s']:.0f}"] for r in rows])
    return (f"Wall time of each step as the commands print it ({data.source('quickstart_times')})"
            ": " + "; ".join(c for c in data.comments("quickstart_times")
                             if not c.startswith("made by:")) + ".\n\n" + table)


