"""The LAMMPS 4 Feb 2025 compatibility build (tools/bootstrap with BBPD_LAMMPS_VERSION=20250204,
built by tools/test) beyond loading the plugin: forces against the NumPy reference, bitwise
rank-count invariance with a growing crack, restart against a continuous run, a notch
across a periodic boundary (the one place where the plugin calls a LAMMPS function whose
signature differs between the versions, src/bbpd_compat.h), and the examples' damage pictures
(dump image).

The checks are those of test_forces.py and test_mpi_restart.py, run with the compatibility
build selected through BBPD_LAMMPS_VERSION (tools/lmp reads it); every run's banner is checked,
so the tests cannot silently fall back to the default build.
"""

import pytest

from bbpd import runner

from scenes import sibling

VERSION = "20250204"
BANNER = "LAMMPS (4 Feb 2025"


forces = sibling("test_forces")
mpi_restart = sibling("test_mpi_restart")
images = sibling("test_images")


@pytest.fixture
def compat(monkeypatch):
    """Select the compatibility build for every LAMMPS run of the test, and check each run's
    banner."""
    monkeypatch.setenv("BBPD_LAMMPS_VERSION", VERSION)
    runs = []
    original = runner.run_lammps

    def checked(*args, **kw):
        proc = original(*args, **kw)
        assert BANNER in proc.output, "not the 4 Feb 2025 build"
        runs.append(proc)
        return proc

    monkeypatch.setattr(runner, "run_lammps", checked)
    monkeypatch.setattr(mpi_restart, "run_lammps", checked)
    yield runs
    assert runs, "no LAMMPS run"


@pytest.mark.parametrize("kernel,model,nprocs", [("gaussian", "plane/stress", 1),
                                                  ("constant", "3d", 2)])
def test_compat_forces_match_reference(compat, tmp_path, kernel, model, nprocs):
    def lmp(script, **kw):
        return runner.run_lammps(script, workdir=tmp_path, **kw)
    forces.test_forces_match_reference(lmp, tmp_path, kernel, model, nprocs)


def test_compat_rank_count_invariance(compat, tmp_path):
    mpi_restart.test_rank_count_invariance(tmp_path, "2d", [1, 2], 200)


def test_compat_restart_equals_continuous_run(compat, tmp_path):
    mpi_restart.test_restart_equals_continuous_run(tmp_path, 1, 2)


def test_compat_notch_across_periodic_boundary(compat, tmp_path):
    """Periodic images go through BBPDCompat::minimum_image, whose 2025 overload differs."""
    def lmp(script, **kw):
        return runner.run_lammps(script, workdir=tmp_path, **kw)
    forces.test_notch_cuts_bonds_across_periodic_boundary(lmp, tmp_path)


lps = sibling("test_lps_compat")


def test_compat_lps_forces_equal_peri_lps(compat, tmp_path):
    """bbpd/lps built against 4 Feb 2025 gives that version's peri/lps forces (to 1e-12 of
    the largest force) on 1, 2 and 4 ranks, the same bits on each."""
    def lmp(script, **kw):
        return runner.run_lammps(script, workdir=tmp_path, **kw)
    lps.test_forces_equal_peri_lps(lmp, tmp_path, "s s s")


def test_compat_damage_pictures(compat, tmp_path):
    """dump image is in the core of 4 Feb 2025 (a package from 4 Jul 2026 on): the examples'
    pictures, with the same settings, from the compatibility build"""
    found = images.pictures("kalthoff-winkler", tmp_path, "yes", version=VERSION)
    assert BANNER in (tmp_path / "log.lammps").read_text()
    assert len(found) == 5
    for _, path in found:
        assert max(images.png_size(path)) == images.LONG_SIDE
