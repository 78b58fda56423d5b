# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's lines under each table: sentences written by hand as templates, the runs'
numbers filled in; the Mode-II verdict as data (mode2_j)."""
from bbpd.benchmarks import dispersion as disp
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import mode1
from bbpd.kernels import KERNELS

from .tables import DISP_KDX, f, run_time

NEGATIVE_VG = -1.0e-3      # measured v_g/v below this counts as negative (the ridge's noise
                           # in the gradient is ~1e-5 of v)
# largest share of the extrapolation's excess that K_II from J may carry for the verdict
# "the excess is in the extrapolation" (and 1 minus it for "in the field")
MODE2_FIELD_SHARE = 0.25

DISPERSION = ("Measured ridge against the relation LAMMPS integrates (eq. 31 with C_v and the "
              "velocity-Verlet shift), k dx {k0:g}-{k1:g}: largest deviation {dev:.1e} ({worst}). "
              "Phase velocity c/v at k dx = {kdx:g}: {phase} (the paper: gaussian least, constant "
              "most dispersive). Negative group velocity: eq. 31 as printed {printed} (the "
              "paper's Fig. 6); with C_v {cv}; measured {measured} (smallest v_g/v: {min_vg}).")
MODE1_TABLE3 = ("Table 3, L2 errors rank: consistent {consistent}, paper's convention {paper}, "
                "the paper {published}; consistent L2 minus the paper's: {diff} points.")
MODE1_TABLE2 = ("Table 2 (Gaussian), dx = {dxs} m: consistent L2 {l2} %, run times {times} s; "
                "the paper {published} %.")
MODE1_J = ("K_I from the J-integral (annulus 0.5-1.5 m), peak errors {j[0]:.2f}-{j[1]:.2f} %; "
           "displacement extrapolation {d[0]:.2f}-{d[1]:.2f} %.")
MODE2 = ("K_II/K_II,ref at the end of the window (extrapolation, tip on the first intact column, "
         "r1 = dx, r2 = 2 dx): {ratio[0]:.3f}-{ratio[1]:.3f}. At dx = {dx:g} mm the L2 errors "
         "rank {l2} and the peak errors {peak}.")
MODE2_J = ("K_II from the J-integral (annulus 5-12.5 mm) at the window end: {j[0]:.3f}-{j[1]:.3f} "
           "of the reference; the excess lives in the {where} (share J carries: {share}).")
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
    """numbers: tables.dispersion_table's; table: dispersion.analytic_table's."""
    phase, min_vg, dev = numbers["phase"], numbers["min_vg"], numbers["dev"]
    if not dev:
        return []
    worst = max(dev, key=dev.get)
    negative = {c: _names([k for k in KERNELS if table[k][c]["group_negative"]])
                for c in ("discrete", "discrete_cv")}
    return [DISPERSION.format(
        k0=disp.KDX_RANGE[0], k1=disp.KDX_RANGE[1], dev=dev[worst], worst=worst, kdx=DISP_KDX[-1],
        phase=ranking({k: p[-1] for k, p in phase.items()}), printed=negative["discrete"],
        cv=negative["discrete_cv"],
        measured=_names([k for k, g in min_vg.items() if g is not None and g < NEGATIVE_VG]),
        min_vg=", ".join(f"{k} {g:.3f}" for k, g in min_vg.items() if g is not None))]


def mode1_text(ok, rows2_ok, rows3_ok):
    """ok: every finished run by (kernel, dx); rows2_ok: Table 2's by dx; rows3_ok: Table 3's
    by kernel."""
    text = []
    if rows3_ok:
        text.append(MODE1_TABLE3.format(
            consistent=ranking({k: r["consistent"]["l2"] for k, r in rows3_ok.items()}),
            paper=ranking({k: r["paper"]["l2"] for k, r in rows3_ok.items()}),
            published=ranking({k: mode1.PAPER_TABLE3[k][1] for k in rows3_ok}),
            diff=", ".join(f"{k} {r['consistent']['l2'] - mode1.PAPER_TABLE3[k][1]:+.2f}"
                           for k, r in rows3_ok.items())))
    if len(rows2_ok) > 1:
        dxs = sorted(rows2_ok, reverse=True)
        text.append(MODE1_TABLE2.format(
            dxs=" -> ".join(f"{dx:g}" for dx in dxs),
            l2=" -> ".join(f"{rows2_ok[dx]['consistent']['l2']:.2f}" for dx in dxs),
            times=" -> ".join(f(run_time(rows2_ok[dx]), ".1f") for dx in dxs),
            published=" -> ".join(f"{mode1.PAPER_TABLE2[dx][1]:.2f}" for dx in dxs
                                  if dx in mode1.PAPER_TABLE2)))
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
    dx = min(d for _, d in ok)
    finest = {k: r for (k, d), r in ok.items() if d == dx}
    text = [MODE2.format(ratio=_span([r["k_end"] / r["k_end_exact"] for r in ok.values()]),
                         dx=dx * 1e3, l2=ranking({k: r["l2"] for k, r in finest.items()}),
                         peak=ranking({k: r["peak"] for k, r in finest.items()}))]
    j = mode2_j(ok)
    if j:
        text.append(MODE2_J.format(j=_span(j["j"].values()), where=j["where"],
                                   share=f(max(j["share"].values(), default=None), ".2f")))
    return text


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
                paper=ranking({k: kw.PAPER_INITIATION_US[k] for k in same})))
    if ok:
        text.append(KW_SYMMETRY.format(tip=max(r["symmetry_tip_mm"] for r in ok.values())))
    return text
