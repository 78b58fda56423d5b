# SPDX-License-Identifier: GPL-2.0-or-later
"""One section of REPORT.md per benchmark: its title, the setup it ran, the table, the
paragraph and the figures, each from tables, prose and figures."""
from bbpd.benchmarks import (branching, dispersion, kalthoff_winkler, kalthoff_winkler_3d,
                             kalthoff_winkler_deck, kalthoff_winkler_grid,
                             kalthoff_winkler_projectile, kalthoff_winkler_study, kink,
                             kink_convergence, mode1, mode1_propagation, mode2, quasi_static,
                             strip)
from bbpd.kernels import KERNELS

from . import figures, prose, tables
from .runs import MODE1_TABLE3_DX
from .tables import md_table


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
    text = prose.dispersion_text(numbers, table)
    figs = figures.dispersion_figures(runs, paper, cv, figdir, notes)
    return _section("dispersion", _tables([("", md_table(header, rows))], specs, results), text,
                    figs)


def mode1_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results, ("t", "k_paper", "k_consistent", "k_ii"))
    rows3_ok = {k: ok[k, MODE1_TABLE3_DX] for k in KERNELS if (k, MODE1_TABLE3_DX) in ok}
    text = prose.mode1_text(ok, rows3_ok)
    figs = figures.mode1_figures({dx: r for (k, dx), r in ok.items() if k == "gaussian"},
                                 rows3_ok, figdir, notes)
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
    return _section("mode2", table, prose.mode2_text(ok), figures.mode2_figures(ok, figdir, notes))


def kw_section(specs, results, figdir, notes):
    ok = tables.finished(specs, results)
    text = prose.kw_text(ok)
    figs = figures.kw_figures(ok, figdir, notes)
    for (k, dx), r in sorted(ok.items()):
        if figures.growth_name(k, dx) in figs:
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
