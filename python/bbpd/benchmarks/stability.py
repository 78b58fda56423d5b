# SPDX-License-Identifier: GPL-2.0-or-later
"""Stable time step of the bbpd/* pair styles under fix nve (velocity Verlet): the bound the
pair style prints at setup (predicted), the lattice-dynamics limit of the periodic plate from
bbpd.reference (exact), the bisected largest stable step (measured) and the energy drift of a
free plate; doc/stability.md gives the reasons for each choice and the commands.
"""

import argparse
import json
import math
import re
import time
from pathlib import Path

import numpy as np

from bbpd import readers
from bbpd import reference as ref
from bbpd.kernels import KERNELS
from bbpd.markdown import table as md_table
from bbpd.runner import LammpsError, run_lammps

HORIZON_RATIOS = (1, 2, 3, 5, 10)    # m = delta/dx

DX = 1.0e-3              # m
THICKNESS = 1.0e-3       # m
YOUNGS = 190.0e9         # Pa, Kalthoff-Winkler steel (paper sec. 4.2.3)
DENSITY = 7800.0         # kg/m^3, same source
NOISE = 1.0              # m/s: amplitude of the random initial velocities
SEED = 20260704

STEPS = 10000            # energy growth over 10,000 steps
GROWTH = 10.0            # stable: max energy of the second half < GROWTH x that of the first
HALT = 1.0e6             # energy above HALT x the initial one: unstable, stop the run
RTOL = 1.0e-3            # bisection stops when (hi - lo)/lo < RTOL
BRACKET = (1.0, 4.0)     # initial r = dt/Y bracket; widened if it does not bracket

DRIFT_STEPS = 20000
DRIFT_RATIO = 0.5        # dt = 0.5 Y
DRIFT_SIDE = 12          # free plate of 12 x 12 atoms
DRIFT_M = 3


def plate_side(m):
    """Atoms per side of the periodic plate: even (so the zone-boundary wave k = pi/dx is one
    of its modes) and wider than two families (2 m + 1 dx), which a periodic family needs."""
    return 16 if m <= 5 else 24


# --------------------------------------------------------------------------- NumPy side

def predicted_bound(kernel, m, youngs=YOUNGS, density=DENSITY, dx=DX):
    """Y = sqrt(2 rho / sum_j b_j), b_j = c(xi_j) C_v V_j / xi_j over the full family of an
    interior atom (plane stress; nan if sum_j b_j <= 0)."""
    delta = m * dx
    r = np.linalg.norm(ref.grid_family(m, 2), axis=1) * dx    # the family the pair style builds
    b = (ref.micromodulus(kernel, "plane/stress", youngs, delta, THICKNESS)
         * ref.kernel(kernel)(r / delta) * ref.partial_volume(r, delta, dx) * dx * dx * THICKNESS / r)
    return math.sqrt(2.0 * density / b.sum()) if b.sum() > 0.0 else math.nan


def exact_limit(kernel, m, side, youngs=YOUNGS, density=DENSITY, dx=DX):
    """2/omega_max of a periodic side x side plate: the largest eigenvalue of the lattice's
    dynamic matrix (bbpd.reference.dynamic_matrix) over the plate's k grid."""
    k1 = 2.0 * math.pi * np.arange(side) / (side * dx)
    lam = max(np.linalg.eigvalsh(ref.dynamic_matrix(kernel, "plane/stress", youngs, m, dx,
                                                    (kx, ky, 0.0)))[-1] for kx in k1 for ky in k1)
    return 2.0 / math.sqrt(lam / density) if lam > 0.0 else math.nan


# --------------------------------------------------------------------------- LAMMPS side

def plate_setup(kernel, m, side, periodic=True, youngs=YOUNGS, density=DENSITY, seed=SEED,
                noise=NOISE, pair_style_extra=""):
    """Input lines for a side x side plane-stress plate at rest positions with random
    velocities (uniform in [-noise, noise] per component), elastic (Gc none)."""
    bound = "p p p" if periodic else "s s p"
    return f"""plugin load bbpdplugin.so
units si
dimension 2
boundary {bound}
atom_style peri
atom_modify map array
lattice sq {DX!r}
region box block -0.5 {side - 0.5} -0.5 {side - 0.5} -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {density!r}
set group all volume {DX * DX * THICKNESS!r}
pair_style bbpd/{kernel} plane/stress thickness {THICKNESS!r}{pair_style_extra}
pair_coeff * * {youngs!r} none {m * DX!r}
variable vx atom {noise!r}*random(-1,1,{seed})
variable vy atom {noise!r}*random(-1,1,{seed + 1})
velocity all set v_vx v_vy 0.0 units box
fix nve all nve
fix 2d all enforce2d
"""


def bound_run(kernel, ratio, steps, thermo=100, halt=HALT):
    """Input lines that take the printed bound Y from 'compute pair' (c_dtb[1]) after 'run 0',
    set dt = ratio x Y and run; the run stops early (fix halt) once the total energy exceeds
    halt x its initial value. Prints 'BOUND Y X' (X: eq. 25)."""
    return f"""compute dtb all pair bbpd/{kernel}
thermo_style custom step pe ke etotal
thermo_modify format float %.15g
run 0
print "BOUND $(c_dtb[1]:%.17g) $(c_dtb[2]:%.17g)"
variable dt equal {ratio!r}*c_dtb[1]
timestep ${{dt}}
variable e0 equal $(etotal:%.17g)
variable growth equal etotal/v_e0
fix stop all halt {thermo} v_growth > {halt!r} error continue
thermo {thermo}
run {steps}
"""


def plate_script(kernel, m, side, ratio, steps, periodic=True, thermo=100, halt=HALT, **kw):
    """A noisy plate (plate_setup) run at dt = ratio x the printed bound (bound_run)."""
    return plate_setup(kernel, m, side, periodic, **kw) + bound_run(kernel, ratio, steps, thermo,
                                                                    halt)


def printed_bound(output):
    """(Y, eq. 25 value) from the script's BOUND line."""
    for line in output.splitlines():
        if line.startswith("BOUND "):
            return tuple(float(v) for v in line.split()[1:3])
    raise ValueError("no BOUND line in the LAMMPS output")


# the ERROR lines the plugin prints when a run blows up (fix_bbpd_bonds.cpp, pair_bbpd.cpp);
# any other ERROR, or an exit without one (a crash), is not an instability
INSTABILITY_ERRORS = re.compile(r"the run is unstable|the run became unstable|"
                                r"either the run is unstable")


def is_instability_error(message):
    """True if a LammpsError message is the plugin's unstable-run ERROR."""
    return bool(message) and message.startswith("ERROR") and \
        INSTABILITY_ERRORS.search(message) is not None


def run_point(workdir, kernel, m, ratio, steps=STEPS, side=None, periodic=True, timeout=600,
              **kw):
    """Run one plate; returns dict(stable, growth, steps_done, bound, error); growth is the
    largest energy of the second half of the run over the largest of the first half."""
    side = side or plate_side(m)
    script = plate_script(kernel, m, side, ratio, steps, periodic, **kw)
    try:
        out = run_lammps(script, workdir, timeout=timeout).output
    except LammpsError as e:
        if not is_instability_error(e.message):
            raise    # a bad input or a crash is not a point of the stability map
        return {"stable": False, "growth": math.inf, "steps_done": None, "bound": None,
                "error": e.message}
    table = readers.thermo_tables(out)[-1]
    energy = table["TotEng"]
    done = int(table["Step"][-1] - table["Step"][0])
    half = table["Step"] - table["Step"][0] <= 0.5 * steps
    growth = float(np.max(energy[~half]) / np.max(energy[half])) if done == steps else math.inf
    stable = bool(np.all(np.isfinite(energy)) and growth < GROWTH)
    return {"stable": stable, "growth": growth, "steps_done": done,
            "bound": printed_bound(out)[0], "error": None}


def bisect(workdir, kernel, m, log=print):
    """Largest stable r = dt/Y, to RTOL; returns (lo, hi, Y printed, runs)."""
    points = []

    def stable(r):
        points.append(run_point(workdir, kernel, m, r))
        return points[-1]["stable"]
    lo, hi = BRACKET
    while not stable(lo):    # the bound itself unstable: a finding, keep going down
        if lo < 1.0e-3:
            raise RuntimeError(f"{kernel} m={m}: unstable down to {lo} Y: {points[-1]}")
        hi, lo = lo, lo / 2.0
    bound = points[-1]["bound"]
    while stable(hi):
        lo, hi = hi, 2.0 * hi
    while (hi - lo) / lo > RTOL:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if stable(mid) else (lo, mid)
    log(f"  {kernel:10s} m={m:2d}: stable up to {lo:.4f} Y, unstable at {hi:.4f} Y ({len(points)} runs)")
    return lo, hi, bound, len(points)


def stability_map(workdir, log=print):
    rows = []
    for kernel in KERNELS:
        for m in HORIZON_RATIOS:
            side = plate_side(m)
            t0 = time.time()
            if not math.isfinite(predicted_bound(kernel, m)):
                # no bond has positive stiffness (triangular m = 1: W(delta) = 0): no bound
                log(f"  {kernel:10s} m={m:2d}: degenerate, sum of bond stiffnesses <= 0")
                rows.append({"kernel": kernel, "m": m, "side": side, "degenerate": True})
                continue
            lo, hi, bound, runs = bisect(Path(workdir) / f"{kernel}-m{m}", kernel, m, log)
            exact = exact_limit(kernel, m, side)
            rows.append({"kernel": kernel, "m": m, "side": side,
                         "bound_printed": bound, "bound_numpy": predicted_bound(kernel, m),
                         "exact_limit": exact, "measured_lo": lo * bound,
                         "measured_hi": hi * bound, "runs": runs,
                         "seconds": time.time() - t0})
    return rows


# --------------------------------------------------------------------------- energy drift

def drift_script(kernel, steps=DRIFT_STEPS, ratio=DRIFT_RATIO, side=DRIFT_SIDE, m=DRIFT_M,
                 thermo=10):
    """Free noisy plate at dt = ratio Y, total energy every `thermo` steps."""
    return plate_script(kernel, m, side, ratio, steps, periodic=False, thermo=thermo)


def energy_drift(output):
    """(drift, fluctuation) of the total energy in the last thermo table: the least-squares
    linear trend over the whole run divided by the initial energy, and std/mean."""
    table = readers.thermo_tables(output)[-1]
    step, energy = table["Step"], table["TotEng"]
    slope = np.polyfit(step - step[0], energy / energy[0], 1)[0]
    return float(slope * (step[-1] - step[0])), float(energy.std() / energy.mean())


def drift_table(workdir, log=print):
    rows = []
    for kernel in KERNELS:
        t0 = time.time()
        out = run_lammps(drift_script(kernel), Path(workdir) / f"drift-{kernel}").output
        drift, fluct = energy_drift(out)
        rows.append({"kernel": kernel, "m": DRIFT_M, "side": DRIFT_SIDE, "steps": DRIFT_STEPS,
                     "ratio": DRIFT_RATIO, "drift": drift, "fluctuation": fluct,
                     "seconds": time.time() - t0})
        log(f"  drift {kernel:10s}: {drift:+.3e} (fluctuation {fluct:.3e})")
    return rows


# --------------------------------------------------------------------------- report

def _map_row(r):
    lead = [r["kernel"], r["m"], f"{r['side']} x {r['side']}"]
    if r.get("degenerate"):
        return lead + ["-"] * 4
    y, mid = r["bound_printed"], 0.5 * (r["measured_lo"] + r["measured_hi"])
    return lead + [f"{y:.4e}", f"{r['exact_limit'] / y:.4f}",
                   f"{r['measured_lo'] / y:.4f}-{r['measured_hi'] / y:.4f}", f"{mid / r['exact_limit']:.4f}"]


def markdown(rows, drifts):
    return (md_table(["kernel", "m", "N x N", "Y printed (s)", "exact 2/omega_max / Y",
                      "measured / Y", "measured / exact"], map(_map_row, rows)) + "\n\n"
            + md_table(["kernel", "m", "plate", "steps", "dt / Y", "energy drift",
                        "energy fluctuation"],
                       ([d["kernel"], d["m"], f"{d['side']} x {d['side']} free", d["steps"],
                         d["ratio"], f"{d['drift']:+.2e}", f"{d['fluctuation']:.2e}"] for d in drifts))
            + "\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, help="folder for stability.json/.md and runs")
    parser.add_argument("--skip-map", action="store_true", help="only the energy drift")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    rows = [] if args.skip_map else stability_map(out / "runs")
    drifts = drift_table(out / "runs")
    (out / "stability.json").write_text(json.dumps({"map": rows, "drift": drifts}, indent=1))
    table = markdown(rows, drifts)
    (out / "stability.md").write_text(table)
    print(table)
    print(f"total {time.time() - t0:.0f} s")


if __name__ == "__main__":
    main()
