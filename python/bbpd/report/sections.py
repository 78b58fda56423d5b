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

# the lines under the tables: hand-written, the runs' numbers and verdicts filled in (what a
# table beside them already shows is not repeated)
DISPERSION = ("Negative group velocity (min v_g/v in the table; the paper's Fig. 6): measured "
              "for {measured}; eq. 31 as printed gives it for {printed}, with C_v for {cv}.")
MODE2_J = ("Where the excess of K_II at the window end lives (the two ratios in the J-integral "
           "table): the {where}.")
KW_PICTURES = ("The row of pictures: the damage of the {k} run at {dx:g} mm at {n} times, drawn "
               "during the run by LAMMPS's dump image (the input's variable images).")


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


# --------------------------------------------------------------------------- figures

def figure_names(make, what, notes):
    """The names of the figures make() draws (it returns their paths), or [] with a note in the
    report: a failure does not stop it."""
    try:
        return [Path(p).name for p in make()]
    except Exception as exc:  # the report must still be written
        notes.append(f"{what} not made: {type(exc).__name__}: {exc}")
        return []


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
                figs += figure_names(lambda: [plot_k(path, series, refs, window,
                                                     title.format(f"{dx * 1e3:g}"), "t (us)",
                                                     r"$K_{II}/(\tau\sqrt{\pi a})$")],
                                     f"figure {path.name}", notes)
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

    def names(negative):
        return ", ".join(k for k in KERNELS if negative(k)) or "none"
    text = [DISPERSION.format(
        measured=names(lambda k: (numbers["min_vg"].get(k) or 0.0) < NEGATIVE_VG),
        printed=names(lambda k: table[k]["discrete"]["group_negative"]),
        cv=names(lambda k: table[k]["discrete_cv"]["group_negative"]))] if numbers["dev"] else []
    figs = figure_names(lambda: dispersion.plot_figures(runs, paper, cv, figdir),
                        "dispersion figures", notes)    # Figs. 4-6
    return _section("dispersion", _tables([("", md_table(header, rows))], specs, results), text,
                    figs)


def mode1_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results, ("t", "k_paper", "k_consistent", "k_ii"))
    rows3_ok = {k: ok[k, MODE1_TABLE3_DX] for k in KERNELS if (k, MODE1_TABLE3_DX) in ok}
    figs = figure_names(lambda: mode1.figures(
        {dx: r for (k, dx), r in ok.items() if k == "gaussian"}, rows3_ok, figdir), "Figs. 9-10", notes)
    rows = [mode1.row(r) for r in ok.values()]
    table = _tables([("Table 2, Gaussian kernel", mode1.table2(rows)),
                     (f"Table 3, dx = {MODE1_TABLE3_DX:g} m", mode1.table3(rows)),
                     ("K_I from the J-integral", mode1.jtable(rows))], specs, results)
    return _section("mode1", table, [], figs)


def mode2_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results, ("t", "k_ii", "k_i", "k_ii_left", "k_ii_j"))
    rows = [mode2.row(r) for r in ok.values()]
    table = _tables([("", mode2.table(rows)), ("K_II from the J-integral", mode2.jtable(rows))],
                    specs, results)
    j = mode2_j(ok)
    return _section("mode2", table, [MODE2_J.format(where=j["where"])] if j else [],
                    mode2_figures(ok, figdir, notes))


def kw_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results)
    figs = figure_names(lambda: kalthoff_winkler.figures(list(ok.values()), figdir),
                        "Kalthoff-Winkler figures", notes)
    text = [KW_PICTURES.format(k=k, dx=dx * 1e3, n=len(r["snapshots"]))
            for (k, dx), r in sorted(ok.items()) if f"growth_{k}_dx{dx * 1e3:g}mm.png" in figs]
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
