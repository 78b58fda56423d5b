# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's lines under each table: sentences written by hand as templates, the runs'
numbers filled in; the Mode-II verdict as data (mode2_j)."""
from bbpd.benchmarks import dispersion as disp
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import mode1
from bbpd.kernels import KERNELS

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
        k0=disp.KDX_RANGE[0], k1=disp.KDX_RANGE[1], dev=dev[worst], worst=worst,
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
                paper=ranking({k: kw.PAPER_INITIATION_US[k] for k in same})))
    if ok:
        text.append(KW_SYMMETRY.format(tip=max(r["symmetry_tip_mm"] for r in ok.values())))
    return text
