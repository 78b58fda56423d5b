"""The cylinder tables of examples/peri-{lps,ves,eps}-dropin/README.md against the CSVs they
were written from (perf/results/spr-*-cylinder.csv, perf/lps_vs_peri.py): the ratios of the
minimum loop times and of the minimum processor times, as the READMEs print them, and as
README.md's styles table quotes them for VES and EPS."""
import csv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def ratios(family):
    """(loop, processor time) of peri/FAMILY over bbpd/FAMILY, minima over the rounds; the rows"""
    rows = list(csv.DictReader(open(ROOT / "perf" / "results" / f"spr-{family}-cylinder.csv")))
    ours = [r for r in rows if r["style"] == f"bbpd/{family}"]
    peri = [r for r in rows if r["style"] == f"peri/{family}"]
    assert len(ours) == len(peri) >= 3
    loop = min(float(r["loop_s"]) for r in peri) / min(float(r["loop_s"]) for r in ours)
    cpu = min(float(r["cpu_s"]) for r in peri) / min(float(r["cpu_s"]) for r in ours)
    return loop, cpu, rows


@pytest.mark.parametrize("family", ["lps", "ves", "eps"])
def test_readme_ratios_come_from_the_csv(family):
    loop, cpu, rows = ratios(family)
    text = (ROOT / "examples" / f"peri-{family}-dropin" / "README.md").read_text()
    assert f"**{loop:.1f}x** | {cpu:.1f}x |" in text, (family, loop, cpu)
    assert rows[0]["date"][:16].split(" ")[1] in text    # the README names the run it quotes


def test_the_styles_table_quotes_the_ves_and_eps_ratios():
    (vl, vc, _), (el, ec, _) = ratios("ves"), ratios("eps")
    text = " ".join((ROOT / "README.md").read_text().split())
    assert (f"LAMMPS's cylinder examples {vl:.1f}x / {el:.1f}x faster (loop time; processor time "
            f"{vc:.1f}x / {ec:.1f}x)") in text
