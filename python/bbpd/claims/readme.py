# SPDX-License-Identifier: GPL-2.0-or-later
"""Tables of doc/verification.md: the paper's benchmarks, the paper's numbers beside ours (from
every benchmark's reference CSV), and the quick start's step times
(doc/results/quickstart_times.csv)."""
from bbpd.kernels import KERNELS

from . import kw, mode1, mode2
from .text import at as at_dx
from .text import grids as grids_of
from .text import md_table, mm, sci, span

DISPERSION_KDX = 2.5    # the k dx of the c/v the table quotes (dispersion.TABLE_KDX[-1])


def _order(values):
    """kernels by value: 'gaussian < triangular < constant'"""
    return " < ".join(sorted(values, key=values.get))


def _three(values, spec=".2f"):
    """constant / triangular / Gaussian"""
    return " / ".join(format(values[k], spec) for k in KERNELS if k in values)


def benchmarks(data):
    """One row per quantity: benchmark, quantity, the paper's value, ours (kernels in the order
    constant / triangular / Gaussian)"""
    disp = {r["kernel"]: r for r in data.rows("dispersion")}
    cv = {k: r[f"phase_kdx{DISPERSION_KDX:g}"] for k, r in disp.items()}
    t2, t3 = mode1.paper()
    m1 = data.rows(mode1.NAME)
    at = at_dx(m1, mode1.TABLE3_DX)
    g = mode1._gauss(data)
    m2 = data.rows(mode2.NAME)
    grids = grids_of(m2)
    paper, exp = kw._consts()
    kat = at_dx(data.rows(kw.NAME), 1.0e-3)
    fine = [r for r in kw._gauss(data) if r["dx_m"] < 1.0e-3]
    rows = [
        ["dispersion (sec. 4.1)", "measured ω(k) against the relation integrated, up to k dx = 2.5",
         "-", sci(max(r["max_dev_discrete_dt"] for r in disp.values()))],
        ["", f"c/v at k dx = {DISPERSION_KDX:g}, kernels by dispersion (least first)",
         "gaussian < triangular < constant", f"{_three(cv, '.3f')}: {_order({k: -v for k, v in cv.items()})}"],
        ["Mode I (Tables 2-3)", f"peak / L2 error (%) at dx = {mode1.TABLE3_DX:g} m, consistent constants",
         " ; ".join(f"{t3[k][0]:.2f} / {t3[k][1]:.2f}" for k in KERNELS),
         " ; ".join(f"{at[k]['consistent_peak']:.2f} / {at[k]['consistent_l2']:.2f}" for k in KERNELS)],
        ["", "kernels by L2 error", _order({k: t3[k][1] for k in at}),
         _order({k: r["consistent_l2"] for k, r in at.items()})],
        ["", "Gaussian L2 (%) at dx = " + ", ".join(f"{r['dx_m']:g}" for r in g) + " m",
         ", ".join(f"{t2[round(r['dx_m'], 6)][1]:.2f}" if round(r["dx_m"], 6) in t2 else "-" for r in g),
         ", ".join(f"{r['consistent_l2']:.2f}" for r in g)],
        ["", "K_I from the J-integral: largest peak error (%), every kernel and grid", "-",
         f"{max(r['j_peak'] for r in m1):.1f}"],
        ["Mode II (Fig. 12)", "K_II by displacement extrapolation at the window end, above the reference",
         "\"good agreement\"", mode2.excess(data)],
        ["", "K_II from the J-integral, peak error (%)", "-",
         span([r["j_peak"] for r in m2], ".1f") + "; Gaussian " + ", ".join(
             f"{at_dx(m2, dx)['gaussian']['j_peak']:.1f}" for dx in grids)
         + " at dx = " + ", ".join(mm(dx) for dx in grids) + " mm"],
        ["Kalthoff-Winkler (Figs. 14-15)", "initiation (us): damage band at 1 mm", _three(paper, ".1f"),
         _three({k: r["damage_band_us"] for k, r in kat.items()}, ".1f")],
        ["", "kernels by initiation time", _order(paper), _order({k: r["damage_band_us"] for k, r in kat.items()})],
        ["", f"crack angle (deg) at 1 mm; experiment {exp:.0f}", "Gaussian closest",
         _three({k: r["angle_deg"] for k, r in kat.items()}, ".1f")
         + "".join(f"; Gaussian {r['angle_deg']:.1f} at {mm(r['dx_m'])} mm" for r in fine)],
    ]
    return md_table(["benchmark", "quantity", "paper", "ours"], rows)


def quickstart_times(data):
    rows = data.rows("quickstart_times")
    table = md_table(["command", "step", "wall time (s)"],
                     [[f"`{r['command']}`", r["step"], f"{r['wall_s']:.0f}"] for r in rows])
    return (f"Wall time of each step as the commands print it ({data.source('quickstart_times')})"
            ": " + "; ".join(c for c in data.comments("quickstart_times")
                             if not c.startswith("made by:")) + ".\n\n" + table)


