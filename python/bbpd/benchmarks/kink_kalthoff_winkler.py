# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler tied to the kink test: the mode mix at the notch tips (compute
bbpd/jintegral) up to initiation, and the kink angles the criteria and the kink test give for
that mix (examples/kink-mixed-mode/README.md has the commands).
"""

import json
import math
from pathlib import Path

import numpy as np

from bbpd import kink
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kink as kinktest
from bbpd.markdown import table as md_table
from bbpd.runner import run_lammps
from bbpd.benchmarks import cli

ANCHOR = "fix             tips all ave/time"
J_LINES = """compute         Jlo all bbpd/jintegral tip ${{a}} ${{ylo}} rin {rin!r} rout {rout!r}
compute         Jhi all bbpd/jintegral tip ${{a}} ${{yhi}} rin {rin!r} rout {rout!r}
fix             jout all ave/time 1 1 1 c_Jlo[1] c_Jlo[2] c_Jlo[3] c_Jhi[1] c_Jhi[2] c_Jhi[3] &
                file j.dat format " %.10g"
"""
# annulus (in horizons): outside the nonlocal zone of the tip, and rout below the distance to
# the impacted layer (a - delta = 9 delta at 2 mm) and to the other notch (5 delta)
RIN_DELTA, ROUT_DELTA = 1.2, 2.4


def script(rin, rout):
    text = kw.EXAMPLE.read_text()
    i = text.index(ANCHOR)
    return text[:i] + J_LINES.format(rin=rin, rout=rout) + text[i:]


def kink_test_angles(psi, kernel="gaussian", alpha=0.0, dx_mm=1.0):
    """Measured kink-test angles at 2 and 4 horizons, interpolated linearly in psi."""
    rows = [r for r in kinktest.read_rows(kinktest.RESULTS)
            if r["kernel"] == kernel and r["alpha"] == alpha and r["dx_mm"] == dx_mm
            and r["ncross"] == kinktest.NCROSS]
    rows.sort(key=lambda r: r["psi"])
    p = [r["psi"] for r in rows]
    return {f"kinktest_{d}": float(np.interp(psi, p, [r[f"angle_{d}"] for r in rows]))
            for d in ("2d", "4d")}


def run(kernel, dx, workdir, tend=70e-6, nprocs=1):
    workdir = Path(workdir)
    delta = 5.0 * dx
    rin, rout = RIN_DELTA * delta, ROUT_DELTA * delta
    run_lammps(script(rin, rout), workdir, nprocs=nprocs,
               vars={"kernel": kernel, "dx": repr(dx), "tend": repr(tend)})
    res = kw.analyse(workdir)
    j = np.loadtxt(workdir / "j.dat", comments="#")
    step = j[:, 0]
    t_us = step * res["dt"] * 1e6
    out = {k: res[k] for k in ("kernel", "dx", "delta", "dt", "t_init_us", "t_band_us",
                               "angle_deg")}
    out.update(rin=rin, rout=rout, t_us=t_us.tolist(), KI_lo=j[:, 2].tolist(),
               KII_lo=j[:, 3].tolist(), KI_hi=j[:, 5].tolist(), KII_hi=j[:, 6].tolist())
    before = np.nonzero(t_us < res["t_init_us"])[0][-1] if res["t_init_us"] else len(t_us) - 1
    KI, KII = j[before, 2], j[before, 3]
    out.update(t_mix_us=float(t_us[before]), KI=float(KI), KII=float(KII),
               psi=math.degrees(math.atan2(KII, KI)),
               mirror_KII=float(j[before, 6] / KII), mirror_KI=float(j[before, 5] / KI))
    # K_I < 0 here (the faces are pressed together and pass through each other: no contact),
    # so the criteria are evaluated for faces without contact; the kink test covers psi <= 90
    # deg and np.interp holds its pure-Mode-II value beyond
    out.update(kink.criteria_angles(KI, KII, kink.BBPD_POISSON[kink.PLANE_STRAIN],
                                    kink.PLANE_STRAIN, closed=True))
    out.update(kink_test_angles(out["psi"]))
    # the same at the time the damage band leaves the tip (bonds near the tip already broken:
    # the stationary-crack J-integral is only indicative there)
    if res["t_band_us"]:
        k = np.nonzero(t_us <= res["t_band_us"])[0][-1]
        out.update(t_band_mix_us=float(t_us[k]), KI_band=float(j[k, 2]), KII_band=float(j[k, 3]),
                   psi_band=math.degrees(math.atan2(j[k, 3], j[k, 2])))
        band = kink.criteria_angles(j[k, 2], j[k, 3], kink.BBPD_POISSON[kink.PLANE_STRAIN],
                                    kink.PLANE_STRAIN, closed=True)
        out.update({f"{c}_band": v for c, v in band.items()})
    (workdir / "kink_kw.json").write_text(json.dumps(out))
    return out


SUMMARY = kinktest.FOLDER / "results" / "kalthoff_winkler_mix.json"
def table(r):
    """README table: the mix before initiation and the angles, Kalthoff-Winkler's and predicted
    (positive = towards the outer side, the experiment's convention)."""
    return md_table(
        ("kernel", "dx (mm)", "first break at tip (us)", "K_I, K_II before it (MPa m^1/2)",
         "psi (deg)", "psi when the damage band leaves (deg)", "KW angle (deg)",
         "kink test at 2 / 4 delta (deg)", "hoop stress", "hoop strain", "max G (HPU)",
         "the three at the band's mix", "experiment"),
        [[r["kernel"], f"{r['dx'] * 1e3:g}", f"{r['t_init_us']:.2f}",
          f"{r['KI'] / 1e6:.1f}, {r['KII'] / 1e6:.1f}", f"{r['psi']:.1f}",
          kw.fmt(r.get("psi_band"), ".1f") + (f" ({r['t_band_mix_us']:.1f} us)" if r.get("psi_band") else ""),
          kw.fmt(r["angle_deg"], ".1f"), f"{-r['kinktest_2d']:.1f} / {-r['kinktest_4d']:.1f}",
          f"{-r['hoop_stress']:.1f}", f"{-r['hoop_strain']:.1f}", f"{-r['energy']:.1f}",
          f"{-r['hoop_stress_band']:.1f}, {-r['hoop_strain_band']:.1f}, {-r['energy_band']:.1f}",
          f"{kw.EXPERIMENT_ANGLE_DEG:.0f}"]])


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kw-kink")
    ap.add_argument("--kernel", default="gaussian")
    ap.add_argument("--dx", type=float, default=2e-3)
    ap.add_argument("--tend", type=float, default=70e-6)
    ap.add_argument("--summary", default=str(SUMMARY), help="JSON to write (the README's table "
                    "comes from it through tools/python -m bbpd.claims --write)")
    args = ap.parse_args(argv)
    r = run(args.kernel, args.dx, args.work, args.tend)
    summary = {k: v for k, v in r.items() if not isinstance(v, list)}
    print(json.dumps(summary, indent=1))
    Path(args.summary).write_text(json.dumps(summary, indent=1) + "\n")
    print(table(r))


if __name__ == "__main__":
    main()
