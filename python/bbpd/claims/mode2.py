# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/mode2-central-crack/README.md and the Mode-II sentence of
doc/compute_bbpd_jintegral.rst, from examples/mode2-central-crack/results/mode2.csv."""
from bbpd.kernels import KERNELS

from . import mode1
from .text import by_kernel, f, joined, md_table, mm, name, ranking, span

NAME = "mode2"
WINDOW_END_US = 9.77    # t_start + 2a/c_d (README, "Reference")


def _rows(data):
    return sorted(data.rows(NAME), key=lambda r: (-r["dx_m"], KERNELS.index(r["kernel"])))


def _grids(data):
    return sorted({r["dx_m"] for r in data.rows(NAME)}, reverse=True)


def _at(data, dx):
    return {r["kernel"]: r for r in data.rows(NAME) if r["dx_m"] == dx}


def note(data):
    return (f"From {data.source(NAME)}; run time: one single-rank run, two at a time on "
            f"{data.cpu(NAME)} (cores shared with other jobs).")


def table(data):
    header = ["kernel", "dx (mm)", "atoms", "peak (%)", "L2 (%)",
              f"K_II/(tau sqrt(pi a)) at {WINDOW_END_US} us, ours / reference",
              "run time (s)"]
    rows = [[r["kernel"], mm(r["dx_m"]), f"{r['atoms']:,.0f}", f(r["peak"]), f(r["l2"]),
             f"{r['k_end']:.3f} / {r['k_end_exact']:.3f}", f(r["run_time_s"], ".1f")]
            for r in _rows(data)]
    return md_table(header, rows) + "\n\n" + note(data)


def jtable(data):
    header = ["kernel", "dx (mm)", "extrapolation: peak / L2 (%)",
              f"extrapolation: ratio at {WINDOW_END_US} us", "J: peak / L2 (%)",
              f"J: ratio at {WINDOW_END_US} us", "run time (s)"]
    rows = [[r["kernel"], mm(r["dx_m"]), f"{r['peak']:.2f} / {r['l2']:.2f}",
             f"{r['ratio_end']:.3f}", f"{r['j_peak']:.2f} / {r['j_l2']:.2f}",
             f"{r['j_ratio_end']:.3f}", f(r["run_time_s"], ".1f")] for r in _rows(data)]
    return md_table(header, rows) + "\n\n" + note(data)


def excess(data):
    """'11.9–28.9 %' of the extrapolation at the window end, over every run."""
    return span([100 * (r["ratio_end"] - 1) for r in data.rows(NAME)], ".0f", " %")


def findings(data):
    grids = _grids(data)
    per_grid = "; ".join(
        f"{span([100 * (r['ratio_end'] - 1) for r in _at(data, dx).values()], '.1f', ' %')} "
        f"at {mm(dx)} mm" for dx in grids)
    l2_rank = "; ".join(f"{ranking({k: r['l2'] for k, r in _at(data, dx).items()})} at "
                        f"{mm(dx)} mm" for dx in grids)
    peak_rank = "; ".join(f"{ranking({k: r['peak'] for k, r in _at(data, dx).items()})} at "
                          f"{mm(dx)} mm" for dx in grids)
    best_l2 = {min(_at(data, dx).items(), key=lambda kr: kr[1]["l2"])[0] for dx in grids}
    best_peak = {min(_at(data, dx).items(), key=lambda kr: kr[1]["peak"])[0] for dx in grids}
    verdict = ("no kernel is best at every grid or by both errors"
               if len(best_l2 | best_peak) > 1 else f"the {name(best_l2.pop())} kernel is best")
    return (f"- BBPD with the paper's extraction (tip on the first intact column, r1 = dx, "
            f"r2 = 2 dx, the convention calibrated on Mode I) **overestimates K_II for all "
            f"three kernels**: at {WINDOW_END_US} us by {per_grid}, and the excess does not "
            f"shrink with dx. By L2 error the kernels rank {l2_rank}; by peak error "
            f"{peak_rank}: {verdict}, and we do not see the paper's \"good agreement, "
            f"particularly for the Gaussian kernel\" with this extraction.")


def symmetry(data):
    rows = data.rows(NAME)
    return (f"- Left and right tips agree to {max(r['left_right'] for r in rows):.0e} "
            f"(relative) and K_I/K_II stays below {max(r['ki_over_kii'] for r in rows):.0e} "
            f"(antisymmetry).")


def conclusion(data):
    grids = _grids(data)
    fine = _at(data, grids[-1])
    conv = ", ".join(f"{name(k)} " + " -> ".join(f"{_at(data, dx)[k]['j_ratio_end']:.3f}"
                                          for dx in grids)
                     for k in KERNELS if all(k in _at(data, dx) for dx in grids))
    l2 = " -> ".join(span([r["j_l2"] for r in _at(data, dx).values()], ".1f", " %")
                     for dx in grids)
    return (f"**Conclusion, from these numbers.** At the end of the window the displacement "
            f"extrapolation is {excess(data)} above the reference for every kernel and grid, "
            f"and its excess does not shrink with dx "
            f"({span([r['ratio_end'] for r in fine.values()], '.2f')} at {mm(grids[-1])} mm). "
            f"K_II from the J-integral of the same runs has peak errors of "
            f"{span([r['j_peak'] for r in data.rows(NAME)], '.1f', ' %')} and converges to the "
            f"reference with dx (ratio at the window end: {conv}; L2 {l2}, the L2 being the "
            f"first microsecond after the waves arrive, where K is small).")


def paper_verdict(data):
    grids = _grids(data)
    closest, farthest, l2_best = {}, {}, {}
    for dx in grids:
        at = _at(data, dx)
        closest.setdefault(min(at, key=lambda k: at[k]["j_peak"]), []).append(mm(dx))
        farthest.setdefault(max(at, key=lambda k: at[k]["j_peak"]), []).append(mm(dx))
        l2_best.setdefault(min(at, key=lambda k: at[k]["j_l2"]), []).append(mm(dx))

    def where(d):
        return "; ".join(f"the {name(k)} kernel at {joined(g)} mm" for k, g in d.items())
    per_grid = "; ".join(
        f"{ranking({k: r['j_peak'] for k, r in _at(data, dx).items()})} at {mm(dx)} mm "
        f"({span([r['j_peak'] for r in _at(data, dx).values()], '.2f', ' %')})" for dx in grids)
    return (f"**The paper's \"good agreement, particularly for the Gaussian\" against its "
            f"J-integral curve,** read with our J-integral: all three kernels agree with the "
            f"reference within {max(r['j_peak'] for r in _at(data, grids[0]).values()):.1f} % "
            f"(peak) at {mm(grids[0])} mm and within "
            f"{max(r['j_peak'] for r in _at(data, grids[-1]).values()):.1f} % at "
            f"{mm(grids[-1])} mm. By peak error the kernels rank {per_grid}: the closest is "
            f"{where(closest)}, the farthest {where(farthest)}. By L2 error the closest is "
            f"{where(l2_best)}. With the J-integral as the extraction, the paper's statement is "
            f"reproduced by the peak error at {joined(closest.get('gaussian', ['no']))} mm; "
            f"with the displacement extrapolation it is not.")


def jintegral_doc(data):
    """The Mode-II half of doc/compute_bbpd_jintegral.rst's benchmark sentence."""
    return (f"On the benchmarks (numbers in examples/mode1-semi-infinite/README.md and "
            f"examples/mode2-central-crack/README.md): Mode-I :math:`K_I(t)` within "
            f"{mode1.gaussian_j_peak(data, 0.05):.2f} % of Freund's solution (peak error) at "
            f":math:`\\Delta x` = 0.05 m with the Gaussian kernel, and Mode-II "
            f":math:`K_{{II}}(t)` within "
            f"{span([r['j_peak'] for r in data.rows(NAME)], '.1f', ' %')} of the reference "
            f"(peak error, three kernels, :math:`\\Delta x` = "
            f"{joined([mm(dx) for dx in _grids(data)])} mm) where the displacement "
            f"extrapolation is {excess(data)} high at the end of the comparison window.")
