"""examples/quasi-static: the plate with a hole's second measure (bbpd.benchmarks.plate_hole.fitted)
on a field of known concentration, the issue's verdict on it as data from the committed sweep,
and the README's tables of K and of the dynamic initiation against the CSVs they quote."""
import csv

import numpy as np
import pytest

from bbpd.benchmarks import center_crack, plate_hole as ph
from bbpd.report import work_precision as wp

RESULTS = ph.HERE / "results"
README = (ph.HERE / "README.md").read_text()


def rows(name):
    return list(csv.DictReader(open(RESULTS / name)))


def test_the_fit_returns_the_amplitude_of_tans_form(tmp_path):
    """sigma_xx = (K/3) Kirsch on the ligament with eps_yy = 0 (sigma_yy = nu sigma_xx): the fit
    gives K back, whatever the rows inside the hole's surface layer hold"""
    dx, k_true = 0.25e-3, 3.4
    lines = []
    for j, y in enumerate(np.arange(ph.W / 2 + ph.R + dx / 2, ph.W, dx)):
        r = y - ph.W / 2
        exx = (k_true / 3) * ph.kirsch_ligament(r)[0] * ph.SIGMA * (1 - ph.NU ** 2) / ph.E
        exx *= 1.5 if r < ph.R + 1.0e-3 else 1.0    # a surface layer the fit must skip
        for side in (-1, 1):
            x0 = ph.L / 2 + side * dx / 2
            lines.append(f"{2 * j + side} {x0 + side * exx * dx / 2!r} {y!r} {side * exx * dx / 2!r} 0")
    dump = tmp_path / "ligament.dump"
    dump.write_text("ITEM: ATOMS id x y c_u[1] c_u[2]\n" + "\n".join(lines) + "\n")
    k, n = ph.fitted(dump, 1.0e-3, ph.FIT_OUTER)
    assert k == pytest.approx(k_true, rel=1e-9) and n == 8
