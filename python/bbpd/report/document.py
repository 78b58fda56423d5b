# SPDX-License-Identifier: GPL-2.0-or-later
"""REPORT.md: the provenance header, one section per benchmark and the problems met while
writing it; figures of an earlier report that this one does not make are removed."""
import time
from pathlib import Path

from bbpd import jobs as jobmod
from . import work_precision

from .sections import BUILDERS
from .tables import failed, run_time

FIGURE_LIST = ".figures"    # the PNGs of the last report, removed before the next one is made


def versions_text(results):
    """The LAMMPS and plugin versions the finished runs' logs report, '?' where a log did not
    say (tests/regression/test_report_header.py fails on one)."""
    versions = sorted({(r.get("lammps_version"), r.get("plugin_version"))
                       for r in results.values() if not failed(r)}, key=str)
    return "; ".join(f"LAMMPS ({v or '?'}), plugin v{p or '?'}" for v, p in versions)


def section_lines(s):
    """A section's lines: its title and the parts it has, one blank line after each (a section
    not run by default has its one-line setup, and a table only where it reads committed data)."""
    parts = [p for p in (s["setup"], s["table"], s["text"]) if p]
    parts += ["\n".join(f"![{name}]({name})" for name in s["figures"])] if s["figures"] else []
    lines = [f"## {s['title']}", ""]
    for p in parts:
        lines += [p, ""]
    return lines


def write_report(out, specs, results, meta, start):
    figdir = Path(out)
    listing = figdir / FIGURE_LIST
    if listing.is_file():    # no stale figure of an earlier (e.g. --full) call stays behind
        for name in listing.read_text().split():
            (figdir / Path(name).name).unlink(missing_ok=True)
    notes = []
    sections = []
    for bench, build in BUILDERS:
        mine = [s for s in specs if s.bench == bench]
        try:
            sections.append(build(mine, results, figdir, notes))
        except Exception as exc:  # one broken section must not cost the others
            sections.append({"title": bench, "setup": "", "table": "",
                             "text": f"FAILED to build this section: {type(exc).__name__}: {exc}",
                             "figures": []})
    try:
        sections.append(work_precision.section(specs, results, figdir, notes))
    except Exception as exc:  # one broken section must not cost the others
        notes.append(f"work-precision section not made: {type(exc).__name__}: {exc}")

    n_failed = sum(failed(results.get(s.job.label)) for s in specs)
    wall = time.perf_counter() - start
    core_s = sum(run_time(r) or 0.0 for r in results.values() if not failed(r))
    lines = [
        "# BBPD: reproduction of Bouaraquia & Mabssout (2026)",
        "",
        "Written by `tools/reproduce" + (" --full" if meta["full"] else " --finer"
                                         if meta.get("finer") else "") + "` "
        f"on {meta['date']}. Every number below comes from the runs of this report.",
        "",
        f"- LAMMPS: {meta['lammps']} (`tools/lmp -h`); the runs' logs: " + versions_text(results),
        f"- plugin: bbpdplugin.so version {meta['plugin']} (CMakeLists.txt), source "
        f"{meta['git']}",
        f"- machine: {meta['machine']}; load average {meta['load']:.1f} at the start (the "
        "cores may be shared)",
        f"- runs: {len(specs)} ({meta['new']} made now, {len(specs) - meta['new']} reused from "
        f"an earlier call), single-rank, {meta['workers']} at a time; {n_failed} failed",
        f"- total wall time of this call: {wall:.0f} s ({jobmod._fmt(wall)}), of which the runs "
        f"{meta['runs_s']:.0f} s; the runs' own wall times add up to {core_s:.0f} s",
        "",
        "Run time in the tables is the wall time of the single-rank LAMMPS run (dispersion: "
        "run and FFT measurement), measured when the run was made; when several runs share "
        "the cores it includes their competition.",
        "",
    ]
    for s in sections:
        lines += section_lines(s)
    if notes:
        lines += ["## Problems while writing the report", ""] + [f"- {n}" for n in notes] + [""]
    path = Path(out) / "REPORT.md"
    path.write_text("\n".join(lines))
    listing.write_text("".join(f"{name}\n" for s in sections for name in s["figures"]))
    return path
