# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler on the field's standard deck (Borden et al. 2012) beside the paper's
loading, bond-based and on bbpd/lps/KERNEL (DECKS), with the loading study's angles
(examples/kalthoff-winkler/README.md, "The standard deck", has the commands).
"""

import itertools
import sys
from pathlib import Path

from bbpd import csvfile
from bbpd import jobs as jobmod
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.provenance import cpu
from bbpd.jobs import ROOT
from bbpd.kernels import KERNELS
from bbpd.runner import run_noted
from bbpd.markdown import cell as _f
from bbpd.markdown import columns
from bbpd.benchmarks import cli

CSV = ROOT / "examples" / "kalthoff-winkler" / "results" / "standard_deck.csv"

# deck -> (what it is, the input script's variables)
DECKS = {
    "paper": ("the paper's: 32 m/s held, rho 7800 kg/m3, G_c 6.9e4 J/m2", {}),
    "standard": ("Borden et al. 2012: 16.5 m/s held, rho 8000 kg/m3, G_c 2.213e4 J/m2",
                 {"v0": 16.5, "rho": 8000.0, "Gc": 2.213e4}),
    "paper-lps": ("the paper's loading on bbpd/lps/KERNEL with nu = 0.3",
                  {"family": "lps", "nu": 0.3}),
    "standard-lps": ("the standard deck on bbpd/lps/KERNEL with its nu = 0.3",
                     {"v0": 16.5, "rho": 8000.0, "Gc": 2.213e4, "family": "lps", "nu": 0.3}),
    "paper-lps-nu025": ("the paper's loading on bbpd/lps/KERNEL with the bond-based nu = 1/4",
                        {"family": "lps", "nu": 0.25}),
}
INPUT_GC = 6.9e4    # in.kalthoff_winkler's default G_c (J/m^2), the paper's
BOND_DECK = {"paper-lps": "paper", "standard-lps": "standard",    # the same loading, bond-based
             "paper-lps-nu025": "paper"}
# (what changes, deck, the deck it changes from): the model family at the same nu, then nu alone
CHANGES = (("the paper's loading on the state-based solid at the bond-based nu = 1/4",
            "paper-lps-nu025", "paper"),
           ("the paper's loading, nu from 1/4 to 0.3 in the state-based solid", "paper-lps",
            "paper-lps-nu025"),
           ("the standard deck on the state-based solid with its nu = 0.3", "standard-lps",
            "standard"))
DX_VALUES = (1.0e-3, 0.5e-3)
COLUMNS = ("deck", "kernel", "dx_mm", "v0", "rho", "Gc", "first_bond_us", "band_us",
           "initial_deg", "fit_deg", "chord_deg", "length_end_mm", "crack_stops", "loop_cpu_s",
           "nprocs")


def case_vars(deck, kernel, dx):
    return kw.variables(kernel, dx, tend=study.TEND, **DECKS[deck][1])


def run_case(workdir, deck, kernel, dx, nprocs=1, reuse=False):
    """Run one deck in workdir (unless reuse and it finished) and measure it: a CSV row."""
    case = run_noted(kw.EXAMPLE, workdir, case_vars(deck, kernel, dx),
                     {"deck": deck, "kernel": kernel, "dx": dx}, nprocs, reuse)
    r = projectile.analyse(workdir)
    r["nprocs"] = case["nprocs"]
    out = projectile.row(r)
    out.update(deck=deck, v0=r["v0"], rho=loaded_density(workdir))
    if out["Gc"] is None:    # a setup report without the bond-based 'E = .. Gc = ..' line
        out["Gc"] = float(DECKS[deck][1].get("Gc", INPUT_GC))
    return {c: out[c] for c in COLUMNS}


def loaded_density(workdir):
    """rho as the run printed it (the KW loading line)."""
    for line in (Path(workdir) / "log.lammps").read_text().splitlines():
        if line.startswith("KW loading:") and " rho " in line:
            return float(line.rsplit(" rho ", 1)[1].split()[0])
    return None


def table(rows):
    return columns(sorted(rows, key=_order), (
        ("deck", "deck"), ("kernel", "kernel"), ("dx (mm)", "dx_mm", "g"), ("v0 (m/s)", "v0", "g"),
        ("rho (kg/m3)", "rho", ".0f"), ("G_c (J/m2)", "Gc", "g"),
        ("first bond (us)", "first_bond_us", ".1f"), ("damage band (us)", "band_us", ".1f"),
        ("initial (deg)", "initial_deg", ".1f"),
        ("fit (deg)", "fit_deg", ".1f"), ("chord (deg)", "chord_deg", ".1f"),
        ("crack length at end (mm)", "length_end_mm", ".0f"), ("crack stops (us)", "crack_stops"),
        ("loop CPU (s)", "loop_cpu_s", ".0f")))


def _order(r):
    return (list(DECKS).index(r["deck"]), -r["dx_mm"], KERNELS.index(r["kernel"]))


def comparison(rows):
    """The numbers the report's lines rest on: 'fine' and 'coarse' (mm); 'deck': {(definition,
    kernel): (standard deck's angle on the finest grid, its change from the paper's loading)};
    'grid': {kernel: change of the standard deck's fit angle from the coarsest to the finest
    grid}; 'changes': {deck of CHANGES: (dx, {kernel: (fit angle, change from its base deck)})}
    on the finest grid both ran; 'hits': the runs within 70 +- 2 deg (by which definitions)
    whose cracks reach the plate's edge."""
    by = {(r["deck"], r["kernel"], r["dx_mm"]): r for r in rows}
    dxs = sorted({r["dx_mm"] for r in rows})
    fine, coarse = dxs[0], dxs[-1]

    def moved(base, deck, k, dx, d):
        a, b = by.get((base, k, dx)), by.get((deck, k, dx))
        if a and b and a[f"{d}_deg"] is not None and b[f"{d}_deg"] is not None:
            return b[f"{d}_deg"], b[f"{d}_deg"] - a[f"{d}_deg"]
        return None
    out = dict(fine=fine, coarse=coarse, deck={}, grid={}, changes={})
    for k in KERNELS:
        for d in kw.ANGLE_DEFS:
            if (v := moved("paper", "standard", k, fine, d)) is not None:
                out["deck"][d, k] = v
        a, b = by.get(("standard", k, coarse)), by.get(("standard", k, fine))
        if fine != coarse and a and b and a["fit_deg"] is not None and b["fit_deg"] is not None:
            out["grid"][k] = b["fit_deg"] - a["fit_deg"]
    for _, deck, base in CHANGES:
        for dx in dxs:    # the finest grid both decks ran
            got = {k: v for k in KERNELS if (v := moved(base, deck, k, dx, "fit")) is not None}
            if got:
                out["changes"][deck] = (dx, got)
                break
    out["hits"] = [(r["deck"], r["kernel"], r["dx_mm"], defs) for r in sorted(rows, key=_order)
                   if (defs := projectile.at_target(r))]
    return out


def summary(rows):
    """REPORT.md's line under the decks' table: comparison()'s runs at the experiment's angle"""
    hits = "; ".join(f"{d} {k} {dx:g} mm ({', '.join(defs)})" for d, k, dx, defs in comparison(rows)["hits"])
    return [f"Within {study.ANGLE_TARGET_DEG:.0f} ± {study.ANGLE_TOL_DEG:.0f}° with cracks that cross "
            f"the plate: {hits or 'none'}."]


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kalthoff-Winkler on the standard deck (Borden et al. 2012) beside the paper's loading"
ESTIMATE_S = {1.0e-3: 10.0, 0.5e-3: 80.0}    # loop CPU of one run on 1 rank (the CSV's)
LPS_COST = 3.5    # LPS loop over bond-based, same grid (the Mode-I plate at dx 0.1 m: 1.99 / 0.58 s)


def jobs(nprocs=1):
    """The runs as bbpd.report specs (tools/reproduce --full)."""
    inputs = (kw.EXAMPLE, Path(__file__), Path(kw.__file__), Path(study.__file__),
              Path(projectile.__file__), kw.ROOT / "potentials" / "kalthoff_winkler_steel.bbpd")
    return jobmod.report_specs("kwdeck", "bbpd.benchmarks.kalthoff_winkler_deck:run_case", inputs, (
        (k, dx, f"Kalthoff-Winkler deck {deck} {k} dx = {dx * 1e3:g} mm",
         {"deck": deck, "kernel": k, "dx": dx, "nprocs": nprocs},
         ESTIMATE_S[dx] * (LPS_COST if deck in BOND_DECK else 1.0))
        for dx in DX_VALUES for deck in DECKS for k in KERNELS))


def section(specs, results, figdir, notes):
    """The standard deck's section of REPORT.md (tools/reproduce --full)."""
    return jobmod.section(
        REPORT_TITLE, "; ".join(f"{d}: {DECKS[d][0]}" for d in DECKS) + ". Prescribed velocity "
        "on the struck layer, to 100 us, the loading study's angles; see "
        "examples/kalthoff-winkler/README.md, 'The standard deck'.",
        specs, results, table, summary,
        not_run=f"Not run by default ({len(jobs())} runs): `tools/reproduce --full` runs them; "
        "the last measured table is in examples/kalthoff-winkler/README.md, 'The standard deck'.")


def read_rows(path=CSV):
    """(comment lines, rows) of a CSV main() wrote"""
    return csvfile.read_csv(path)


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kw-deck", nprocs=1, kernels=KERNELS, dx=DX_VALUES, reuse=True,
                    csv=True, append=True)
    ap.add_argument("--decks", nargs="+", default=list(DECKS), choices=list(DECKS))
    a = ap.parse_args(argv)
    earlier, rows, made = csvfile.continue_csv(a.csv if a.append else None,
                                               cli.command("kalthoff_winkler_deck", argv))
    for dx, deck, k in itertools.product(a.dx, a.decks, a.kernels):
        r = run_case(Path(a.work) / f"{deck}-{k}-dx{dx * 1e3:g}mm", deck, k, dx, a.nprocs, a.reuse)
        print(f"{deck} {k} {dx * 1e3:g} mm: initial {_f(r['initial_deg'], '.1f')} fit "
              f"{_f(r['fit_deg'], '.1f')} chord {_f(r['chord_deg'], '.1f')} "
              f"stops {r['crack_stops']} loop CPU {_f(r['loop_cpu_s'], '.0f')} s", flush=True)
        rows.append(r)
    if a.csv:
        csvfile.write_csv(a.csv, rows, comments=[*earlier, made,
                                                 f"timing: LAMMPS loop CPU time, {cpu()}"])
    print(table(rows), *summary(rows), sep="\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
