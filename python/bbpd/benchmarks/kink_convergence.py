# SPDX-License-Identifier: GPL-2.0-or-later
"""The kink test's convergence: the kink angle against m and R/delta, pure Mode II by default,
measured as bbpd.benchmarks.kink measures (examples/kink-mixed-mode/README.md has the reasons
and the commands).
"""

import sys
import time
from pathlib import Path

from bbpd import csvfile
from bbpd import jobs as jobmod
from bbpd.benchmarks import kink as kinkbench
from bbpd.provenance import cpu
from bbpd.kernels import KERNELS
from bbpd.runner import run_lammps
from bbpd import plots
from bbpd.markdown import cell
from bbpd.markdown import table as md_table
from bbpd.benchmarks import cli
from bbpd.benchmarks.kink_limit import (ALPHA, HORIZONS, KERNEL, NAMES, PSI, coverage, disk_moves,
                                        kernel_spread, limit, limits, mix_of, resolution_deg,
                                        sequences, sweep_stats)

CSV = kinkbench.FOLDER / "results" / "kink_convergence.csv"
DELTA = 5.0e-3
DT_PER_M = 0.16                     # dtfactor / m of the kink test (kink.DTFACTOR)
# (m, R/delta), cheapest first: a sweep stopped early keeps the cases that finished
CASES = ((5, 10), (10, 10), (5, 20), (15, 10), (10, 20), (20, 10))
COLUMNS = ("kernel", "psi", "alpha", "m", "R_over_delta", "dx_mm", "atoms", "steps",
           "K_init_over_Kc", "extension_over_delta", "angle_2d", "angle_4d", "hoop_stress",
           "hoop_strain", "energy", "loop_s", "nprocs", "cpu")


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
    return dict({c: r.get(c) for c in COLUMNS}, m=float(m), R_over_delta=float(r_over_delta),
                dx_mm=r["dx"] * 1e3, cpu=cpu())


def _angle(r, dist):
    """'angle +- resolution' for the table"""
    a = r[f"angle_{dist}"]
    return "-" if a is None else f"{cell(a, '.1f')} ± {resolution_deg(r['m'], dist):.1f}"


def _order(r):
    psi, alpha = mix_of(r)
    return (r["kernel"] != KERNEL, r["kernel"], -psi, alpha, r["R_over_delta"], r["m"])


def table(rows):
    head = ("kernel", "psi", "alpha", "m", "R/delta", "dx (mm)", "atoms", "steps",
            "K at 1st break / K_c", "extension (delta)", "angle at 2 delta", "angle at 4 delta",
            "hoop stress", "hoop strain", "max G", "loop (s)", "ranks")
    out = md_table(head, ([
        r["kernel"], *(f"{v:g}" for v in mix_of(r)), f"{r['m']:g}", f"{r['R_over_delta']:g}",
        f"{r['dx_mm']:.3g}", cell(r["atoms"], ".0f"), cell(r["steps"], ".0f"),
        cell(r["K_init_over_Kc"], ".3f"), cell(r["extension_over_delta"], ".1f"), _angle(r, "2d"),
        _angle(r, "4d"), *(cell(r[c], ".1f") for c in ("hoop_stress", "hoop_strain", "energy")),
        cell(r["loop_s"], ".0f"), cell(r["nprocs"], ".0f")] for r in sorted(rows, key=_order)))
    out += "\n\n" + RESOLUTION_NOTE
    if rows and all(r.get("cpu") for r in rows):
        out += "\n\n" + loop_times(rows)
    return out


RESOLUTION_NOTE = ("Angles ± the grid's resolution: half a spacing across the path at 2 or 4 "
                   "horizons from the tip, atan(1 / (2 n m)) for n horizons.")


def _signed(v):
    """v to 0.1 with its sign, +0.0 for a zero however it rounds"""
    return "+0.0" if float(format(v, ".1f")) == 0.0 else format(v, "+.1f")


def _yes(flag):
    return "yes" if flag else "no"


def _names(criteria, empty="none"):
    return ", ".join(NAMES[c] for c in criteria) or empty


def sequences_table(rows):
    """kink_limit.sequences as a table: per kernel, mode mix, distance and disk the angles over
    m, the criterion the finest lies nearest (offset ± its error bar), the last step in m and
    whether it settled (within SETTLED_DEG) or moved by more than the two runs' error bars"""
    return md_table(
        ("kernel", "psi", "alpha", "at", "R/delta", "m", "angle (deg)", "nearest at the finest m: "
         "offset ± bar (deg)", "last step (deg)", "settled (<= 1 deg)", "step beyond both bars"),
        ([s["kernel"], f"{s['psi']:g}", f"{s['alpha']:g}", s["dist"], f"{s['rd']:g}",
          ", ".join(f"{m:g}" for m in s["ms"]), ", ".join(cell(a, ".1f") for a in s["angles"]),
          f"{NAMES.get(s['nearest'], 'all three agree')}: {_signed(s['offset'])} ± {s['bar']:.1f}",
          _signed(s["step"]), _yes(s["settled"]), _yes(s["beyond_bars"])] for s in sequences(rows)))


def disk_table(rows):
    """kink_limit.disk_moves as a table: the angle's change when the disk doubles at one m"""
    return md_table(("kernel", "psi", "alpha", "at", "m", "R/delta 10 -> 20 (deg)"),
                    ([d["kernel"], f"{d['psi']:g}", f"{d['alpha']:g}", d["dist"], f"{d['m']:g}",
                      _signed(d["move"])] for d in disk_moves(rows)))


def _mix_list(mixes):
    return ", ".join(f"{p:g}/{a:g}" for p, a in sorted(mixes, key=lambda x: (-x[0], x[1])))


def sweeps_table(rows):
    """kink_limit.sweep_stats as a table: per whole mixed-mode sweep and distance the RMS (mean
    ± its standard error) from each criterion, the criteria the two-standard-error test admits,
    those it excludes by less than one angle's error bar, and the grid's pull"""
    return md_table(
        ("kernel", "m", "R/delta", "at", "runs", *(f"{n}: RMS (mean ± s.e.), deg" for n in NAMES.values()),
         "admitted", "excluded by less than the bar", "grid's pull: mean (max), deg"),
        ([s["kernel"], f"{s['m']:g}", f"{s['rd']:g}", s["dist"], s["n"],
          *(f"{s['rms'][c]:.1f} ({s['bias'][c]:+.1f} ± {s['se'][c]:.1f})" for c in NAMES),
          _names(s["admitted"]), _names(s["unresolved"], "-"),
          f"{s['pull_mean']:.1f} ({s['pull_max']:.1f})"] for s in sweep_stats(rows)))


def _verdict(t):
    between = (" (between " + " and ".join(NAMES[c] for c in t["between"]) + ")"
               if t["between"] and t["state"] == "none fits" else "")
    return t["state"] + (f" {NAMES[t['limit']]}" if t["limit"] else "") + between


def limits_table(rows):
    """kink_limit.limits as a table: per kernel, disk and distance the whole sweeps over m, the
    nearest criterion and each criterion's RMS at each m, the grid's pull, the verdict on the
    limit and the last step of the sweep's mean (paired by mix, ± its standard error)"""
    out = []
    for t in limits(rows):
        v = [t["v"][m] for m in t["ms"]]
        out.append([t["kernel"], f"{t['rd']:g}", t["dist"], ", ".join(f"{m:g}" for m in t["ms"]),
                    ", ".join(NAMES[x["best"]] for x in v),
                    *(", ".join(f"{x['rms'][c]:.1f}" for x in v) for c in NAMES),
                    ", ".join(f"{x['pull_mean']:.1f}" for x in v), _verdict(t),
                    f"{t['step'][0]:+.1f} ± {t['step'][1]:.1f}"])
    return md_table(("kernel", "R/delta", "at", "m", "nearest by RMS",
                     *(f"RMS from {n}, deg" for n in NAMES.values()), "grid's pull, deg", "verdict",
                     "last step of the mean, deg"), out)


def kernels_table(rows):
    """kink_limit.kernel_spread as a table: the kernels at one m over the mixes all of them ran"""
    return md_table(
        ("m", "R/delta", "at", "mixes (psi/alpha)", "nearest per kernel", "kernels' spread: mean, "
         "max (at mix), deg", "within both bars", "criterion nearest for every kernel"),
        ([f"{k['m']:g}", f"{k['rd']:g}", k["dist"], _mix_list(k["mixes"]),
          "; ".join(f"{kern} " + " and ".join(NAMES[c] for c in k["nearest"][kern])
                    for kern in k["kernels"]),
          f"{k['spread_mean']:.1f}, {k['spread_max']:.1f} ({_mix_list([k['widest']])})",
          f"{_yes(k['within_bars'])} (± {k['bar']:.1f})", _names(k["common"])]
         for k in kernel_spread(rows)))


def coverage_table(rows):
    """kink_limit.coverage as a table: what of the planned sweep has run, and its loop times"""
    return md_table(
        ("kernel", "m", "mixes run", "left (psi/alpha)", "loop (s), of the runs on", "machine"),
        ([kernel, f"{m:g}", f"{len(c['done'])} of {len(c['done']) + len(c['left'])}",
          _mix_list(c["left"]) or "-",
          f"{min(c['loops']):.0f}-{max(c['loops']):.0f}, {len(c['loops'])}" if c["loops"] else "-",
          c["machine"] or "-"] for (kernel, m), c in coverage(rows).items()))


def loop_times(rows):
    """'Loop times: ...': the CPU that timed each run (appended runs may come from another
    machine)."""
    def case(r):
        psi, alpha = mix_of(r)
        return f"{r['kernel']} psi = {psi:g}, alpha = {alpha:g}, m = {r['m']:g}, R/delta = {r['R_over_delta']:g}"
    return csvfile.loop_times_note(sorted(rows, key=_order), "cpu", case)


FIGURE = kinkbench.FOLDER / "kink_convergence.png"


def figure(rows, path=FIGURE):
    """The angle at 2 and 4 horizons against m with its error bar, one panel per distance and
    mode mix (pure Mode II first), each (kernel, crack direction, R/delta) a line, and the three
    criteria of that mix as horizontal lines."""
    mixes = sorted({mix_of(r)[0] for r in rows if mix_of(r)[0] > 0.0}, reverse=True)
    with plots.figure(path, len(mixes), 2, figsize=(10, 3.6 * len(mixes)), squeeze=False, dpi=120) as (fig, axes):
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


def limit_table(found):
    """kink_limit.limit as a table: the disk and the m of the committed whole sweeps, per
    distance the state of the limit and the criterion approached, and the one every distance
    follows; empty without two whole sweeps"""
    if found is None:
        return ""
    return md_table(("kernel", "R/delta", "m", "at", "state", "limit", "follows"), (
        [found["kernel"], f"{found['rd']:g}", ", ".join(f"{m:g}" for m in found["ms"]), d,
         t["state"], NAMES[t["limit"]] if t["limit"] else "-",
         NAMES[found["follows"]] if found["follows"] else "not settled"]
        for d, t in found["at"].items()))


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kink test: convergence of the pure Mode II angle in m and in the disk's size"


def jobs(nprocs=1):
    """The runs as bbpd.report specs (tools/reproduce --full)."""
    inputs = (kinkbench.EXAMPLE, Path(__file__), Path(kinkbench.__file__))
    return jobmod.report_specs("kinkconv", "bbpd.benchmarks.kink_convergence:run_case", inputs, (
        (KERNEL, DELTA / m, f"kink convergence m = {m:g} R/delta = {rd:g}",
         {"m": m, "r_over_delta": rd, "nprocs": nprocs}, 90.0 * (m / 5.0) ** 3 * (rd / 10.0) ** 3)
        for m, rd in CASES))


def section(specs, results, figdir, notes):
    """The kink convergence section of REPORT.md (tools/reproduce --full), with the limit
    that the committed whole sweeps name (they take days, so no report run remakes them)."""
    found = limit(read_rows())
    committed = (f"The last table gives the limit the committed whole mixed-mode sweeps "
                 f"({CSV.relative_to(kinkbench.ROOT)}) name." if found else
                 "No R/delta has the whole mixed-mode sweep at two m yet.")
    s = jobmod.section(
        REPORT_TITLE, f"Gaussian kernel, pure Mode II, crack along the rows, delta = "
        f"{DELTA * 1e3:g} mm; see examples/kink-mixed-mode/README.md. {committed}", specs, results,
        lambda rows: table(rows) + "\n\n" + sequences_table(rows),
        not_run=f"Not run by default ({len(jobs())} runs, about an hour): `tools/reproduce --full` "
        "runs them; the last measured table is in examples/kink-mixed-mode/README.md, "
        f"'Convergence in m and in the disk's size'. {committed}")
    s["table"] = "\n\n".join(p for p in (s["table"], limit_table(found)) if p)
    return s


def read_rows(path=CSV):
    return csvfile.read_csv(path)[1]


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kink-conv", nprocs=1, reuse=True, csv=True, append=True)
    ap.add_argument("--cases", nargs="+", help="M:R_OVER_DELTA pairs (default: all)")
    ap.add_argument("--kernel", default=KERNEL, choices=KERNELS)
    ap.add_argument("--psi", type=float, default=PSI, choices=kinkbench.MIXES_DEG,
                    help="mode mix arctan(K_II/K_I) in degrees (default: pure Mode II)")
    ap.add_argument("--alpha", type=float, default=ALPHA, choices=kinkbench.ALPHAS_DEG,
                    help="crack direction to the grid's rows in degrees")
    ap.add_argument("--figure", help="draw the angle against m of the CSV's rows here (no runs)")
    a = ap.parse_args(argv)
    if a.figure:
        figure(read_rows(a.csv or CSV), a.figure)
        return 0
    cases = CASES if not a.cases else [tuple(float(v) for v in c.split(":")) for c in a.cases]
    earlier, rows, made = csvfile.continue_csv(a.csv if a.append else None,
                                               cli.command("kink_convergence", argv))
    for m, rd in cases:
        start = time.perf_counter()
        r = run_case(a.work, m, rd, a.nprocs, a.reuse, a.kernel, a.psi, a.alpha)
        print(f"psi {a.psi:g} alpha {a.alpha:g} m {m:g} R/delta {rd:g}: angle {cell(r['angle_2d'], '.1f')} / {cell(r['angle_4d'], '.1f')} deg "
              f"(2 / 4 delta), loop {cell(r['loop_s'], '.0f')} s, wall "
              f"{time.perf_counter() - start:.0f} s", flush=True)
        rows.append(r)
        if a.csv:    # after every run: a stopped sweep keeps what it measured
            csvfile.write_csv(a.csv, rows, [*earlier, made, "timing: LAMMPS loop time (s); the "
                                            "CPU of each run in column cpu"], columns=COLUMNS)
    print(sequences_table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
