# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of the paper's benchmarks: examples/mode1-semi-infinite, examples/mode2-central-crack,
examples/kalthoff-winkler (its main table) and doc/verification.md (the paper's numbers beside
ours, the quick start's step times), from the reference CSVs of bbpd.claims.data."""
from bbpd import csvfile
from bbpd.benchmarks import kalthoff_winkler as kw_bench
from bbpd.benchmarks import mode1 as mode1_bench
from bbpd.benchmarks import mode1_lps
from bbpd.kernels import KERNELS
from bbpd.jobs import ROOT
from bbpd.markdown import made_by
from bbpd.markdown import table as md_table

MODE1, MODE2, KW, TIPS = "mode1", "mode2", "kalthoff_winkler", "mode1_tips"
TABLE3_DX = mode1_bench.TABLE3_DX
DISPERSION_KDX = 2.5    # the k dx of the c/v the table quotes (dispersion.TABLE_KDX[-1])
DASH = "–"


# --------------------------------------------------------------------------- number formats

def span(values, spec=".1f", unit=""):
    """'a–b' over the values (rounded first), or 'a' when they round alike."""
    vals = [v for v in values if v is not None]
    lo, hi = format(min(vals), spec), format(max(vals), spec)
    return (lo if lo == hi else f"{lo}{DASH}{hi}") + unit


def sci(v):
    """6e-06 -> 6e-6"""
    mant, exp = f"{v:.0e}".split("e")
    return f"{mant}e{int(exp)}"


def mm(dx):
    return f"{dx * 1e3:g}"


def at(rows, dx):
    """{kernel: row} of the rows at grid spacing dx (m)"""
    return {r["kernel"]: r for r in rows if abs(r["dx_m"] - dx) < 1e-12}


def grids(rows):
    """the rows' grid spacings, coarsest first"""
    return sorted({r["dx_m"] for r in rows}, reverse=True)


def gauss(rows):
    """the Gaussian kernel's rows, coarsest first"""
    return sorted((r for r in rows if r["kernel"] == "gaussian"), key=lambda r: -r["dx_m"])


def _order(values):
    """kernels by value: 'gaussian < triangular < constant'"""
    return " < ".join(sorted(values, key=values.get))


def _three(values, spec=".2f"):
    """constant / triangular / Gaussian"""
    return " / ".join(format(values[k], spec) for k in KERNELS if k in values)


# --------------------------------------------------------------------------- tables

MOST_COMMANDS = 20    # a CSV written by more commands names them in its header only


def made(path, render, timing=False):
    """A block: render(data) under the commands of the CSV at path's provenance lines ('made
    by: X', 'rows added by: Y') and, with timing, its timing line"""
    commands = [ln.split(": ", 1)[1] for ln in csvfile.provenance(path)]
    intro = (made_by(commands) if len(commands) <= MOST_COMMANDS else
             f"Made by `{commands[0]}`; rows added by {len(commands) - 1} more commands, each "
             f"named in the header of `{path.relative_to(ROOT)}`.")
    if timing:
        intro += f" Timing: {csvfile.comment(path, 'timing')}."
    return lambda data: intro + "\n\n" + render(data)


def with_run_note(table, name):
    """render(data): table(rows of the reference `name`) and the note under a table of one
    single-rank run per row"""
    return lambda data: table(data.rows(name)) + (
        f"\n\nFrom {data.source(name)}. Run time: one single-rank run, two at a time on "
        f"{data.cpu(name)} (cores shared with other jobs). Every other number is deterministic.")


def tips_table(data):
    def where(x):
        return {0.5: "+0.5 dx", -0.5: "-0.5 dx", 0.0: "0"}.get(x, f"{x:+g} dx")

    def pair(r, a, b):
        return f"{r[a]:.2f} / {r[b]:.2f}"
    header = ["tip x - a", "r1, r2 (dx)", "face nodes at x - a", "K_max / K_max,exact (consistent)",
              "consistent peak / L2", "paper peak / L2"]
    rows = [[where(r["tipshift_dx"]) + (" (default, paper Fig. 7)" if i == 0 else ""),
             f"{r['r1_dx']:g}, {r['r2_dx']:g}",
             f"{r['tipshift_dx'] - r['r1_dx']:g}, {r['tipshift_dx'] - r['r2_dx']:g} dx",
             f"{r['kmax_ratio']:.3f}", pair(r, "consistent_peak", "consistent_l2"),
             pair(r, "paper_peak", "paper_l2")] for i, r in enumerate(data.rows(TIPS))]
    return md_table(header, rows) + f"\n\nFrom {data.source(TIPS)}."


lps_table = made(mode1_lps.CSV, lambda data: mode1_lps.table(mode1_lps.read_rows(), data.rows(MODE1)))


def mode2_excess(data):
    """'11.9–28.9 %' of the extrapolation at the window end, over every run."""
    return span([100 * (r["ratio_end"] - 1) for r in data.rows(MODE2)], ".0f", " %")


def benchmarks(data):
    """doc/verification.md: one row per quantity: benchmark, quantity, the paper's value, ours
    (kernels in the order constant / triangular / Gaussian)"""
    disp = {r["kernel"]: r for r in data.rows("dispersion")}
    cv = {k: r[f"phase_kdx{DISPERSION_KDX:g}"] for k, r in disp.items()}
    t2, t3 = mode1_bench.PAPER_TABLE2, mode1_bench.PAPER_TABLE3
    m1 = data.rows(MODE1)
    at3 = at(m1, TABLE3_DX)
    g = gauss(m1)
    m2 = data.rows(MODE2)
    paper, exp = kw_bench.PAPER_INITIATION_US, kw_bench.EXPERIMENT_ANGLE_DEG
    kat = at(data.rows(KW), 1.0e-3)
    fine = [r for r in gauss(data.rows(KW)) if r["dx_m"] < 1.0e-3]
    rows = [
        ["dispersion (sec. 4.1)", "measured ω(k) against the relation integrated, up to k dx = 2.5",
         "-", sci(max(r["max_dev_discrete_dt"] for r in disp.values()))],
        ["", f"c/v at k dx = {DISPERSION_KDX:g}, kernels by dispersion (least first)",
         "gaussian < triangular < constant", f"{_three(cv, '.3f')}: {_order({k: -v for k, v in cv.items()})}"],
        ["Mode I (Tables 2-3)", f"peak / L2 error (%) at dx = {TABLE3_DX:g} m, consistent constants",
         " ; ".join(f"{t3[k][0]:.2f} / {t3[k][1]:.2f}" for k in KERNELS),
         " ; ".join(f"{at3[k]['consistent_peak']:.2f} / {at3[k]['consistent_l2']:.2f}" for k in KERNELS)],
        ["", "kernels by L2 error", _order({k: t3[k][1] for k in at3}),
         _order({k: r["consistent_l2"] for k, r in at3.items()})],
        ["", "Gaussian L2 (%) at dx = " + ", ".join(f"{r['dx_m']:g}" for r in g) + " m",
         ", ".join(f"{t2[round(r['dx_m'], 6)][1]:.2f}" if round(r["dx_m"], 6) in t2 else "-" for r in g),
         ", ".join(f"{r['consistent_l2']:.2f}" for r in g)],
        ["", "K_I from the J-integral: largest peak error (%), every kernel and grid", "-",
         f"{max(r['j_peak'] for r in m1):.1f}"],
        ["Mode II (Fig. 12)", "K_II by displacement extrapolation at the window end, above the reference",
         "\"good agreement\"", mode2_excess(data)],
        ["", "K_II from the J-integral, peak error (%)", "-",
         span([r["j_peak"] for r in m2], ".1f") + "; Gaussian " + ", ".join(
             f"{at(m2, dx)['gaussian']['j_peak']:.1f}" for dx in grids(m2))
         + " at dx = " + ", ".join(mm(dx) for dx in grids(m2)) + " mm"],
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
