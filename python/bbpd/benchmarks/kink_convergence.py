# SPDX-License-Identifier: GPL-2.0-or-later
"""The kink test's convergence: the kink angle against m and R/delta, pure Mode II by default.

A pure-K problem has no length scale, so the angle at which the crack of
examples/kink-mixed-mode/in.kink leaves the tip is a property of the model at a given m =
delta/dx and kernel; the disk's size R/delta only has to be large enough for the Williams
field to hold over the tip's neighbourhood. This sweep runs the Gaussian kernel under pure
Mode II (psi = 90 deg, crack along the rows) at delta = 5 mm for

  m = 5, 10, 15, 20 at R/delta = 10 (R = 50 mm, the kink test's disk), and
  m = 5, 10 at R/delta = 20 (R = 100 mm),

measured as bbpd.benchmarks.kink measures (angle at 2 and 4 horizons from the tip); --psi and
--alpha run the same cases at another mode mix and crack direction (the kink test's
MIXES_DEG and ALPHAS_DEG), each (kernel, psi, alpha) a sequence of its own. The time
step is DT_PER_M * m * dx / c_d, the kink test's rule (0.8 at m = 5, 1.6 at m = 10): the
stable step of a bond family scales with the horizon, not with dx.

Command line (from the repository root):
  tools/python -m bbpd.benchmarks.kink_convergence --work /tmp/kink-conv --nprocs 2 \
      --csv examples/kink-mixed-mode/results/kink_convergence.csv
  # another kernel's cases, added to the same CSV:
  tools/python -m bbpd.benchmarks.kink_convergence --work /tmp/kink-conv --kernel constant \
      --cases 10:10 15:10 --append --csv examples/kink-mixed-mode/results/kink_convergence.csv
  # another mix and crack direction:
  tools/python -m bbpd.benchmarks.kink_convergence --work /tmp/kink-conv --psi 45 --alpha 22.5 \
      --cases 10:20 --nprocs 2 --append --csv examples/kink-mixed-mode/results/kink_convergence.csv
"""

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

from bbpd import csvfile
from bbpd import jobs as jobmod
from bbpd.benchmarks import kink as kinkbench
from bbpd.benchmarks.mode1_propagation import machine
from bbpd.jobs import Job, Spec
from bbpd.kernels import KERNELS
from bbpd.runner import run_lammps

CSV = kinkbench.FOLDER / "results" / "kink_convergence.csv"
KERNEL, PSI, ALPHA = "gaussian", 90.0, 0.0
DELTA = 5.0e-3
DT_PER_M = 0.16                     # dtfactor / m of the kink test (kink.DTFACTOR)
# (m, R/delta), cheapest first: a sweep stopped early keeps the cases that finished
CASES = ((5, 10), (10, 10), (5, 20), (15, 10), (10, 20), (20, 10))
SETTLED_DEG = 1.0                   # the last refinement in m moves the angle by less
# The angle's error bar is the grid's resolution: the path is the centroid of a band of two to
# three crack atoms (bbpd.crack_path), and one more atom row on one side of the band moves the
# centroid across the path by half a spacing. At d = n horizons = n m spacings from the tip that
# turns the direction by atan(LATERAL_QUANTUM_DX / (n m)).
LATERAL_QUANTUM_DX = 0.5
HORIZONS = {f"{n:g}d": n for n in kinkbench.DISTANCES}    # where the angles are measured
COLUMNS = ("kernel", "psi", "alpha", "m", "R_over_delta", "dx_mm", "atoms", "steps",
           "K_init_over_Kc", "extension_over_delta", "angle_2d", "angle_4d", "hoop_stress",
           "hoop_strain", "energy", "loop_s", "nprocs", "cpu")
TIMING = "timing: "    # the CSV's comment line naming the CPU of rows without a cpu column


def case_vars(m, r_over_delta, kernel=KERNEL, psi=PSI, alpha=ALPHA):
    dx = DELTA / m
    return {"kernel": kernel, "psi": repr(float(psi)), "alpha": repr(float(alpha)), "dx": repr(dx),
            "m": repr(float(m)), "R": repr(r_over_delta * DELTA),
            "dtfactor": repr(DT_PER_M * m)}


def case_folder(m, r_over_delta, kernel=KERNEL, psi=PSI, alpha=ALPHA):
    """the run's folder name: the pure Mode II Gaussian cases keep their short names"""
    name = f"m{m:g}-R{r_over_delta:g}" if kernel == KERNEL else f"{kernel}-m{m:g}-R{r_over_delta:g}"
    if (float(psi), float(alpha)) != (PSI, ALPHA):
        name += f"-psi{float(psi):g}-alpha{float(alpha):g}"
    return name


def run_case(workdir, m, r_over_delta, nprocs=1, reuse=False, kernel=KERNEL, psi=PSI, alpha=ALPHA):
    wd = Path(workdir) / case_folder(m, r_over_delta, kernel, psi, alpha)
    if not (reuse and (wd / "final.dump").is_file()):
        run_lammps(str(kinkbench.EXAMPLE), wd, nprocs=nprocs,
                   vars=case_vars(m, r_over_delta, kernel, psi, alpha),
                   timeout=4 * 3600)
    r = kinkbench.analyse(wd)
    row = {"kernel": r["kernel"], "psi": r["psi"], "alpha": r["alpha"], "m": float(m),
           "R_over_delta": float(r_over_delta), "dx_mm": r["dx"] * 1e3, "atoms": r["atoms"],
           "steps": r["steps"], "K_init_over_Kc": r["K_init_over_Kc"],
           "extension_over_delta": r["extension_over_delta"], "angle_2d": r["angle_2d"],
           "angle_4d": r["angle_4d"], "hoop_stress": r["hoop_stress"],
           "hoop_strain": r["hoop_strain"], "energy": r["energy"], "loop_s": r["loop_s"],
           "nprocs": r["nprocs"], "cpu": machine()}
    return row


def resolution_deg(m, dist):
    """the error bar (deg) of an angle measured `dist` ('2d', '4d') from the tip at m = delta/dx"""
    return math.degrees(math.atan(LATERAL_QUANTUM_DX / (HORIZONS[dist] * m)))


def _angle(r, dist):
    """'angle +- resolution' for the table"""
    a = r[f"angle_{dist}"]
    return "-" if a is None else f"{_f(a)} ± {resolution_deg(r['m'], dist):.1f}"


def _f(v, spec=".1f"):
    if v is None:
        return "-"
    text = format(v, spec)
    # a straight crack measured as -1e-15 deg is 0.0, not -0.0
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def _signed(v):
    """v to 0.1 with its sign, +0.0 for a zero however it rounds"""
    return "+0.0" if float(format(v, ".1f")) == 0.0 else format(v, "+.1f")


def _capital(text):
    """text with its first letter a capital (a kernel's name opening a sentence)"""
    return text[0].upper() + text[1:]


def mix_of(r):
    """(psi, alpha) of a row (the rows of pure Mode II along the rows may omit them)"""
    return (float(r.get("psi", PSI)), float(r.get("alpha", ALPHA)))


def _order(r):
    psi, alpha = mix_of(r)
    return (r["kernel"] != KERNEL, r["kernel"], -psi, alpha, r["R_over_delta"], r["m"])


def table(rows, command=None):
    head = ("| kernel | psi | alpha | m | R/delta | dx (mm) | atoms | steps | K at 1st break / K_c | "
            "extension (delta) | angle at 2 delta | angle at 4 delta | hoop stress | hoop strain | "
            "max G | loop (s) | ranks |")
    lines = [head, "|" + "---|" * 17]
    for r in sorted(rows, key=_order):
        psi, alpha = mix_of(r)
        lines.append("| " + " | ".join([
            r["kernel"], f"{psi:g}", f"{alpha:g}", f"{r['m']:g}", f"{r['R_over_delta']:g}",
            f"{r['dx_mm']:.3g}", _f(r["atoms"], ".0f"),
            _f(r["steps"], ".0f"), _f(r["K_init_over_Kc"], ".3f"),
            _f(r["extension_over_delta"], ".1f"), _angle(r, "2d"), _angle(r, "4d"),
            _f(r["hoop_stress"]), _f(r["hoop_strain"]), _f(r["energy"]), _f(r["loop_s"], ".0f"),
            _f(r["nprocs"], ".0f")]) + " |")
    out = "\n".join(lines) + "\n\n" + RESOLUTION_NOTE
    if rows and all(r.get("cpu") for r in rows):
        out += "\n\n" + loop_times(rows)
    made = [command] if isinstance(command, str) else list(command or [])
    intro = " ".join(f"{'Made by' if k == 0 else 'Rows added by'} `{c}`." for k, c in enumerate(made))
    return intro + "\n\n" + out if made else out


RESOLUTION_NOTE = ("Angles ± the grid's resolution: half a spacing across the path at 2 or 4 "
                   "horizons from the tip, atan(1 / (2 n m)) for n horizons.")


def loop_times(rows):
    """'Loop times: ...': the CPU that timed each run (appended runs may come from another
    machine)."""
    def case(r):
        psi, alpha = mix_of(r)
        return f"{r['kernel']} psi = {psi:g}, alpha = {alpha:g}, m = {r['m']:g}, R/delta = {r['R_over_delta']:g}"
    return csvfile.loop_times_note(sorted(rows, key=_order), "cpu", case)


def with_cpu(rows, comments):
    """rows with their cpu: a CSV from before the cpu column names its one CPU on its timing
    line ('timing: LAMMPS loop time, CPU, shared machine')"""
    line = next((c[len(TIMING):] for c in comments if c.startswith(TIMING)), "")
    cpu = line.split("loop time, ", 1)[-1].removesuffix(", shared machine") if line else "unknown"
    return [dict(r, cpu=r.get("cpu") or cpu) for r in rows]


AGREE_DEG = 0.05     # criteria closer than the table's last digit name no nearest one (pure Mode I)
NAMES = {"hoop_stress": "max. hoop stress", "hoop_strain": "max. hoop strain",
         "energy": "max. energy release rate"}


def verdict(rows):
    """The sentences on each sequence in m at a fixed R/delta (the kink test's 10 and every
    larger disk with two values of m), and on doubling the disk: which criterion the finest m
    lies nearest, and whether the last refinement settled it; per kernel (the Gaussian's first)
    and per mode mix and crack direction (pure Mode II along the rows first)."""
    groups = sorted({(r["kernel"],) + mix_of(r) for r in rows},
                    key=lambda g: (g[0] != KERNEL, g[0], -g[1], g[2]))
    parts = [_group_verdict([r for r in rows if (r["kernel"],) + mix_of(r) == g], *g) for g in groups]
    return " ".join(parts) if parts else "No verdict: it needs two values of m at R/delta = 10."


def _nearest_phrase(angle, last, near, bar):
    """'; the finest (± bar) lies nearest the X criterion (+d from a: within its error bar)' for
    the finest run `last` measured at `angle`, or, where the three criteria agree (pure Mode I),
    how far it lies from their common angle"""
    off = angle - last[near]
    where = ("within" if abs(off) <= bar else "outside") + " its error bar)"
    if max(last[c] for c in NAMES) - min(last[c] for c in NAMES) <= AGREE_DEG:
        return (f"; the three criteria agree ({_f(last[near])}°) and the finest (± {bar:.1f}°) "
                f"lies {_signed(off)}° from them ({where}")
    return (f"; the finest (± {bar:.1f}°) lies nearest the {NAMES[near]} criterion "
            f"({_signed(off)}° from {_f(last[near])}°: {where}")


def _group_verdict(rows, kernel, psi=PSI, alpha=ALPHA):
    where = kernel if (psi, alpha) == (PSI, ALPHA) else f"{kernel}, psi = {psi:g}°, alpha = {alpha:g}°"
    out = []
    for dist in ("2d", "4d"):
        sizes = sorted({r["R_over_delta"] for r in rows if r["R_over_delta"] >= 10.0})
        for rd in sizes:
            seq = sorted((r for r in rows if r["R_over_delta"] == rd and r[f"angle_{dist}"]
                          is not None), key=lambda r: r["m"])
            if len(seq) < 2:
                continue
            last, prev = seq[-1], seq[-2]
            step = last[f"angle_{dist}"] - prev[f"angle_{dist}"]
            near = min(NAMES, key=lambda c: abs(last[f"angle_{dist}"] - last[c]))
            bar, bar_prev = resolution_deg(last["m"], dist), resolution_deg(prev["m"], dist)
            s = (f"{where}, at {dist[0]} horizons, R/delta = {rd:g}: " + ", ".join(
                f"{_f(r[f'angle_{dist}'])}° at m = {r['m']:g}" for r in seq)
                 + _nearest_phrase(last[f"angle_{dist}"], last, near, bar) + ", and the last "
                 f"refinement (m = {prev['m']:g} to {last['m']:g}) moves it by {_signed(step)}°: ")
            s += ("settled within {:g}°".format(SETTLED_DEG) if abs(step) <= SETTLED_DEG
                  else f"not settled (more than {SETTLED_DEG:g}°")
            if abs(step) > SETTLED_DEG:
                s += (", and more than the two error bars, ± {:.1f} and ± {:.1f}°)" if abs(step) > bar + bar_prev
                      else ", within the two error bars, ± {:.1f} and ± {:.1f}°)").format(bar_prev, bar)
            out.append(s)
        base = {r["m"]: r for r in rows if r["R_over_delta"] == 10.0 and r[f"angle_{dist}"] is not None}
        size = {r["m"]: r for r in rows if r["R_over_delta"] == 20.0 and r[f"angle_{dist}"]
                is not None}
        pairs = [(m, size[m][f"angle_{dist}"] - base[m][f"angle_{dist}"]) for m in sorted(base)
                 if m in size]
        if pairs:
            out.append(f"at {dist[0]} horizons, doubling the disk to R/delta = 20 moves it by " + ", ".join(
                f"{_signed(d)}° at m = {m:g}" for m, d in pairs))
    return (". ".join(_capital(s) for s in out) + "." if out else
            f"{_capital(where)}: no verdict, it needs two values of m at one R/delta.")


FIGURE = kinkbench.FOLDER / "kink_convergence.png"


def figure(rows, path=FIGURE):
    """The angle at 2 and 4 horizons against m with its error bar, one panel per distance and
    mode mix (pure Mode II first), each (kernel, crack direction, R/delta) a line, and the three
    criteria of that mix as horizontal lines."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    mixes = sorted({mix_of(r)[0] for r in rows if mix_of(r)[0] > 0.0}, reverse=True)
    fig, axes = plt.subplots(len(mixes), 2, figsize=(10, 3.6 * len(mixes)), squeeze=False)
    try:
        for ax_row, psi in zip(axes, mixes):
            on = [r for r in rows if mix_of(r)[0] == psi]
            for ax, dist in zip(ax_row, HORIZONS):
                for c, style in zip(NAMES, ("-", "--", ":")):
                    ax.axhline(on[0][c], color="k", ls=style, lw=0.9, label=NAMES[c])
                lines = sorted({(r["kernel"], mix_of(r)[1], r["R_over_delta"]) for r in on},
                               key=lambda k: (k[0] != KERNEL, k))
                for kernel, alpha, rd in lines:
                    seq = sorted((r for r in on if (r["kernel"], mix_of(r)[1], r["R_over_delta"])
                                  == (kernel, alpha, rd) and r[f"angle_{dist}"] is not None),
                                 key=lambda r: r["m"])
                    shift = (0.25 * (alpha > 0.0) - 0.25 * (rd < 20.0)    # keep the bars apart
                             + 0.12 * (KERNELS.index(kernel) - 1))
                    ax.errorbar([r["m"] + shift for r in seq], [r[f"angle_{dist}"] for r in seq],
                                yerr=[resolution_deg(r["m"], dist) for r in seq], capsize=3,
                                color=kinkbench.COLORS[kernel], marker="o" if alpha == 0.0 else "D",
                                ls="-" if rd >= 20.0 else ":", mfc="none" if rd < 20.0 else None,
                                label=f"{kernel}, crack {alpha:g}°, R/δ = {rd:g}")
                ax.set_title(f"psi = {psi:g}°, angle at {HORIZONS[dist]:g} horizons", fontsize=10)
                ax.set_xlabel("m = δ/dx")
                ax.grid(alpha=0.3)
            ax_row[0].set_ylabel("kink angle (deg)")
            ax_row[1].legend(fontsize=6.5, loc="best")
        fig.tight_layout()
        fig.savefig(path, dpi=120)
    finally:
        plt.close(fig)


def _whole_sweeps(rows):
    """{(kernel, m, R/delta): its rows as the kink test's verdict reads them} for every group
    that has run the whole mixed-mode sweep (every psi of the kink test but pure Mode I, in
    both crack directions), the Gaussian's first"""
    need = _sweep_need()
    out = {}
    for kernel, m, rd in sorted({(r["kernel"], r["m"], r["R_over_delta"]) for r in rows},
                                key=lambda g: (g[0] != KERNEL, g)):
        sel = [r for r in rows if (r["kernel"], r["m"], r["R_over_delta"]) == (kernel, m, rd)]
        if need <= {mix_of(r) for r in sel}:
            # the kink test's verdict reads one grid's rows: dx and the ramp are this group's
            out[kernel, m, rd] = [dict(r, psi=mix_of(r)[0], alpha=mix_of(r)[1], dx=m,
                                       ncross=kinkbench.NCROSS) for r in sel if mix_of(r) in need]
    return out


def _sweep_need():
    """the (psi, alpha) pairs of the whole mixed-mode sweep: every psi of the kink test but pure
    Mode I, in both crack directions"""
    return {(p, a) for p in kinkbench.MIXES_DEG if p > 0.0 for a in kinkbench.ALPHAS_DEG}


def _sweep_mixes():
    return ", ".join(f"{p:g}" for p in sorted(p for p in kinkbench.MIXES_DEG if p > 0.0))


def sweep_verdict(rows):
    """Sentences on every (kernel, m, R/delta) that has run the whole mixed-mode sweep: at each
    distance the RMS and mean deviation from each criterion with its standard error, which
    criteria the mean admits (bbpd.benchmarks.kink's test: |mean| <= 2 standard errors), and
    the grid's pull (mean |angle at 22.5 deg - angle along the rows|)."""
    out = []
    for (kernel, m, rd), as_kink in _whole_sweeps(rows).items():
        for dist in HORIZONS:
            v = kinkbench.verdict(as_kink, dist, dx=m)
            dev = ", ".join(f"{NAMES[c]} {v['rms'][c]:.1f} (mean {v['bias'][c]:+.1f} ± {v['se'][c]:.1f})"
                            for c in NAMES)
            out.append(f"{_capital(kernel)}, m = {m:g}, R/delta = {rd:g}, the whole "
                       f"mixed-mode sweep ({v['n']} runs: psi = {_sweep_mixes()}°, both crack "
                       f"directions), at {HORIZONS[dist]:g} horizons: RMS deviation (mean ± its "
                       f"standard error) {dev}°; nearest by RMS {NAMES[v['best']]}. "
                       f"{kinkbench.consistency(v)}{_unresolved(v, m, dist)} The crack's "
                       f"direction to the grid moves the angle by {v['pull_mean']:.1f}° on average "
                       f"(at most {v['pull_max']:.1f}°).")
    return " ".join(out) if out else "No (kernel, m, R/delta) has run the whole mixed-mode sweep."


def _unresolved(v, m, dist):
    """' ...' naming the criteria the two-standard-error test excludes by a mean deviation no
    larger than one angle's error bar (resolution_deg): the standard error of the mean falls
    with the number of runs, the grid's resolution does not, so such an exclusion says less
    than the grid can resolve"""
    bar = resolution_deg(m, dist)
    close = [c for c in NAMES if c not in kinkbench.admitted(v) and abs(v["bias"][c]) <= bar]
    if not close:
        return ""
    return (" Of these, " + " and ".join(f"{NAMES[c]}'s mean ({_signed(v['bias'][c])}°)" for c in close)
            + f" lies within one angle's error bar (± {bar:.1f}°): excluded by less than the grid resolves.")


def _across(per_m, value, fmt=".1f"):
    """'a, b, c': value(v) of each m's verdict v, in the order of per_m"""
    return ", ".join(format(value(v), fmt) for v in per_m.values())


def _nearest(v, dist):
    """the criteria whose RMS in verdict v (of m = v['m']) lies within the grid's resolution of
    the smallest: those the sweep cannot tell apart"""
    least = min(v["rms"].values())
    return [c for c in NAMES if v["rms"][c] - least <= resolution_deg(v["m"], dist)]


def limits(rows):
    """The whole mixed-mode sweep followed across m, per kernel and R/delta with two or more
    complete sweeps, at each distance: a list of dicts with kernel, rd, dist, ms, v (each m's
    verdict), 'limit' (the criterion the sequence approaches, or None) and 'state', the verdict
    on the limit read off the two finest m. RMS values closer than the grid's resolution at that
    distance (resolution_deg) cannot be told apart: those criteria are all nearest.
    - 'none fits' when the two-standard-error test admits none at the finest m;
    - 'tied' when two criteria are nearest at the finest m;
    - 'approaches' when limit is the one nearest at the finest m and among the nearest at the m
      before, its RMS does not grow from the one to the other, the test admits it at the
      finest m and the last step moves the mean by no more than the test's standard errors;
    - else 'changes' (the nearest changes), 'grows' (its RMS grows), 'excluded' (the test
      excludes it) or 'drifts' (the last step moves the mean): not settled.
    'step' is the last step in m: the mean over the mixes of each mix's change of angle, with
    its standard error (paired by mix, so the mixes' own spread cancels)."""
    sweeps = _whole_sweeps(rows)
    out = []
    for kernel, rd in sorted({(k, rd) for k, _, rd in sweeps}, key=lambda g: (g[0] != KERNEL, g)):
        ms = sorted(m for k, m, r in sweeps if (k, r) == (kernel, rd))
        if len(ms) < 2:
            continue
        for dist in HORIZONS:
            v = {m: dict(kinkbench.verdict(sweeps[kernel, m, rd], dist, dx=m), m=m) for m in ms}
            prev, last = v[ms[-2]], v[ms[-1]]
            step = _step(sweeps[kernel, ms[-2], rd], sweeps[kernel, ms[-1], rd], dist)
            best = last["best"]
            near, near_prev = _nearest(last, dist), _nearest(prev, dist)
            admitted = kinkbench.admitted(last)
            if not admitted:
                state = "none fits"
            elif len(near) > 1:
                state = "tied"
            elif best not in near_prev:
                state = "changes"
            elif last["rms"][best] > prev["rms"][best]:
                state = "grows"
            elif best not in admitted:
                state = "excluded"
            elif _drifts(step):
                state = "drifts"
            else:
                state = "approaches"
            out.append(dict(kernel=kernel, rd=rd, dist=dist, ms=ms, v=v, state=state, near=near,
                            near_prev=near_prev, step=step,
                            limit=best if state == "approaches" else None))
    return out


def _step(before, after, dist):
    """(mean, standard error) over the mixes of the change of the angle at dist from the rows
    `before` to the rows `after` (two whole sweeps), paired by mix"""
    key = f"angle_{dist}"
    a = {mix_of(r): r[key] for r in before}
    d = [r[key] - a[mix_of(r)] for r in after]
    return statistics.fmean(d), statistics.stdev(d) / math.sqrt(len(d))


def _drifts(step):
    """the last step moves the mean by more than the two-standard-error test allows"""
    return abs(step[0]) > kinkbench.TEST_SE * step[1]


def _step_text(t):
    """the last step in m of one entry of limits(), and whether it drifts"""
    mean, se = t["step"]
    verdict = ("more than two standard errors: the sequence still drifts" if _drifts(t["step"])
               else "within two standard errors: no drift shown")
    return (f"from m = {t['ms'][-2]:g} to {t['ms'][-1]:g} the mean moves by {mean:+.1f} ± {se:.1f}° "
            f"(paired by mix; positive: the crack kinks less), {verdict}")


def _limit_tail(t):
    """the sentence on the limit of one entry of limits()"""
    ms, dist, v = t["ms"], t["dist"], t["v"]
    prev, last = v[ms[-2]], v[ms[-1]]
    best = last["best"]
    step = f"m = {ms[-2]:g} to {ms[-1]:g}"
    if t["state"] == "none fits":
        means = "; ".join(f"from {NAMES[c]} {_across(v, lambda x: x['bias'][c], '+.1f')}"
                          for c in _between(last) or (_nearest_mean(last),))
        return (f"At m = {ms[-1]:g} the two-standard-error test admits none of the criteria: none "
                f"fits; {_bracket(last)}. The mean deviation at m = "
                f"{_across(v, lambda x: x['m'], 'g')}: {means}°; {_step_text(t)}.")
    if t["state"] == "tied":
        return (f"Not settled: at m = {ms[-1]:g} " + " and ".join(NAMES[c] for c in t["near"])
                + " lie equally near (RMS " + " and ".join(f"{last['rms'][c]:.1f}" for c in t["near"])
                + f"°, closer than the grid's resolution, ± {resolution_deg(ms[-1], dist):.1f}°).")
    if t["state"] == "changes":
        return (f"Not settled: from {step} the nearest criterion changes from "
                + " and ".join(NAMES[c] for c in t["near_prev"]) + f" to {NAMES[best]}.")
    if t["state"] == "grows":
        return (f"Not settled: {NAMES[best]} stays the nearest, but from {step} its RMS "
                f"grows from {prev['rms'][best]:.1f} to {last['rms'][best]:.1f}°.")
    if t["state"] == "drifts":
        return (f"Not settled: {NAMES[best]} stays the nearest with its RMS falling and the test "
                f"admits it at m = {ms[-1]:g}, but {_step_text(t)}.")
    if t["state"] == "excluded":
        return (f"Not settled: {NAMES[best]} stays the nearest with its RMS falling, but at "
                f"m = {ms[-1]:g} the test excludes it.")
    return (f"The sequence approaches {NAMES[best]}: among the nearest at m = {ms[-2]:g} "
            f"and the nearest at {ms[-1]:g}, its RMS falling from {prev['rms'][best]:.1f} to "
            f"{last['rms'][best]:.1f}°, admitted by the test at m = {ms[-1]:g}; {_step_text(t)}.")


def _between(v):
    """(the criterion nearest the mean of verdict v among those it kinks beyond, the nearest
    among those it falls short of), or None when it lies beyond (or short of) every one; the
    sign is kinkbench.consistency's: a positive mean deviation kinks less"""
    more = [c for c in NAMES if v["bias"][c] < 0.0]
    less = [c for c in NAMES if v["bias"][c] >= 0.0]
    if not (more and less):
        return None
    return tuple(min(side, key=lambda c: abs(v["bias"][c])) for side in (more, less))


def _nearest_mean(v):
    """the criterion the mean angle of verdict v lies nearest"""
    return min(NAMES, key=lambda c: abs(v["bias"][c]))


def _bracket(v):
    """where the mean angle of verdict v lies among the criteria, as a clause"""
    def dev(c):
        return f"{abs(v['bias'][c]):.1f} ± {v['se'][c]:.1f}°"
    pair = _between(v)
    if pair:
        more, less = pair
        return (f"the mean lies between {NAMES[more]} (BBPD kinks more by {dev(more)}) and "
                f"{NAMES[less]} (less by {dev(less)})")
    nearest = _nearest_mean(v)
    word = "more" if v["bias"][nearest] < 0.0 else "less"
    return f"BBPD kinks {word} than every criterion, by {dev(nearest)} than the nearest, {NAMES[nearest]}"


def sweep_trend(rows):
    """limits() as sentences: per kernel, R/delta and distance the nearest criterion by RMS,
    each criterion's RMS and the grid's pull at each m, and the verdict on the limit."""
    out = []
    for t in limits(rows):
        v = t["v"]
        rms_text = "; ".join(f"{NAMES[c]} {_across(v, lambda x: x['rms'][c])}" for c in NAMES)
        out.append(f"{_capital(t['kernel'])}, R/delta = {t['rd']:g}, the whole mixed-mode sweep "
                   f"at m = {_across(v, lambda x: x['m'], 'g')}, {HORIZONS[t['dist']]:g} horizons out: "
                   f"nearest by RMS {_across(v, lambda x: NAMES[x['best']], 's')}; RMS {rms_text}°; "
                   f"the grid's pull {_across(v, lambda x: x['pull_mean'])}°. " + _limit_tail(t))
    return (" ".join(out) if out else
            "No trend across m: no (kernel, R/delta) has run the whole mixed-mode sweep at two m.")


def limit_sentence(rows, kernel=KERNEL):
    """One sentence for other READMEs: what the kink test's sweep in m says about the limit for
    `kernel`, in the largest disk (R/delta) with two complete sweeps, at each distance; a
    criterion is named only where the sequence approaches it."""
    mine = [t for t in limits(rows) if t["kernel"] == kernel]
    if not mine:
        return (f"The kink test's sweep in m has no verdict on the limit for the {kernel} kernel "
                "yet (no R/delta with the whole mixed-mode sweep at two m).")
    rd = max(t["rd"] for t in mine)
    mine = [t for t in mine if t["rd"] == rd]
    parts = []
    for t in mine:
        where = f"{HORIZONS[t['dist']]:g} horizons from the tip"
        if t["limit"] is not None:
            parts.append(f"{where} it approaches {NAMES[t['limit']]}")
        elif t["state"] == "tied":
            parts.append(f"{where} it is not settled (" + " and ".join(NAMES[c] for c in t["near"])
                         + f" equally near at m = {t['ms'][-1]:g})")
        elif t["state"] == "none fits":
            pair = _between(t["v"][t["ms"][-1]])
            parts.append(f"{where} none of the criteria fits" + (
                " (the kink lies between " + " and ".join(NAMES[c] for c in pair)
                + (", still drifting" if _drifts(t["step"]) else "") + ")" if pair else ""))
        else:
            parts.append(f"{where} it is not settled")
    settled = all(t["limit"] is not None for t in mine)
    same = len({t["limit"] for t in mine}) == 1
    verdict = (f"the kink follows {NAMES[mine[0]['limit']]}" if settled and same else
               "which criterion the kink follows is not settled")
    return (f"The kink test's whole mixed-mode sweep followed in m ({_capital(kernel)}, "
            f"R/delta = {rd:g}, m = {', '.join(f'{m:g}' for m in mine[0]['ms'])}): "
            + "; ".join(parts) + f"; so {verdict}.")


# The planned sweep, what the kink verdict needs: the whole mixed-mode sweep (both crack
# directions) in the disk R/delta = PLAN_R_OVER_DELTA, for the Gaussian kernel at m = 10, 15, 20
# and for the constant and triangular kernels at m = 15
PLAN = {"gaussian": (10, 15, 20), "constant": (15,), "triangular": (15,)}
PLAN_R_OVER_DELTA = 20


def coverage(rows):
    """What of PLAN has run (computed from the CSV): per kernel and m the mixed-mode runs in,
    the ones left, and each group's loop time with the CPU and rank count that timed it."""
    need = _sweep_need()
    rd = PLAN_R_OVER_DELTA
    parts, left = [], []
    for kernel, ms in PLAN.items():
        for m in ms:
            sel = [r for r in rows if (r["kernel"], r["m"], r["R_over_delta"]) == (kernel, m, rd)
                   and mix_of(r) in need]
            done = {mix_of(r) for r in sel}
            state = "whole" if done == need else f"{len(done)} of {len(need)}"
            if sel:
                # machines differ: the loop times of the machine that timed most of the group
                by = {}
                for r in sel:
                    by.setdefault(f"{r['cpu']}, {r['nprocs']:g} ranks", []).append(r["loop_s"])
                machine, loops = max(sorted(by.items()), key=lambda kv: len(kv[1]))
                state += (f" (loop {min(loops):.0f}-{max(loops):.0f} s for the {len(loops)} of them "
                          f"on {machine})")
            parts.append(f"{_capital(kernel)} m = {m:g}: {state}")
            if need - done:
                left.append(f"{_capital(kernel)} m = {m:g}: {_mix_list(need - done)}")
    text = (f"The planned sweep, at R/delta = {rd:g} over psi = {_sweep_mixes()}° in both "
            "crack directions: " + "; ".join(parts) + ". ")
    return text + ("Left: " + "; ".join(left) + "." if left else "Every run of it is in.")


def _mixes_at(rows, kernel, m, rd):
    """the mixed-mode (psi, alpha) pairs run for (kernel, m, R/delta)"""
    return {mix_of(r) for r in rows
            if (r["kernel"], r["m"], r["R_over_delta"]) == (kernel, m, rd) and mix_of(r)[0] > 0.0}


def _mix_list(mixes):
    return ", ".join(f"psi = {p:g}° " + ("along the rows" if a == 0.0 else f"at {a:g}°")
                     for p, a in sorted(mixes, key=lambda x: (-x[0], x[1])))


def _rms_from_criteria(sel, key, m):
    """{'m': m, 'rms': {criterion: RMS of (angle `key` - criterion) over the rows sel}}: what
    _nearest reads"""
    return {"m": m, "rms": {c: kinkbench.rms([r[key] - r[c] for r in sel]) for c in NAMES}}


def _rms_move(name, before, after):
    """"X's RMS falls from a to b°", or "holds at a°" when the two show the same digits"""
    if f"{before:.1f}" == f"{after:.1f}":
        return f"{name}'s RMS holds at {after:.1f}°"
    return f"{name}'s RMS {'falls' if after < before else 'grows'} from {before:.1f} to {after:.1f}°"


def subset_trend(rows):
    """Where the finest m has run only part of the mixed-mode sweep that a coarser m ran whole
    (same kernel and R/delta): those mixes followed across
    every m that ran them all, per kernel and R/delta, at each distance: each criterion's RMS
    over the same mixes and the nearest (criteria within the grid's resolution of the smallest
    RMS tie), and whether the RMS of the finest m's nearest falls or grows over the last step.
    A part of the sweep names no limit: sweep_trend does, once the finest m is complete."""
    whole = _whole_sweeps(rows)
    out = []
    for kernel, rd in sorted({(r["kernel"], r["R_over_delta"]) for r in rows},
                             key=lambda g: (g[0] != KERNEL, g)):
        finest = max(r["m"] for r in rows if (r["kernel"], r["R_over_delta"]) == (kernel, rd))
        mixes = _mixes_at(rows, kernel, finest, rd)
        if (not mixes or (kernel, finest, rd) in whole
                or not any((k, r_) == (kernel, rd) for k, _, r_ in whole)):
            continue    # complete, or no coarser m ran the whole sweep to hold it against
        ms = sorted(m for m in {r["m"] for r in rows if (r["kernel"], r["R_over_delta"]) == (kernel, rd)}
                    if mixes <= _mixes_at(rows, kernel, m, rd))
        if len(ms) < 2:
            continue
        for dist in HORIZONS:
            key = f"angle_{dist}"
            per_m = {}
            for m in ms:
                sel = [r for r in rows if (r["kernel"], r["m"], r["R_over_delta"]) == (kernel, m, rd)
                       and mix_of(r) in mixes and r[key] is not None]
                if len(sel) != len(mixes):
                    break       # a run that measured no angle this far out: no RMS over the set
                per_m[m] = _rms_from_criteria(sel, key, m)
            if len(per_m) < 2:
                continue
            seq = list(per_m)
            last, prev = per_m[seq[-1]], per_m[seq[-2]]
            rms_text = "; ".join(f"{NAMES[c]} {_across(per_m, lambda x: x['rms'][c])}" for c in NAMES)
            ties = {m: _nearest(v, dist) for m, v in per_m.items()}
            nearest_text = ", ".join(f"at m = {m:g} " + " and ".join(NAMES[c] for c in t)
                                     + (" (tied)" if len(t) > 1 else "") for m, t in ties.items())
            count = "the one mix" if len(mixes) == 1 else f"the {len(mixes)} mixes"
            s = (f"{_capital(kernel)}, R/delta = {rd:g}, {count} run so far at m = {finest:g} "
                 f"({_mix_list(mixes)}) followed over m = {_across(per_m, lambda x: x['m'], 'g')}, "
                 f"{HORIZONS[dist]:g} horizons out: RMS {rms_text}°; nearest {nearest_text}. ")
            moves = [_rms_move(NAMES[c], prev["rms"][c], last["rms"][c]) for c in ties[seq[-1]]]
            s += (f"From m = {seq[-2]:g} to {seq[-1]:g} the nearest at {seq[-1]:g}: " + "; ".join(moves)
                  + f". A part of the sweep: it says which way these mixes move, not the limit.")
            out.append(s)
    return " ".join(out) if out else "Every finest m has run the whole mixed-mode sweep or none of it."


# a comparison over the mode mix needs more than one mix: pure Mode II alone is in verdict()
KERNEL_COMPARISON_MIN_MIXES = 2


def kernel_comparison(rows):
    """Per (m, R/delta) run by more than one kernel, over the mixed-mode mixes every such kernel
    ran (at least KERNEL_COMPARISON_MIN_MIXES), at each distance: each kernel's RMS from each
    criterion and its nearest (criteria within the grid's resolution of the smallest RMS tie),
    and how far the kernels' angles lie apart (largest minus smallest, per mix), held against
    the two runs' error bars. Whether the kernel changes the nearest criterion is computed: the
    kernels agree when one criterion is among the nearest of every kernel."""
    out = []
    for m, rd in sorted({(r["m"], r["R_over_delta"]) for r in rows}, key=lambda g: (g[1], g[0])):
        kernels = sorted({r["kernel"] for r in rows if (r["m"], r["R_over_delta"]) == (m, rd)
                          and mix_of(r)[0] > 0.0}, key=lambda k: (k != KERNEL, k))
        if len(kernels) < 2:
            continue
        mixes = set.intersection(*(_mixes_at(rows, k, m, rd) for k in kernels))
        if len(mixes) < KERNEL_COMPARISON_MIN_MIXES:
            continue
        for dist in HORIZONS:
            key = f"angle_{dist}"
            runs = {(r["kernel"], mix_of(r)): r for r in rows
                    if (r["m"], r["R_over_delta"]) == (m, rd) and r["kernel"] in kernels
                    and mix_of(r) in mixes}
            measured = sorted(x for x in mixes if all(runs[k, x][key] is not None for k in kernels))
            if len(measured) < KERNEL_COMPARISON_MIN_MIXES:
                continue
            per_k = {k: _rms_from_criteria([runs[k, x] for x in measured], key, m) for k in kernels}
            ties = {k: _nearest(v, dist) for k, v in per_k.items()}
            spread = {x: max(runs[k, x][key] for k in kernels) - min(runs[k, x][key] for k in kernels)
                      for x in measured}
            widest = max(spread, key=spread.get)
            bar = resolution_deg(m, dist)
            rms_text = "; ".join(f"{_capital(k)} " + ", ".join(f"{NAMES[c]} {per_k[k]['rms'][c]:.1f}"
                                                              for c in NAMES) for k in kernels)
            near_text = ", ".join(f"{_capital(k)} " + " and ".join(NAMES[c] for c in ties[k])
                                  + (" (tied)" if len(ties[k]) > 1 else "") for k in kernels)
            common = [c for c in NAMES if all(c in ties[k] for k in kernels)]
            within = ("within" if spread[widest] <= 2.0 * bar else "beyond")
            s = (f"m = {m:g}, R/delta = {rd:g}, the {len(measured)} mixes run by every kernel here "
                 f"({_mix_list(measured)}), {HORIZONS[dist]:g} horizons out: RMS {rms_text}°; nearest "
                 f"{near_text}. The kernels' angles lie {_f(sum(spread.values()) / len(spread))}° apart "
                 f"on average and at most {_f(spread[widest])}° ({_mix_list([widest])}), {within} the "
                 f"two runs' error bars (± {bar:.1f}° each). ")
            s += (f"The kernel does not change the nearest criterion ("
                  + " and ".join(NAMES[c] for c in common) + ")." if common else
                  "The kernel changes the nearest criterion.")
            out.append(s)
    return (" ".join(out) if out else
            "No (m, R/delta) has more than one kernel over more than one mixed mode.")


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kink test: convergence of the pure Mode II angle in m and in the disk's size"


def jobs(nprocs=1):
    """The runs as bbpd.report specs (tools/reproduce --full)."""
    inputs = (kinkbench.EXAMPLE, Path(__file__), Path(kinkbench.__file__))
    specs = []
    for m, rd in CASES:
        label = f"kink convergence m = {m:g} R/delta = {rd:g}"
        job = Job(label=label, func="bbpd.report:run_job",
                  kwargs={"target": "bbpd.benchmarks.kink_convergence:run_case",
                          "args": {"m": m, "r_over_delta": rd, "nprocs": nprocs}, "label": label},
                  inputs=tuple(str(p) for p in inputs),
                  estimate_s=90.0 * (m / 5.0) ** 3 * (rd / 10.0) ** 3)
        specs.append(Spec("kinkconv", KERNEL, DELTA / m, job))
    return specs


def section(specs, results, figdir, notes):
    """The kink convergence section of REPORT.md (tools/reproduce --full), with the limit
    that the committed whole sweeps name (they take days, so no report run remakes them)."""
    committed = (f"The committed whole mixed-mode sweeps ({CSV.relative_to(kinkbench.ROOT)}): "
                 + limit_sentence(read_rows()))
    return jobmod.rows_section(
        REPORT_TITLE, specs, results,
        f"Not run by default ({len(jobs())} runs, about an hour): `tools/reproduce --full` runs "
        "them; the last measured table is in examples/kink-mixed-mode/README.md, 'Convergence "
        f"in m and in the disk's size'. {committed}",
        f"Gaussian kernel, pure Mode II, crack along the rows, delta = {DELTA * 1e3:g} mm; see "
        f"examples/kink-mixed-mode/README.md. {committed}",
        table, verdict)


def read_rows(path=CSV):
    comments, rows = csvfile.read_csv(path)
    return with_cpu(rows, comments)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--work", default="/tmp/kink-conv")
    ap.add_argument("--nprocs", type=int, default=1)
    ap.add_argument("--cases", nargs="+", help="M:R_OVER_DELTA pairs (default: all)")
    ap.add_argument("--kernel", default=KERNEL, choices=KERNELS)
    ap.add_argument("--psi", type=float, default=PSI, choices=kinkbench.MIXES_DEG,
                    help="mode mix arctan(K_II/K_I) in degrees (default: pure Mode II)")
    ap.add_argument("--alpha", type=float, default=ALPHA, choices=kinkbench.ALPHAS_DEG,
                    help="crack direction to the grid's rows in degrees")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--csv")
    ap.add_argument("--append", action="store_true",
                    help="add the runs to --csv, keeping its rows and the commands that made them")
    ap.add_argument("--figure", help="draw the angle against m of the CSV's rows here (no runs)")
    a = ap.parse_args(argv)
    if a.figure:
        figure(read_rows(a.csv or CSV), a.figure)
        return 0
    cases = CASES if not a.cases else [tuple(float(v) for v in c.split(":")) for c in a.cases]
    cmd = "tools/python -m bbpd.benchmarks.kink_convergence " + " ".join(argv or sys.argv[1:])
    earlier, rows, made = csvfile.continue_csv(a.csv if a.append else None, cmd)
    if rows:
        rows = read_rows(a.csv)    # with the CPU of rows from before the cpu column
    for m, rd in cases:
        start = time.perf_counter()
        r = run_case(a.work, m, rd, a.nprocs, a.reuse, a.kernel, a.psi, a.alpha)
        print(f"psi {a.psi:g} alpha {a.alpha:g} m {m:g} R/delta {rd:g}: angle {_f(r['angle_2d'])} / {_f(r['angle_4d'])} deg "
              f"(2 / 4 delta), loop {_f(r['loop_s'], '.0f')} s, wall "
              f"{time.perf_counter() - start:.0f} s", flush=True)
        rows.append(r)
        if a.csv:    # after every run: a stopped sweep keeps what it measured
            csvfile.write_csv(a.csv, [{c: r.get(c) for c in COLUMNS} for r in rows], comments=[
                *earlier, made, f"{TIMING}LAMMPS loop time (s); the CPU of each run in column cpu"])
    print(verdict(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
