# SPDX-License-Identifier: GPL-2.0-or-later
"""What the kink test's runs in m say (bbpd.benchmarks.kink_convergence runs them), as data: each
sequence in m and whether its last step settled it, the whole mixed-mode sweeps' deviations from
the kink criteria, the criterion the sweeps approach (or why none), the kernels against one
another, and what of the planned sweep has run. Every verdict is a dict of the numbers it rests
on; the READMEs state them by hand and tests/python/test_kink_convergence.py checks them."""
import math
import statistics

from bbpd.benchmarks import kink as kinkbench

KERNEL, PSI, ALPHA = "gaussian", 90.0, 0.0    # the sweep's default: pure Mode II along the rows

SETTLED_DEG = 1.0                   # the last refinement in m moves the angle by less


# The angle's error bar is the grid's resolution: the path is the centroid of a band of two to
# three crack atoms (bbpd.crack_path), and one more atom row on one side of the band moves the
# centroid across the path by half a spacing. At d = n horizons = n m spacings from the tip that
# turns the direction by atan(LATERAL_QUANTUM_DX / (n m)).
LATERAL_QUANTUM_DX = 0.5
HORIZONS = {f"{n:g}d": n for n in kinkbench.DISTANCES}    # where the angles are measured


def resolution_deg(m, dist):
    """the error bar (deg) of an angle measured `dist` ('2d', '4d') from the tip at m = delta/dx"""
    return math.degrees(math.atan(LATERAL_QUANTUM_DX / (HORIZONS[dist] * m)))


def mix_of(r):
    """(psi, alpha) of a row (the rows of pure Mode II along the rows may omit them)"""
    return (float(r.get("psi", PSI)), float(r.get("alpha", ALPHA)))


AGREE_DEG = 0.05     # criteria closer than the table's last digit name no nearest one (pure Mode I)
NAMES = kinkbench.CRITERION_NAMES


def _group_key(g):
    """the Gaussian's groups first, pure Mode II along the rows before the other mixes"""
    return (g[0] != KERNEL, g[0], -g[1], g[2])


def sequences(rows):
    """Each sequence in m at one R/delta (10 or larger, two values of m or more), per kernel,
    mode mix (psi, alpha) and distance: a dict with the m values and angles, the criterion the
    finest lies nearest (None where the three agree within AGREE_DEG: pure Mode I), the finest's
    offset from it and its error bar (resolution_deg), the last refinement's step and both error
    bars; settled when the step is within SETTLED_DEG, beyond_bars when it exceeds the two bars."""
    out = []
    for g in sorted({(r["kernel"],) + mix_of(r) for r in rows}, key=_group_key):
        group = [r for r in rows if (r["kernel"],) + mix_of(r) == g]
        for dist in HORIZONS:
            key = f"angle_{dist}"
            for rd in sorted({r["R_over_delta"] for r in group if r["R_over_delta"] >= 10.0}):
                seq = sorted((r for r in group if r["R_over_delta"] == rd and r[key] is not None),
                             key=lambda r: r["m"])
                if len(seq) < 2:
                    continue
                prev, last = seq[-2], seq[-1]
                near = min(NAMES, key=lambda c: abs(last[key] - last[c]))
                agree = max(last[c] for c in NAMES) - min(last[c] for c in NAMES) <= AGREE_DEG
                bars = (resolution_deg(prev["m"], dist), resolution_deg(last["m"], dist))
                step = last[key] - prev[key]
                out.append(dict(kernel=g[0], psi=g[1], alpha=g[2], dist=dist, rd=rd,
                                ms=[r["m"] for r in seq], angles=[r[key] for r in seq],
                                nearest=None if agree else near, offset=last[key] - last[near],
                                bar=bars[1], within_bar=abs(last[key] - last[near]) <= bars[1],
                                step=step, bars=bars, settled=abs(step) <= SETTLED_DEG,
                                beyond_bars=abs(step) > sum(bars)))
    return out


def disk_moves(rows):
    """Doubling the disk (R/delta 10 -> 20) at one m: the change of angle, per kernel, mode mix,
    distance and m run at both sizes."""
    out = []
    for g in sorted({(r["kernel"],) + mix_of(r) for r in rows}, key=_group_key):
        for dist in HORIZONS:
            key = f"angle_{dist}"
            at = {rd: {r["m"]: r[key] for r in rows if (r["kernel"],) + mix_of(r) == g
                       and r["R_over_delta"] == rd and r[key] is not None} for rd in (10.0, 20.0)}
            out += [dict(kernel=g[0], psi=g[1], alpha=g[2], dist=dist, m=m,
                         move=at[20.0][m] - at[10.0][m]) for m in sorted(at[10.0]) if m in at[20.0]]
    return out


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


def sweep_stats(rows):
    """Per (kernel, m, R/delta) that has run the whole mixed-mode sweep, at each distance, the
    kink test's numbers (bbpd.benchmarks.kink.verdict: RMS and mean deviation from each criterion
    with its standard error, the nearest by RMS, the grid's pull), the criteria the
    two-standard-error test admits, and 'unresolved': those it excludes by a mean deviation no
    larger than one angle's error bar (the standard error falls with the number of runs, the
    grid's resolution does not)."""
    out = []
    for (kernel, m, rd), as_kink in _whole_sweeps(rows).items():
        for dist in HORIZONS:
            v = kinkbench.verdict(as_kink, dist, dx=m)
            ok = kinkbench.admitted(v)
            bar = resolution_deg(m, dist)
            out.append(dict(kernel=kernel, m=m, rd=rd, dist=dist, n=v["n"], rms=v["rms"],
                            bias=v["bias"], se=v["se"], best=v["best"], admitted=ok, bar=bar,
                            unresolved=[c for c in NAMES if c not in ok and abs(v["bias"][c]) <= bar],
                            pull_mean=v["pull_mean"], pull_max=v["pull_max"]))
    return out


def _nearest(v, dist):
    """the criteria whose RMS in verdict v (of m = v['m']) lies within the grid's resolution of
    the smallest: those the sweep cannot tell apart"""
    least = min(v["rms"].values())
    return [c for c in NAMES if v["rms"][c] - least <= resolution_deg(v["m"], dist)]


def _between(v):
    """(the criterion nearest the mean of verdict v among those it kinks beyond, the nearest
    among those it falls short of), or None when it lies beyond (or short of) every one; the
    sign is kinkbench.consistency's: a positive mean deviation kinks less"""
    more = [c for c in NAMES if v["bias"][c] < 0.0]
    less = [c for c in NAMES if v["bias"][c] >= 0.0]
    if not (more and less):
        return None
    return tuple(min(side, key=lambda c: abs(v["bias"][c])) for side in (more, less))


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
                            near_prev=near_prev, step=step, drifts=_drifts(step),
                            between=_between(last),
                            nearest_mean=min(NAMES, key=lambda c: abs(last["bias"][c])),
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


def limit(rows, kernel=KERNEL):
    """What the sweep in m says about the limit for `kernel`, in the largest disk (R/delta) with
    two complete sweeps: {'kernel', 'rd', 'ms', 'at': {dist: its entry of limits()}, 'follows':
    the criterion every distance approaches, or None}; None without two complete sweeps."""
    mine = [t for t in limits(rows) if t["kernel"] == kernel]
    if not mine:
        return None
    rd = max(t["rd"] for t in mine)
    at = {t["dist"]: t for t in mine if t["rd"] == rd}
    found = {t["limit"] for t in at.values()}
    follows = found.pop() if len(found) == 1 and None not in found else None
    return dict(kernel=kernel, rd=rd, ms=next(iter(at.values()))["ms"], at=at, follows=follows)


# The planned sweep, what the kink verdict needs: the whole mixed-mode sweep (both crack
# directions) in the disk R/delta = PLAN_R_OVER_DELTA, for the Gaussian kernel at m = 10, 15, 20
# and for the constant and triangular kernels at m = 15
PLAN = {"gaussian": (10, 15, 20), "constant": (15,), "triangular": (15,)}
PLAN_R_OVER_DELTA = 20


def coverage(rows):
    """What of PLAN has run: {(kernel, m): {'done': mixes run, 'left': mixes left, 'loops': the
    loop times (s) of the machine and rank count that timed most of them, 'machine'}}"""
    need = _sweep_need()
    out = {}
    for kernel, ms in PLAN.items():
        for m in ms:
            sel = [r for r in rows if (r["kernel"], r["m"], r["R_over_delta"])
                   == (kernel, m, PLAN_R_OVER_DELTA) and mix_of(r) in need]
            by = {}
            for r in sel:
                by.setdefault(f"{r['cpu']}, {r['nprocs']:g} ranks", []).append(r["loop_s"])
            machine, loops = max(sorted(by.items()), key=lambda kv: len(kv[1])) if by else (None, [])
            done = {mix_of(r) for r in sel}
            out[kernel, m] = dict(done=done, left=need - done, loops=loops, machine=machine)
    return out


def _mixes_at(rows, kernel, m, rd):
    """the mixed-mode (psi, alpha) pairs run for (kernel, m, R/delta)"""
    return {mix_of(r) for r in rows
            if (r["kernel"], r["m"], r["R_over_delta"]) == (kernel, m, rd) and mix_of(r)[0] > 0.0}


def _rms_from_criteria(sel, key, m):
    """{'m': m, 'rms': {criterion: RMS of (angle `key` - criterion) over the rows sel}}: what
    _nearest reads"""
    return {"m": m, "rms": {c: kinkbench.rms([r[key] - r[c] for r in sel]) for c in NAMES}}


# a comparison over the mode mix needs more than one mix: pure Mode II alone is in sequences()
KERNEL_COMPARISON_MIN_MIXES = 2


def kernel_spread(rows):
    """Per (m, R/delta) run by more than one kernel, over the mixed-mode mixes every such kernel
    ran (at least KERNEL_COMPARISON_MIN_MIXES), at each distance: each kernel's RMS from each
    criterion ('rms': {kernel: {criterion: RMS}}) and nearest ('nearest': {kernel: criteria}),
    the spread of the kernels' angles per mix (mean, max, the widest mix), the error bar, whether
    the widest spread lies within the two runs' bars, and the criteria nearest for every kernel
    ('common': empty when the kernel changes the nearest criterion)."""
    out = []
    for m, rd in sorted({(r["m"], r["R_over_delta"]) for r in rows}, key=lambda g: (g[1], g[0])):
        kernels = sorted({r["kernel"] for r in rows if (r["m"], r["R_over_delta"]) == (m, rd)
                          and mix_of(r)[0] > 0.0}, key=lambda k: (k != KERNEL, k))
        if len(kernels) < 2:
            continue
        mixes = set.intersection(*(_mixes_at(rows, k, m, rd) for k in kernels))
        runs = {(r["kernel"], mix_of(r)): r for r in rows
                if (r["m"], r["R_over_delta"]) == (m, rd) and r["kernel"] in kernels and mix_of(r) in mixes}
        for dist in HORIZONS:
            key = f"angle_{dist}"
            measured = sorted(x for x in mixes if all(runs[k, x][key] is not None for k in kernels))
            if len(measured) < KERNEL_COMPARISON_MIN_MIXES:
                continue
            per_k = {k: _rms_from_criteria([runs[k, x] for x in measured], key, m) for k in kernels}
            nearest = {k: _nearest(v, dist) for k, v in per_k.items()}
            spread = {x: max(runs[k, x][key] for k in kernels) - min(runs[k, x][key] for k in kernels)
                      for x in measured}
            widest = max(spread, key=spread.get)
            bar = resolution_deg(m, dist)
            out.append(dict(m=m, rd=rd, dist=dist, kernels=kernels, mixes=measured,
                            rms={k: v["rms"] for k, v in per_k.items()}, nearest=nearest,
                            spread_mean=sum(spread.values()) / len(spread),
                            spread_max=spread[widest], widest=widest, bar=bar,
                            within_bars=spread[widest] <= 2.0 * bar,
                            common=[c for c in NAMES if all(c in nearest[k] for k in kernels)]))
    return out
