"""The standard deck of Kalthoff-Winkler (bbpd.benchmarks.kalthoff_winkler_deck): the input
script takes its variables, and the comparison behind the report's lines follows the rows."""
import pytest

from bbpd.benchmarks import kalthoff_winkler_deck as deck
from bbpd.runner import run_lammps

SHORT_US = 3.0    # a few microseconds: the loading lines and the calibration only


def test_standard_deck_reaches_the_input(tmp_path):
    v = deck.case_vars("standard", "gaussian", 2.0e-3)
    v["tend"] = repr(SHORT_US * 1e-6)
    run_lammps(str(deck.kw.EXAMPLE), tmp_path, vars=v)
    log = (tmp_path / "log.lammps").read_text()
    assert "KW loading: v0 16.5 " in log
    assert deck.loaded_density(tmp_path) == 8000.0
    assert "Gc = 22130" in log or "Gc = 2.213e+04" in log


def rows_of(angles):
    """rows of both decks for the three kernels at two grids, fit angle from angles[(deck, dx)]"""
    out = []
    for (d, dx), a in angles.items():
        for k in deck.KERNELS:
            out.append({"deck": d, "kernel": k, "dx_mm": dx, "v0": 1.0, "rho": 1.0, "Gc": 1.0,
                        "first_bond_us": 1.0, "band_us": 2.0, "initial_deg": a - 1.0,
                        "fit_deg": a, "chord_deg": a + 1.0, "length_end_mm": 80.0,
                        "crack_stops": "edge 70", "loop_cpu_s": 1.0, "nprocs": 1})
    return out


def test_summary_follows_the_rows():
    c = deck.comparison(rows_of({("paper", 1.0): 61.0, ("standard", 1.0): 65.0,
                                 ("paper", 0.5): 62.0, ("standard", 0.5): 69.5}))
    assert c["fine"] == 0.5 and c["deck"]["fit", "gaussian"] == (69.5, 7.5)
    assert c["grid"]["constant"] == 4.5
    assert ("standard", "gaussian", 0.5, ["initial", "fit", "chord"]) in c["hits"]
    assert deck.comparison(rows_of({("paper", 1.0): 50.0, ("standard", 1.0): 50.0}))["hits"] == []


@pytest.mark.parametrize("bad", ["fast", ""])
def test_unknown_deck_is_refused(bad):
    with pytest.raises(KeyError):
        deck.case_vars(bad, "gaussian", 1.0e-3)


def test_lps_deck_reaches_the_input(tmp_path):
    v = deck.case_vars("paper-lps", "gaussian", 2.0e-3)
    assert v["family"] == "lps" and float(v["nu"]) == 0.3
    v["tend"] = repr(SHORT_US * 1e-6)
    run_lammps(str(deck.kw.EXAMPLE), tmp_path, vars=v)
    log = (tmp_path / "log.lammps").read_text()
    assert "pair style bbpd/lps/gaussian model plane/strain" in log
    # K and G of E = 190 GPa, nu = 0.3 in plane strain: kappa' = E / (2 (1 + nu) (1 - 2 nu))
    assert "K = 1.8269231e+11  G = 7.3076923e+10" in log


def test_summary_separates_the_family_from_poissons_ratio():
    c = deck.comparison(rows_of({("paper", 1.0): 61.0, ("paper-lps-nu025", 1.0): 55.0,
                                 ("paper-lps", 1.0): 51.0}))
    assert c["changes"]["paper-lps-nu025"] == (1.0, {k: (55.0, -6.0) for k in deck.KERNELS})
    assert c["changes"]["paper-lps"] == (1.0, {k: (51.0, -4.0) for k in deck.KERNELS})
