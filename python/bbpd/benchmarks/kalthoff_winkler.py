# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler impact benchmark (Bouaraquia & Mabssout 2026, sec. 4.2.3): runs
examples/kalthoff-winkler/in.kalthoff_winkler and measures from its outputs the initiation, the
crack path, its angle and speed, the cracks' mirror symmetry and the damage far from them
(examples/kalthoff-winkler/README.md defines each and has the commands).
"""

import json
import math
import re
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

from bbpd import readers, snapshots
from bbpd.crack_path import clusters
from bbpd.kernels import KERNELS
from bbpd.runner import run_noted
from bbpd.markdown import cell as fmt
from bbpd.markdown import columns
from bbpd import plots
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "kalthoff-winkler" / "in.kalthoff_winkler"

# paper sec. 4.2.3: crack initiation times (us) and the experiment's crack angle
PAPER_INITIATION_US = {"constant": 20.0, "triangular": 20.8, "gaussian": 21.7}
EXPERIMENT_ANGLE_DEG = 70.0

# damage of an atom next to a long straight cut is ~0.44 with m = 5 (half a spacing from the
# cut), ~0.31 one row farther: 0.35 keeps the two rows that flank a crack
PHI_CRACK = 0.35
LINK = 1.5            # neighbour links in the crack graph, in grid spacings (8-neighbourhood)
FIT_RANGE = (10.0e-3, 50.0e-3)   # crack length range for the angle and speed fits (m):
                                 # beyond the tip's horizon at dx <= 2 mm, before the edge
                                 # (a 70-degree crack meets y = 0 at a length of ~80 mm)
# the loading study's measures (README, "Loading study")
T_EVAL_US = 70.0                    # paper Fig. 14
INITIAL_RANGE = (3.0e-3, 15.0e-3)   # m from the notch tip: past the tip's horizon (5 mm at 1 mm)
SPEED_WINDOW_US = 5.0
ANGLE_DEFS = ("initial", "fit", "chord")
ARREST_GROWTH_DX, ARREST_US = 2.0, 10.0   # a crack that grows < 2 dx in the last 10 us stopped

E, NU, RHO = 190.0e9, 0.25, 7800.0        # paper sec. 4.2.3 (kalthoff_winkler_steel.bbpd)
MU = E / (2.0 * (1.0 + NU))
C_S = math.sqrt(MU / RHO)                 # shear wave speed
C_P = math.sqrt(3.0 * MU / RHO)           # plane-strain P wave, nu = 1/4 (lambda = mu)
# Rayleigh speed for nu = 1/4: root of the Rayleigh equation, c_R / c_s = sqrt(2 - 2/sqrt(3))
C_R = C_S * math.sqrt(2.0 - 2.0 / math.sqrt(3.0))


# --------------------------------------------------------------------------- reading outputs

def read_log(path):
    """Run parameters printed by the input script and the pair style."""
    text = Path(path).read_text()
    m = re.search(r"^KW: kernel (\S+) dx (\S+) delta (\S+) dt (\S+) steps (\d+) plate (\S+) (\S+) "
                  r"notch lines y = (\S+) (\S+) tip x = (\S+)", text, re.M)
    if not m:
        raise RuntimeError(f"{path}: no 'KW:' line; was it written by in.kalthoff_winkler?")
    info = dict(kernel=m[1], dx=float(m[2]), delta=float(m[3]), dt=float(m[4]), nsteps=int(m[5]),
                Lx=float(m[6]), Ly=float(m[7]), ylo=float(m[8]), yhi=float(m[9]), a=float(m[10]))
    info.update(readers.pair_setup(text))    # s0, the time step's bound and its fraction
    info["loop_s"], info["nprocs"] = readers.loop_time(text)
    # in 3D the atoms inside the experiment's slot are deleted once dx is below its width:
    # the notch's flank atoms then lie up to slot/2 + dx from the notch line, not dx
    m3 = re.search(r"^KW 3d: thickness \S+ middle layer z = \S+ slot (\S+)", text, re.M)
    deleted = re.search(r"^Deleted (\d+) atoms", text, re.M)
    info["flank"] = info["dx"]
    if m3 and deleted and int(deleted[1]) > 0:
        info["flank"] = 0.5 * float(m3[1]) + info["dx"]
    m = re.search(r"^KW loading: v0 (\S+) tramp (\S+) thold (\S+) layer (\S+)", text, re.M)
    if m:
        info.update(v0=float(m[1]), tramp=float(m[2]), thold=float(m[3]), layer=float(m[4]))
    return info


# --------------------------------------------------------------------------- measurements

def first_rise(steps, series, rel=1e-9):
    """First step at which series exceeds its first value (a bond broke), or None."""
    above = np.nonzero(series > series[0] * (1.0 + rel) + rel)[0]
    return int(steps[above[0]]) if len(above) else None


def notch_cracks(x, y, phi, g):
    """Crack atoms of each notch: {'lo'/'hi': boolean mask of the outer-side crack ahead of the
    tip, linked to the notch flanks}, and the mask of the notch flank atoms themselves."""
    crack = phi >= PHI_CRACK
    idx = np.nonzero(crack)[0]
    labels = clusters(np.column_stack([x[idx], y[idx]]), LINK * g["dx"])
    out = {}
    for side, yn, outer in (("lo", g["ylo"], y < g["ylo"]), ("hi", g["yhi"], y > g["yhi"])):
        # flank seeds: crack atoms within dx of the notch line (flank: see read_log), up to its tip (on a rotated
        # grid the band along the cut can have gaps wider than LINK far from the tip)
        band = g.get("flank", g["dx"])
        flank = crack & (x <= g["a"]) & (np.abs(y - yn) < band)
        if band > g["dx"]:
            # the slot's faces keep their bonds through the thickness (damage below PHI_CRACK
            # on the mid-plane): the crack is seeded at the slot's round tip as well
            flank |= crack & (np.hypot(x - g["a"], y - yn) < band)
        seeds = set(labels[np.isin(idx, np.nonzero(flank)[0])])
        linked = np.zeros_like(crack)
        linked[idx[np.isin(labels, list(seeds))]] = True
        out[side] = linked & outer & (x > g["a"])
        out[side + "_flank"] = linked & (x <= g["a"]) & (np.abs(y - yn) < band + g["dx"])
    return out


def tip_of(x, y, mask, tip, dx):
    """Crack atom farthest from the notch tip, and that distance (0 if there is none).
    Ties (grid atoms at equal distance) go to the largest x, which mirrors about y = Ly/2."""
    if not mask.any():
        return tip, 0.0
    xm, ym = x[mask], y[mask]
    r = np.hypot(xm - tip[0], ym - tip[1])
    near = np.nonzero(r >= r.max() - 1e-6 * dx)[0]
    k = near[np.argmax(xm[near])]
    return (xm[k], ym[k]), float(r[k])


def crack_angle(x, y, mask, tip, outer_sign, fit_range=FIT_RANGE):
    """Angle (deg) of the crack's principal axis from +x towards the outer side, fitted over
    the crack atoms whose distance from the notch tip lies in fit_range; None if < 3 atoms."""
    r = np.hypot(x - tip[0], y - tip[1])
    sel = mask & (r >= fit_range[0]) & (r <= fit_range[1])
    if sel.sum() < 3:
        return None
    p = np.column_stack([x[sel], outer_sign * (y[sel] - tip[1])])
    p = p - p.mean(axis=0)
    axis = np.linalg.svd(p, full_matrices=False)[2][0]
    if axis[0] < 0:
        axis = -axis
    return math.degrees(math.atan2(axis[1], axis[0]))


def crack_speed(times, lengths, fit_range=FIT_RANGE):
    """Mean crack speed (m/s): least-squares slope of length against time in fit_range."""
    t = np.asarray(times)
    L = np.asarray(lengths)
    sel = (L >= fit_range[0]) & (L <= fit_range[1])
    if sel.sum() < 2:
        return None
    return float(np.polyfit(t[sel], L[sel], 1)[0])


def far_damage(x, y, phi, phi0, cracks, g):
    """Clusters of atoms whose damage grew (phi > phi0) farther than delta + dx from the notch
    flanks and the two cracks (masks from notch_cracks); far_edge marks those reaching
    x > Lx - delta."""
    dx, delta = g["dx"], g["delta"]
    path = cracks["lo"] | cracks["hi"] | cracks["lo_flank"] | cracks["hi_flank"]
    dist = np.full(len(x), np.inf)
    if path.any():
        dist = cKDTree(np.column_stack([x[path], y[path]])).query(np.column_stack([x, y]))[0]
    far = (phi > phi0 + 1e-12) & (dist > delta + dx)
    out = []
    if far.any():
        pts = np.column_stack([x[far], y[far]])
        lab = clusters(pts, LINK * dx)
        for c in np.unique(lab):
            p = pts[lab == c] * 1e3
            out.append(dict(
                atoms=int(len(p)), x_mm=[float(p[:, 0].min()), float(p[:, 0].max())],
                y_mm=[float(p[:, 1].min()), float(p[:, 1].max())],
                far_edge=bool(p[:, 0].max() > (g["Lx"] - delta) * 1e3),
                max_phi=float(phi[far][lab == c].max())))
    return out


def mirror_damage_difference(x, y, phi, dx, Ly):
    """Largest damage difference between mirror atoms about y = Ly/2, or None if the grid has
    no mirror image of every atom (a perturbed or rotated grid: -var grid)."""
    def key(a, b):
        return round(a / dx * 2), round(b / dx * 2)
    mirror = {key(a, b): p for a, b, p in zip(x, y, phi)}
    pos = {key(a, b): (a, b) for a, b in zip(x, y)}
    pairs = [(key(a, Ly - b), p) for a, b, p in zip(x, y, phi)]
    exact = len(mirror) == len(x) and all(
        k in pos and abs(pos[k][0] - a) + abs(pos[k][1] - (Ly - b)) < 1e-6 * dx
        for (k, _), a, b in zip(pairs, x, y))
    return float(max(abs(p - mirror[k]) for k, p in pairs)) if exact else None


def chord_angle(tip, crack_tip, outer_sign):
    """Angle (deg) of the line from the notch tip to the crack tip, from +x to the outer side."""
    dx_, dy_ = crack_tip[0] - tip[0], outer_sign * (crack_tip[1] - tip[1])
    if dx_ == 0.0 and dy_ == 0.0:
        return None
    return math.degrees(math.atan2(dy_, dx_))


def angles_of(x, y, phi, g):
    """The three angles (ANGLE_DEFS) and the crack tip of both cracks in one damage field."""
    cr = notch_cracks(x, y, phi, g)
    out = {}
    for side, yn, sign in (("lo", g["ylo"], -1.0), ("hi", g["yhi"], 1.0)):
        tip = (g["a"], yn)
        ctip, length = tip_of(x, y, cr[side], tip, g["dx"])
        out[side] = {
            "initial": crack_angle(x, y, cr[side], tip, sign, fit_range=INITIAL_RANGE),
            "fit": crack_angle(x, y, cr[side], tip, sign),
            "chord": chord_angle(tip, ctip, sign) if length > 0 else None,
            "tip": [float(ctip[0]), float(ctip[1])], "length_mm": length * 1e3}
    return out


def mean_or_none(vals):
    vals = [v for v in vals if v is not None]
    return float(np.mean(vals)) if vals else None


def peak_speed(t_us, lengths, window_us=SPEED_WINDOW_US):
    """Largest mean speed (m/s) of the crack tip over any window of window_us."""
    t, L = np.asarray(t_us), np.asarray(lengths)
    best = None
    for i in range(len(t)):
        j = np.searchsorted(t, t[i] + window_us - 1e-9)
        if j >= len(t):
            break
        if L[i] <= 0.0:
            continue
        v = (L[j] - L[i]) / ((t[j] - t[i]) * 1e-6)
        best = v if best is None else max(best, v)
    return best


def analyse(workdir):
    """All measurements of one run directory (the files the input script writes): the
    benchmark's and the loading study's (README, "Loading study")."""
    workdir = Path(workdir)
    g = read_log(workdir / "log.lammps")
    dt, dx, delta = g["dt"], g["dx"], g["delta"]
    tips = {"lo": (g["a"], g["ylo"]), "hi": (g["a"], g["yhi"])}
    res = dict(g)

    # initiation from the per-step monitor
    steps, dlo, dhi, dall, qlo, qhi = readers.tips(workdir / "tips.dat")
    for side, series, quad in (("lo", dlo, qlo), ("hi", dhi, qhi)):
        s = first_rise(steps, series)
        res[f"t_init_{side}_us"] = None if s is None else s * dt * 1e6
        band = np.nonzero(quad >= PHI_CRACK)[0]
        res[f"t_band_{side}_us"] = float(steps[band[0]] * dt * 1e6) if len(band) else None
    s_any = first_rise(steps, dall)
    res["t_first_break_us"] = None if s_any is None else s_any * dt * 1e6
    for kind in ("init", "band"):    # the earlier tip's
        res[f"t_{kind}_us"] = min((t for s in ("lo", "hi") if (t := res[f"t_{kind}_{s}_us"]) is not None),
                                  default=None)
    res["first_break_at_tip"] = (None not in (res["t_first_break_us"], res["t_init_us"])
                                 and abs(res["t_init_us"] - res["t_first_break_us"]) < 0.5 * dt * 1e6)

    # crack-tip trajectories from the damage snapshots, and the far-edge crack: new damage at
    # x > Lx - delta (t_far_edge_us), and the first that lies farther than delta + dx from the
    # notch cracks (far_edge_own_us: a notch crack that runs into the far edge is not one)
    traj = {"t_us": [], "lo": [], "hi": [], "L_lo": [], "L_hi": []}
    sym = 0.0
    res["t_far_edge_us"] = res["far_edge_own_us"] = res["far_edge_y_mm"] = None
    snaps = readers.dump_snapshots(workdir / "damage.dump")
    initial = {int(i): p for i, p in zip(snaps[0][1]["id"], snaps[0][1]["c_dmg"])}
    for step, s in snaps:
        x, y, phi = s["f_ref[1]"], s["f_ref[2]"], s["c_dmg"]
        t = step * dt * 1e6
        cr = notch_cracks(x, y, phi, g)
        if res["far_edge_own_us"] is None:
            grew = phi > np.array([initial.get(int(i), 0.0) for i in s["id"]]) + 1e-12
            edge = np.nonzero(grew & (x > g["Lx"] - delta))[0]
            if len(edge) and res["t_far_edge_us"] is None:
                res["t_far_edge_us"] = t
            path = cr["lo"] | cr["hi"]
            if len(edge) and path.any():
                dist = cKDTree(np.column_stack([x[path], y[path]])).query(
                    np.column_stack([x[edge], y[edge]]))[0]
                edge = edge[dist > delta + dx]
            if len(edge):
                res["far_edge_own_us"] = t
                off = np.abs(y[edge] - 0.5 * g["Ly"]) * 1e3    # distance from the mid-line
                res["far_edge_y_mm"] = [float(off.min()), float(off.max())]
        traj["t_us"].append(t)
        for side in ("lo", "hi"):
            p, L = tip_of(x, y, cr[side], tips[side], dx)
            traj[side].append([float(p[0]), float(p[1])])
            traj["L_" + side].append(L)
        plo, phi_ = traj["lo"][-1], traj["hi"][-1]
        sym = max(sym, math.hypot(plo[0] - phi_[0], plo[1] - (g["Ly"] - phi_[1])))
    res["trajectory"] = traj
    res["symmetry_tip_mm"] = sym * 1e3
    t = np.array(traj["t_us"]) * 1e-6
    for side in ("lo", "hi"):
        L = np.array(traj["L_" + side])
        res[f"speed_{side}"] = crack_speed(t, L)
        res[f"length_{side}_mm"] = float(L[-1] * 1e3)

    # the end state: angle, mirror mismatch, damage far from the cracks
    final = readers.dump_snapshots(workdir / "final.dump")
    (_, s0), (_, s1) = final[0], final[-1]
    x, y, phi = s1["f_ref[1]"], s1["f_ref[2]"], s1["c_dmg"]
    cr = notch_cracks(x, y, phi, g)
    for side, sign in (("lo", -1.0), ("hi", 1.0)):
        res[f"angle_{side}_deg"] = crack_angle(x, y, cr[side], tips[side], sign)
        res[f"crack_{side}"] = np.column_stack([x[cr[side]], y[cr[side]]]).tolist()
    res["damage_map"] = {"x": x.tolist(), "y": y.tolist(), "phi": phi.tolist()}
    res["symmetry_phi"] = mirror_damage_difference(x, y, phi, dx, g["Ly"])
    for key in ("angle_{}_deg", "speed_{}"):
        res[key.replace("_{}", "")] = mean_or_none([res[key.format(s)] for s in ("lo", "hi")])
    far_clusters = far_damage(x, y, phi, s0["c_dmg"], cr, g)
    res["far_damage"] = far_clusters
    res["far_damage_other"] = sum(c["atoms"] for c in far_clusters if not c["far_edge"])
    res["far_edge_crack"] = any(c["far_edge"] for c in far_clusters)
    res.update(study_measures(snaps, traj, g))
    for key in ("speed", "speed_peak"):
        res[key + "_over_cR"] = None if res[key] is None else res[key] / C_R
    return res


def study_measures(snaps, traj, g):
    """The loading study's measures of the damage snapshots and the tip trajectories: the
    angles at T_EVAL_US and at the end, the initial angle, how the crack stops, its speeds."""
    res = {}
    times = [step * g["dt"] * 1e6 for step, _ in snaps]
    # the snapshot at T_EVAL_US: the last one at or before it (snapshots are ~1 us apart)
    k70 = max([i for i, t in enumerate(times) if t <= T_EVAL_US + 1e-6], default=None)
    for name, k in (("t70", k70), ("end", len(snaps) - 1)):
        if k is None:
            continue
        s = snaps[k][1]
        ang = angles_of(s["f_ref[1]"], s["f_ref[2]"], s["c_dmg"], g)
        res[f"angles_{name}"] = ang
        res[f"t_{name}_us"] = times[k]
        for d in ANGLE_DEFS:
            res[f"{d}_{name}_deg"] = mean_or_none([ang[sd][d] for sd in ("lo", "hi")])
        res[f"length_{name}_mm"] = mean_or_none([ang[sd]["length_mm"] for sd in ("lo", "hi")])

    # the initial angle on the first snapshot in which the crack reaches past INITIAL_RANGE
    # (later damage, e.g. the far-edge crack joining the path, cannot change it)
    initial = {}
    for side in ("lo", "hi"):
        past = np.nonzero(np.array(traj["L_" + side]) >= INITIAL_RANGE[1])[0]
        k = int(past[0]) if len(past) else len(snaps) - 1
        s = snaps[k][1]
        initial[side] = angles_of(s["f_ref[1]"], s["f_ref[2]"], s["c_dmg"], g)[side]["initial"]
    res["initial_deg"] = mean_or_none(list(initial.values()))
    res["initial_side_deg"] = initial      # each crack's own: they differ off the square grid

    # when a crack tip first comes within delta of the plate boundary
    res["t_edge_us"] = None
    for t, plo, phi_ in zip(traj["t_us"], traj["lo"], traj["hi"]):
        if any(min(p[0], g["Lx"] - p[0], p[1], g["Ly"] - p[1]) < g["delta"] for p in (plo, phi_)):
            res["t_edge_us"] = t
            break
    Ls = 0.5 * (np.array(traj["L_lo"]) + np.array(traj["L_hi"]))
    # arrest: the crack grew by less than ARREST_GROWTH over the last ARREST_US of the run
    t_all = np.array(traj["t_us"])
    near_end = np.nonzero((Ls >= Ls[-1] - ARREST_GROWTH_DX * g["dx"]) & (Ls > 0))[0]
    t_stop = float(t_all[near_end[0]]) if len(near_end) else float(t_all[-1])
    res["t_arrest_us"] = (t_stop if res["t_edge_us"] is None and Ls[-1] > 0
                          and t_all[-1] - t_stop >= ARREST_US else None)
    res["length_end_mm"] = float(Ls[-1] * 1e3)
    res["speed_peak"] = peak_speed(traj["t_us"], Ls)
    return res


# --------------------------------------------------------------------------- running

def variables(kernel, dx, **extra):
    """The input script's -var arguments: floats written exactly, other values as they are,
    None left out"""
    return {k: repr(float(v)) if isinstance(v, float) else str(v)
            for k, v in dict(kernel=kernel, dx=float(dx), **extra).items() if v is not None}


def run(kernel, dx, workdir, nprocs=2, tend=None, reuse=False, images=False):
    """Run the example in workdir; return analyse(workdir) with the run's wall time (s).
    reuse: analyse the outputs of an earlier finished run in workdir instead of running.
    images: the input's damage pictures as well, listed as snapshots [(t in us, path)]."""
    workdir = Path(workdir)
    note = run_noted(EXAMPLE, workdir, variables(kernel, dx, images="yes" if images else "no",
                                                 tend=tend), {"kernel": kernel, "dx": dx}, nprocs, reuse)
    res = analyse(workdir)
    res["wall_s"] = note["wall_s"]
    if images:
        res["snapshots"] = [(step * res["dt"] * 1e6, str(path))
                            for step, path in snapshots.find(workdir)]
    (workdir / "results.json").write_text(json.dumps(res))
    return res


# --------------------------------------------------------------------------- figures

def damage_panel(ax, res, size):
    """The damage at the end of a run on its reference configuration, a square of `size`
    (points^2 at dx = 1 mm) per atom; returns the scatter (for a colour bar)."""
    m = res["damage_map"]
    sc = ax.scatter(np.array(m["x"]) * 1e3, np.array(m["y"]) * 1e3, c=m["phi"], marker="s",
                    s=size * (res["dx"] / 1e-3) ** 2, linewidths=0, cmap="jet", vmin=0.0,
                    vmax=0.6, rasterized=True)
    ax.set_aspect("equal")
    return sc


def plot_damage_map(res, path):
    """Damage at the end of the run on the reference configuration (paper Fig. 14)."""
    with plots.figure(path, figsize=(3.6, 6.0)) as (fig, ax):
        fig.colorbar(damage_panel(ax, res, 4.0), ax=ax, label="damage")
        ax.set(xlabel="x (mm)", ylabel="y (mm)")
        ax.set_title(f"{res['kernel']}, dx = {res['dx'] * 1e3:g} mm, "
                     f"t = {res['nsteps'] * res['dt'] * 1e6:.0f} us", fontsize=9)
    return path


def plot_paths(runs, path, title, fontsize=7):
    """Crack-tip paths of runs [(label, result, line style, colour or None)] in the plate with
    its notches and the experiment's 70 deg lines (paper Fig. 15)."""
    with plots.figure(path, figsize=(3.8, 6.0)) as (fig, ax):
        g = runs[0][1]
        ax.plot([0, g["Lx"] * 1e3, g["Lx"] * 1e3, 0, 0], [0, 0, g["Ly"] * 1e3, g["Ly"] * 1e3, 0],
                color="black", linewidth=0.8)
        for label, r, style, color in runs:
            for side, y0 in (("lo", r["ylo"]), ("hi", r["yhi"])):
                ax.plot([0, r["a"] * 1e3], [y0 * 1e3] * 2, color="grey", linewidth=2)
                L = np.array(r["trajectory"]["L_" + side])
                p = np.vstack([[r["a"], y0], np.array(r["trajectory"][side])[L > 0]]) * 1e3
                color = ax.plot(p[:, 0], p[:, 1], style, color=color, linewidth=1.2,
                                label=label if side == "lo" else None)[0].get_color()
        ang = math.radians(EXPERIMENT_ANGLE_DEG)
        for y0, sign in ((g["ylo"], -1), (g["yhi"], 1)):
            length = y0 / math.sin(ang) if sign < 0 else (g["Ly"] - y0) / math.sin(ang)
            ax.plot([g["a"] * 1e3, (g["a"] + length * math.cos(ang)) * 1e3],
                    [y0 * 1e3, (y0 + sign * length * math.sin(ang)) * 1e3], "k--", linewidth=1.0,
                    label="70 deg (experiment)" if sign < 0 else None)
        ax.set(aspect="equal", xlim=(-5, g["Lx"] * 1e3 + 5), ylim=(-5, g["Ly"] * 1e3 + 5),
               xlabel="x (mm)", ylabel="y (mm)")
        ax.legend(fontsize=fontsize - 1, loc="center left")
        ax.set_title(title, fontsize=fontsize + 1)
    return path


def figures(results, folder):
    """The crack growing (the dump images of the runs that drew them, in a row), the damage map
    of every run, the kernels' crack paths at each dx and each kernel's over its dx; returns
    the paths written."""
    folder = Path(folder)
    out = []
    for r in sorted(results, key=lambda r: (-r["dx"], KERNELS.index(r["kernel"]))):
        tag = f"{r['kernel']}_dx{r['dx'] * 1e3:g}mm"
        if r.get("snapshots"):
            out.append(snapshots.draw_strip(
                [(f"t = {t:.1f} us", p) for t, p in r["snapshots"]], folder / f"growth_{tag}.png",
                f"Kalthoff-Winkler, {r['kernel']}, dx = {r['dx'] * 1e3:g} mm: damage from 0 "
                "(blue) to 1 (red), LAMMPS dump image"))
        out.append(plot_damage_map(r, folder / f"damage_{tag}.png"))
    for dx in sorted({r["dx"] for r in results}, reverse=True):
        same = [r for r in results if r["dx"] == dx]
        if len(same) > 1:
            out.append(plot_runs(same, folder / f"paths_dx{dx * 1e3:g}mm.png"))
    for kernel in KERNELS:
        same = sorted((r for r in results if r["kernel"] == kernel), key=lambda r: -r["dx"])
        if len(same) > 1:
            out.append(plot_runs(same, folder / f"paths_{kernel}_convergence.png"))
    return out


def plot_runs(results, path):
    """plot_paths of the kernels at one dx, or of one kernel's grids"""
    by_dx = len({r["dx"] for r in results}) > 1
    g = results[0]
    return plot_paths([((f"dx = {r['dx'] * 1e3:g} mm" if by_dx else r["kernel"])
                        + f" ({r['angle_deg']:.1f} deg)", r, "-", None) for r in results], path,
                      f"crack-tip paths, {g['kernel']}" if by_dx
                      else f"crack-tip paths, dx = {g['dx'] * 1e3:g} mm", fontsize=8)


# --------------------------------------------------------------------------- table

def row(res):
    """The CSV row of one run (examples/kalthoff-winkler/results/kalthoff_winkler.csv)."""
    return {"kernel": res["kernel"], "dx_m": res["dx"], "atoms": len(res["damage_map"]["x"]),
            "first_bond_us": res["t_init_us"], "damage_band_us": res["t_band_us"],
            "angle_deg": res["angle_deg"], "speed_m_s": res["speed"],
            "symmetry_tip_mm": res["symmetry_tip_mm"],
            "far_edge_crack_us": res["t_far_edge_us"] if res["far_edge_crack"] else None,
            "far_damage_other_atoms": res.get("far_damage_other"), "run_time_s": res["wall_s"]}


def table(rows):
    """Markdown table of row()s: kernel x resolution, the paper's values beside ours."""
    return columns(sorted(rows, key=lambda r: (KERNELS.index(r["kernel"]), -r["dx_m"])), (
        ("kernel", "kernel"), ("dx (mm)", lambda r: f"{r['dx_m'] * 1e3:g}"), ("atoms", "atoms", ".0f"),
        ("first bond (us)", "first_bond_us", ".1f"), ("damage band (us)", "damage_band_us", ".1f"),
        ("paper (us)", lambda r: f"{PAPER_INITIATION_US[r['kernel']]:.1f}"),
        ("angle (deg)", "angle_deg", ".1f"), ("exp. (deg)", lambda r: f"{EXPERIMENT_ANGLE_DEG:.0f}"),
        ("speed (m/s)", "speed_m_s", ".0f"), ("tip mirror mismatch (mm)", "symmetry_tip_mm", ".1e"),
        ("far-edge crack from (us)", lambda r: "none" if r["far_edge_crack_us"] is None
         else f"{r['far_edge_crack_us']:.0f}"),
        ("other far damage (atoms)", "far_damage_other_atoms", ".0f"),
        ("run time (s)", "run_time_s", ".1f")))


def main(argv=None):
    args = cli.parser(__doc__, "/tmp/kalthoff-winkler", nprocs=2, kernels=KERNELS,
                      dx=[2e-3, 1e-3], figures="write the PNGs here (default: --work)",
                      reuse=True).parse_args(argv)
    work = Path(args.work)
    figs = Path(args.figures or work)
    figs.mkdir(parents=True, exist_ok=True)
    results = []
    for dx in args.dx:
        for kernel in args.kernels:
            res = run(kernel, dx, work / f"{kernel}-dx{dx * 1e3:g}mm", nprocs=args.nprocs,
                      reuse=args.reuse)
            results.append(res)
            print(f"{kernel} dx = {dx * 1e3:g} mm: initiation {fmt(res['t_init_us'], '.2f')} us, "
                  f"angle {fmt(res['angle_deg'], '.1f')} deg, speed {fmt(res['speed'], '.0f')} m/s, "
                  f"wall {res['wall_s']:.0f} s", flush=True)
    figures(results, figs)
    # the table covers every finished run in --work, also those of earlier invocations
    rows = [row(json.loads(p.read_text())) for p in sorted(work.glob("*/results.json"))]
    print(table(rows))
    (work / "table.md").write_text(table(rows) + "\n")


if __name__ == "__main__":
    main()
