"""LAMMPS's examples/peri/in.peri.lps (glass cylinder shattered by a spherical indenter)
run with peri/lps and, ported, with 'bbpd/lps 3d'
(examples/peri-lps-dropin): mean damage and the number of atoms with damage > 0.5 at
steps 500 and 1000 agree within 2 %.

Default suite: the cylinder at 0.8 of its size (1,773 atoms); the original size (3,487
atoms) is marked slow. The loop-time ratio is printed, not asserted (perf/lps_vs_peri.py
measures it).
"""
import pytest
from scenes import cylinder_dropin


def test_cylinder_small_matches_peri_lps(lmp):
    cylinder_dropin(lmp, "lps", 0.8, atoms_abs=1)


@pytest.mark.slow
def test_cylinder_full_matches_peri_lps(lmp):
    cylinder_dropin(lmp, "lps", 1, atoms_abs=1)
