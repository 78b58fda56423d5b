# SPDX-License-Identifier: GPL-2.0-or-later
"""One section of REPORT.md per benchmark: its title, the setup it ran, the table, the lines
under it (sentences written by hand as templates, the runs' numbers filled in; the Mode-II
verdict as data, mode2_j) and the figures (a figure that fails is noted in the report)."""
from pathlib import Path

import numpy as np

from bbpd.benchmarks import (branching, dispersion, kalthoff_winkler, kalthoff_winkler_3d,
                             kalthoff_winkler_deck, kalthoff_winkler_grid,
                             kalthoff_winkler_projectile, kalthoff_winkler_study, kink,
                             kink_convergence, mode1, mode1_propagation, mode2, quasi_static,
                             strip)
from bbpd.kernels import COLORS, KERNELS
from bbpd.plots import plot_k

from . import tables
from .runs import MODE1_TABLE3_DX
from .tables import md_table

NEGATIVE_VG = -1.0e-3      # measured v_g/v below this counts as negative (the ridge's noise
                           # in the gradient is ~1e-5 of v)
# largest share of the extrapolation's excess that K_II from J may carry for the verdict
# "the excess is in the extrapolation" (and 1 minus it for "in the field")
MODE2_FIELD_SHARE = 0.25

DISPERSION = ("Largest deviation of the measured ridge from the relation LAMMPS integrates (eq. 31 "
              "with C_v and the velocity-Verlet shift), k dx {k0:g}-{k1:g}: {dev:.1e} ({worst}). "
              "Negative group velocity measured: {measured}; eq. 31 as printed: {printed} (the "
              "paper's Fig. 6); with C_v: {cv}.")
MODE1 = ("Table 3, L2 errors (consistent constants) rank {ours}; the paper's {paper}.")
MODE1_J = ("K_I from the J-integral (annulus 0.5-1.5 m), peak errors {j[0]:.2f}-{j[1]:.2f} %; "
           "displacement extrapolation {d[0]:.2f}-{d[1]:.2f} %.")
MODE2 = ("K_II/K_II,ref at the end of the window by extrapolation (tip on the first intact "
         "column, r1 = dx, r2 = 2 dx): {ratio[0]:.3f}-{ratio[1]:.3f}.")
MODE2_J = ("From the J-integral (annulus 5-12.5 mm): {j[0]:.3f}-{j[1]:.3f}; the excess lives in "
           "the {where}.")
KW_ORDER = ("dx = {dx:g} mm: the damage band leaves the tips in the order {order}; the paper's "
            "initiation: {paper}.")
KW_SYMMETRY = "Mirror symmetry of the two cracks: tip mismatch <= {tip:.1g} mm."


def ranking(values):
    """Names ordered by value, None (failed) left out: 'a < b < c'."""
    ok = [(v, k) for k, v in values.items() if v is not None]
    return " < ".join(k for _, k in sorted(ok))


def _names(kernels):
    return ", ".join(kernels) or "none"


def _span(values):
    return min(values), max(values)


def dispersion_text(numbers, table):
    """numbers: dispersion.table's; table: dispersion.analytic_table's."""
    min_vg, dev = numbers["min_vg"], numbers["dev"]
    if not dev:
        return []
    worst = max(dev, key=dev.get)
    negative = {c: _names([k for k in KERNELS if table[k][c]["group_negative"]])
                for c in ("discrete", "discrete_cv")}
    return [DISPERSION.format(
        k0=dispersion.KDX_RANGE[0], k1=dispersion.KDX_RANGE[1], dev=dev[worst], worst=worst,
        measured=_names([k for k, g in min_vg.items() if g is not None and g < NEGATIVE_VG]),
        printed=negative["discrete"], cv=negative["discrete_cv"])]


def mode1_text(ok, rows3_ok):
    """ok: every finished run by (kernel, dx); rows3_ok: Table 3's by kernel."""
    text = [MODE1.format(ours=ranking({k: r["consistent"]["l2"] for k, r in rows3_ok.items()}),
                         paper=ranking({k: mode1.PAPER_TABLE3[k][1] for k in rows3_ok}))
            ] if rows3_ok else []
    withj = [key for key, r in ok.items() if "jintegral" in r]
    if withj:
        text.append(MODE1_J.format(j=_span([ok[k]["jintegral"]["consistent"]["peak"] for k in withj]),
                                   d=_span([ok[k]["consistent"]["peak"] for k in withj])))
    return text


def mode2_j(ok):
    """Where the Mode-II excess lives, as data: K_II/K_ref at the window end from the
    extrapolation ('dsif') and from the J-integral ('j'), the share of the extrapolation's
    excess that J carries, 'where': 'extrapolation' (J carries less than MODE2_FIELD_SHARE of
    it), 'field' (more than 1 - MODE2_FIELD_SHARE) or 'partly', and per dx the kernels' peak
    errors of J; None without J."""
    withj = {key: r for key, r in ok.items() if "jintegral" in r}
    if not withj:
        return None
    rd = {key: r["k_end"] / r["k_end_exact"] for key, r in withj.items()}
    rj = {key: r["jintegral"]["k_end"] / r["k_end_exact"] for key, r in withj.items()}
    share = {key: (rj[key] - 1.0) / (rd[key] - 1.0) for key in withj if rd[key] != 1.0}
    where = ("extrapolation" if share and max(share.values()) < MODE2_FIELD_SHARE else
             "field" if share and min(share.values()) > 1.0 - MODE2_FIELD_SHARE else "partly")
    peaks = {dx: {k: r["jintegral"]["peak"] for (k, d), r in withj.items() if d == dx}
             for dx in sorted({d for _, d in withj}, reverse=True)}
    return dict(dsif=rd, j=rj, share=share, where=where, peaks=peaks)


def mode2_text(ok):
    """ok: (kernel, dx) -> finished result."""
    if not ok:
        return []
    j = mode2_j(ok)
    return ([MODE2.format(ratio=_span([r["k_end"] / r["k_end_exact"] for r in ok.values()]))]
            + ([MODE2_J.format(j=_span(j["j"].values()), where=j["where"])] if j else []))


def kw_text(ok):
    """ok: (kernel, dx) -> finished result. What the table does not show: the order in which
    the damage band leaves the tips against the paper's initiation order, per dx, and the
    mirror symmetry of the two cracks."""
    text = []
    for dx in sorted({dx for _, dx in ok}, reverse=True):
        same = {k: r for (k, d), r in ok.items() if d == dx}
        if len(same) > 1:
            text.append(KW_ORDER.format(
                dx=dx * 1e3, order=ranking({k: r["t_band_us"] for k, r in same.items()}),
                paper=ranking({k: kalthoff_winkler.PAPER_INITIATION_US[k] for k in same})))
    if ok:
        text.append(KW_SYMMETRY.format(tip=max(r["symmetry_tip_mm"] for r in ok.values())))
    return text


# --------------------------------------------------------------------------- figures

def _figures(make, what, notes):
    """The names of the figures make() draws (it returns their paths), or [] with a note in the
    report: a failure does not stop it."""
    try:
        return [Path(p).name for p in make()]
    except Exception as exc:  # the report must still be written
        notes.append(f"{what} not made: {type(exc).__name__}: {exc}")
        return []


def _figure(make, path, notes):
    """[the name of the figure make() draws at path], or [] with a note in the report"""
    return _figures(lambda: (make(), [path])[1], f"figure {Path(path).name}", notes)


def mode2_figures(ok, figdir, notes):
    """Fig. 12 per dx: K_II(t) of the three kernels, from the extrapolation and from J."""
    figs = []
    win = mode2.window()
    tt = np.linspace(0.0, mode2.T_END, 600)
    refs = [("semi-infinite crack loaded by 2 tau", tt * 1e6,
             mode2.normalise(mode2.reference()(tt)), "--", "black")]
    # the extrapolation's figure and the J-integral's: (file, K_II column, label, title)
    kinds = (("kernels", "k_ii", lambda r: f"(L2 {r['l2']:.1f} %)",
              "Fig. 12: Mode-II K_II(t), dx = {} mm, m = 5, three kernels"),
             ("jintegral", "k_ii_j", lambda r: f"from J (peak {r['jintegral']['peak']:.1f} %)",
              "Mode-II K_II(t) from the J-integral, dx = {} mm, three kernels"))
    window = (win.t_start * 1e6, win.t_end_ignoring_corners * 1e6)
    for dx in sorted({dx for _, dx in ok}, reverse=True):
        for name, col, label, title in kinds:
            series = [(f"{k} {label(r)}", r["t"] * 1e6, mode2.normalise(r[col]), COLORS[k])
                      for (k, d), r in ok.items() if d == dx and col in r]
            if series:
                path = figdir / f"fig12_{name}_dx{dx * 1e3:g}mm.png"
                figs += _figure(lambda: plot_k(path, series, refs, window,
                                               title.format(f"{dx * 1e3:g}"), "t (us)",
                                               r"$K_{II}/(\tau\sqrt{\pi a})$"), path, notes)
    return figs


# title and setup of each section this module builds
SETUP = {
    "dispersion": ("Wave dispersion of a 1D bar (sec. 4.1, Figs. 4-6)",
        "Periodic ring of 1000 atoms, m = 5, delta = 1 mm, dx = 0.2 mm, v = sqrt(E/rho) = 5000 "
        "m/s, dt = dx/v; measured omega(k) is the ridge of the 2-D power spectrum of u(x, t) "
        "(examples/dispersion-1d/README.md). The paper gives these curves only as figures: its "
        "column is eq. 31 as printed (w_j = W(j/m), no time-step shift). Deviations are max "
        "|omega_measured/omega - 1| and the smallest group velocity is taken over the energetic k "
        "with k dx 0.1-2.5. The curves of Figs. 4-6 and the measured points are also written as "
        "CSV in csv/."),
    "mode1": ("Stationary Mode-I semi-infinite crack (sec. 4.2.1, Tables 2-3, Figs. 9-10)",
        "Plate 10 m x 4 m, edge crack a = 5 m, ramp load on the top edge, m = 5, plane stress, "
        "K_I by compute bbpd/dsif and compute bbpd/jintegral every step, errors (%) of eqs. 44-45 "
        "over t <= 3 t_c against Freund's eq. 42 in two conventions: the paper's (nu = 0.3, C_d = "
        "5944 m/s) and the BBPD model's own constants (plane stress nu = 1/3, C_d = 5434 m/s); "
        "see examples/mode1-semi-infinite/README.md."),
    "mode2": ("Mode-II central crack under shear (sec. 4.2.2, Fig. 12)",
        "Plate 104 x 40 mm, central crack 2a = 24 mm, step shear tau on both long edges, plane "
        "strain (nu = 1/4), m = 5. K_II by compute bbpd/dsif and by compute bbpd/jintegral (J "
        "columns); errors (%) of eqs. 44-45 against the early-time analytic reference "
        "(semi-infinite crack loaded by 2 tau, checked by classical FE) over its validity window "
        "5.77-9.77 us; see examples/mode2-central-crack/README.md. The paper shows Fig. 12 only "
        "(no numbers), against a J-integral curve not available to us."),
    "kw": ("Kalthoff-Winkler impact (sec. 4.2.3, Figs. 14-15)",
        "Steel plate 100 x 200 mm with two 50 mm notches, impact at 32 m/s between them, plane "
        "strain, m = 5, 70 us. First bond: first broken bond within delta of a notch tip; damage "
        "band: first atom ahead of the tip with damage >= 0.35 (a crack band on the damage map); "
        "angle and speed over crack lengths 10-50 mm; see examples/kalthoff-winkler/README.md."),
}


def _section(name, table, text, figs):
    title, setup = SETUP[name]
    return {"title": title, "setup": setup, "table": table, "text": " ".join(text), "figures": figs}


def _tables(parts, specs, results):
    """[(title, table)] one after the other, then the table of the failed runs among specs"""
    texts = [(f"{title}:\n\n" if title else "") + table for title, table in parts]
    return "\n\n".join(texts + [tables.failures(specs, results)]).strip()


def dispersion_section(specs, results, figdir, notes):
    runs = tables.dispersion_runs(specs, results)
    table, paper, cv = tables.dispersion_csv(runs, figdir)
    header, rows, numbers = dispersion.table(runs, table)
    text = dispersion_text(numbers, table)
    figs = _figures(lambda: dispersion.plot_figures(runs, paper, cv, figdir),
                            "dispersion figures", notes)    # Figs. 4-6
    return _section("dispersion", _tables([("", md_table(header, rows))], specs, results), text,
                    figs)


def mode1_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results, ("t", "k_paper", "k_consistent", "k_ii"))
    rows3_ok = {k: ok[k, MODE1_TABLE3_DX] for k in KERNELS if (k, MODE1_TABLE3_DX) in ok}
    text = mode1_text(ok, rows3_ok)
    figs = _figures(lambda: mode1.figures(
        {dx: r for (k, dx), r in ok.items() if k == "gaussian"}, rows3_ok, figdir), "Figs. 9-10", notes)
    rows = [mode1.row(r) for r in ok.values()]
    table = _tables([("Table 2, Gaussian kernel", mode1.table2(rows)),
                     (f"Table 3, dx = {MODE1_TABLE3_DX:g} m", mode1.table3(rows)),
                     ("K_I from the J-integral", mode1.jtable(rows))], specs, results)
    return _section("mode1", table, text, figs)


def mode2_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results, ("t", "k_ii", "k_i", "k_ii_left", "k_ii_j"))
    rows = [mode2.row(r) for r in ok.values()]
    table = _tables([("", mode2.table(rows)), ("K_II from the J-integral", mode2.jtable(rows))],
                    specs, results)
    return _section("mode2", table, mode2_text(ok), mode2_figures(ok, figdir, notes))


def kw_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results)
    text = kw_text(ok)
    figs = _figures(lambda: kalthoff_winkler.figures(list(ok.values()), figdir),
                            "Kalthoff-Winkler figures", notes)
    for (k, dx), r in sorted(ok.items()):
        if f"growth_{k}_dx{dx * 1e3:g}mm.png" in figs:
            text.append(f"The row of pictures is the damage of the {k} run at {dx * 1e3:g} mm "
                        f"at {len(r['snapshots'])} times, drawn during the run by LAMMPS's "
                        "dump image (the input's variable images; the other runs leave it "
                        "off).")
    table = _tables([("", kalthoff_winkler.table([kalthoff_winkler.row(r) for r in ok.values()]))],
                    specs, results)
    return _section("kw", table, text, figs)


# the sections of REPORT.md in order: (Spec.bench of their runs, builder)
BUILDERS = (("dispersion", dispersion_section), ("mode1", mode1_section),
            ("mode2", mode2_section), ("mode1prop", mode1_propagation.section),
            ("strip", strip.section), ("kink", kink.section), ("branching", branching.section),
            ("kw", kw_section), ("kwstudy", kalthoff_winkler_study.section),
            ("kwprojectile", kalthoff_winkler_projectile.section),
            ("kwgrid", kalthoff_winkler_grid.section), ("kwdeck", kalthoff_winkler_deck.section),
            ("kw3d", kalthoff_winkler_3d.section), ("kinkconv", kink_convergence.section),
            ("quasistatic", quasi_static.section))
