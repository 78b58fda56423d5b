# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's lines under each table: fixed templates with the runs' numbers filled in, and
the verdicts they rest on as data (mode2_j)."""
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


def ranking(values):
    """Names ordered by value, None (failed) left out: 'a < b < c'."""
    ok = [(v, k) for k, v in values.items() if v is not None]
    return " < ".join(k for _, k in sorted(ok))


def _names(kernels):
    return ", ".join(kernels) or "none"


def dispersion_text(numbers, table):
    """numbers: tables.dispersion_table's; table: dispersion.analytic_table's."""
    phase, min_vg, dev = numbers["phase"], numbers["min_vg"], numbers["dev"]
    if not dev:
        return []
    worst = max(dev, key=dev.get)
    at = {k: p[-1] for k, p in phase.items()}
    k0, k1 = disp.KDX_RANGE
    return [f"Measured ridge against the relation LAMMPS integrates (eq. 31 with C_v and the "
            f"velocity-Verlet shift), k dx {k0:g}-{k1:g}: largest deviation {dev[worst]:.1e} ({worst}).",
            f"Phase velocity c/v at k dx = {DISP_KDX[-1]:g}: {ranking(at)}; least dispersive "
            f"{max(at, key=at.get)} (paper: gaussian), most {min(at, key=at.get)} (paper: constant).",
            "Negative group velocity: eq. 31 as printed "
            + _names([k for k in KERNELS if table[k]["discrete"]["group_negative"]])
            + " (the paper's Fig. 6); with C_v "
            + _names([k for k in KERNELS if table[k]["discrete_cv"]["group_negative"]])
            + "; measured " + _names([k for k, g in min_vg.items() if g is not None and g < NEGATIVE_VG])
            + f" (smallest v_g/v over k dx {k0:g}-{k1:g}: "
            + ", ".join(f"{k} {g:.3f}" for k, g in min_vg.items() if g is not None) + ")."]


def mode1_text(ok, rows2_ok, rows3_ok):
    """ok: every finished run by (kernel, dx); rows2_ok: Table 2's by dx; rows3_ok: Table 3's
    by kernel."""
    text = []
    if rows3_ok:
        def rank(conv, col):
            return ranking({k: r[conv][col] for k, r in rows3_ok.items()})
        text.append(f"Table 3, L2 errors rank: consistent {rank('consistent', 'l2')}, paper's "
                    f"convention {rank('paper', 'l2')}, the paper "
                    f"{ranking({k: mode1.PAPER_TABLE3[k][1] for k in rows3_ok})}; peak errors "
                    f"(consistent) {rank('consistent', 'peak')}. Consistent L2 minus the paper's: "
                    + ", ".join(f"{k} {r['consistent']['l2'] - mode1.PAPER_TABLE3[k][1]:+.2f}"
                                for k, r in rows3_ok.items()) + " points.")
    if len(rows2_ok) > 1:
        dxs = sorted(rows2_ok, reverse=True)
        l2 = [rows2_ok[dx]["consistent"]["l2"] for dx in dxs]
        text.append(f"Table 2 (Gaussian), dx = {' -> '.join(f'{dx:g}' for dx in dxs)} m: "
                    "consistent L2 " + " -> ".join(f"{e:.2f}" for e in l2) + " % (falls at every "
                    f"step: {'yes' if all(b < a for a, b in zip(l2, l2[1:])) else 'no'}), run "
                    "times " + " -> ".join(f(run_time(rows2_ok[dx]), ".1f") for dx in dxs)
                    + " s; the paper " + " -> ".join(f"{mode1.PAPER_TABLE2[dx][1]:.2f}" for dx in dxs
                                                    if dx in mode1.PAPER_TABLE2) + " %.")
    withj = {key: r["jintegral"]["consistent"] for key, r in ok.items() if "jintegral" in r}
    if withj:
        jp = [v["peak"] for v in withj.values()]
        dp = [ok[key]["consistent"]["peak"] for key in withj]
        text.append(f"K_I from the J-integral (annulus 0.5-1.5 m), peak errors {min(jp):.2f}-"
                    f"{max(jp):.2f} %; displacement extrapolation {min(dp):.2f}-{max(dp):.2f} %.")
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
    ratio = {key: r["k_end"] / r["k_end_exact"] for key, r in ok.items()}
    text = [f"K_II/K_II,ref at the end of the window (extrapolation, tip on the first intact "
            f"column, r1 = dx, r2 = 2 dx): {min(ratio.values()):.3f}-{max(ratio.values()):.3f}."]
    dxs = sorted({dx for _, dx in ok}, reverse=True)
    for dx in dxs:
        l2 = {k: r["l2"] for (k, d), r in ok.items() if d == dx}
        peak = {k: r["peak"] for (k, d), r in ok.items() if d == dx}
        text.append(f"dx = {dx * 1e3:g} mm: L2 errors rank {ranking(l2)} ({min(l2.values()):.1f}-"
                    f"{max(l2.values()):.1f} %), peak errors {ranking(peak)} "
                    f"({min(peak.values()):.1f}-{max(peak.values()):.1f} %).")
    common = [k for k in KERNELS if all((k, d) in ok for d in dxs)]
    if len(dxs) > 1 and common:
        text.append(f"Ratio at the window end, dx = {dxs[0] * 1e3:g} -> {dxs[-1] * 1e3:g} mm: "
                    + ", ".join(f"{k} {ratio[(k, dxs[0])]:.3f} -> {ratio[(k, dxs[-1])]:.3f}"
                                for k in common) + ".")
    j = mode2_j(ok)
    if j:
        text.append(f"K_II from the J-integral (annulus 5-12.5 mm) at the window end: "
                    f"{min(j['j'].values()):.3f}-{max(j['j'].values()):.3f} of the reference"
                    + (f"; J carries at most {100 * max(j['share'].values()):.0f} % of the "
                       "extrapolation's excess" if j["share"] else "")
                    + f"; the excess lives in: {j['where']}. Peak errors of J rank "
                    + "; ".join(f"{ranking(p)} at dx = {dx * 1e3:g} mm" for dx, p in j["peaks"].items())
                    + ".")
    text.append("The paper shows Fig. 12 only (no numbers), against a J-integral curve not "
                "available to us.")
    return text


def kw_text(ok):
    """ok: (kernel, dx) -> finished result. What the table does not show: the order in which
    the damage band leaves the tips against the paper's initiation order, per dx, and the
    mirror symmetry of the two cracks."""
    text = []
    for dx in sorted({dx for _, dx in ok}, reverse=True):
        same = {k: r for (k, d), r in ok.items() if d == dx}
        if len(same) > 1:
            text.append(f"dx = {dx * 1e3:g} mm: the damage band leaves the tips in the order "
                        f"{ranking({k: r['t_band_us'] for k, r in same.items()})}; the paper's "
                        f"initiation: {ranking({k: kw.PAPER_INITIATION_US[k] for k in same})}.")
    if ok:
        text.append("Mirror symmetry of the two cracks: tip mismatch <= "
                    f"{max(r['symmetry_tip_mm'] for r in ok.values()):.1g} mm.")
    return text