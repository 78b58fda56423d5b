"""REPORT.md's header names the LAMMPS and plugin versions of every run, and a section not run
by default is one line without blank lines after it.

The header reads each result's versions; the timing repeats of the work-precision diagrams
(bbpd.report.work_precision.repeat_run) delete their run folders and once reported none, so the header
read 'LAMMPS (?), plugin v?'. Both kinds of job run here once, on the coarsest Mode-I grid.
"""
import re

from bbpd.report import work_precision
from bbpd.benchmarks import kalthoff_winkler_grid
from bbpd.report import document, runs

MODE1 = ("bbpd.benchmarks.mode1:run", {"kernel": "gaussian", "dx": 0.2, "nprocs": 1})
VERSION = re.compile(r"^LAMMPS \(\d+ \w+ \d{4}\), plugin v\d+\.\d+\.\d+$")


def assert_parsed(text):
    """every version of a header's 'the runs' logs:' list was read from a log"""
    assert text and "?" not in text, f"unparsed version in the header: {text}"
    for part in text.split("; "):
        assert VERSION.match(part), part


def test_every_kind_of_run_names_its_build(tmp_path):
    target, args = MODE1
    results = {
        "run": runs.run_job(str(tmp_path / "run"), target, args, "Mode I"),
        "timing": work_precision.repeat_run(str(tmp_path / "timing"), target, args, repeats=1),
    }
    assert results["timing"]["loop_times"]
    for res in results.values():
        assert_parsed(document.versions_text({"one": res}))
    assert_parsed(document.versions_text(results))


def test_header_check_catches_an_unparsed_version():
    """negative control: a result without versions (what repeat_run returned) fails the check"""
    text = document.versions_text({"run": {"lammps_version": "4 Jul 2026",
                                           "plugin_version": "0.1.0"}, "timing": {}})
    assert "?" in text
    try:
        assert_parsed(text)
    except AssertionError:
        return
    raise AssertionError("assert_parsed passed a header with '?'")


def test_section_not_run_by_default_is_one_line():
    s = kalthoff_winkler_grid.section([], {}, None, [])
    lines = document.section_lines(s)
    assert lines == [f"## {s['title']}", "", s["setup"], ""]
    assert s["setup"].startswith("Not run by default") and "\n" not in s["setup"]
    # a section with every part: one blank line between parts, none doubled
    full = document.section_lines({"title": "T", "setup": "S", "table": "| a |", "text": "X",
                                   "figures": ["a.png", "b.png"]})
    assert full == ["## T", "", "S", "", "| a |", "", "X", "", "![a.png](a.png)\n![b.png](b.png)",
                    ""]
