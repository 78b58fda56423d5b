"""Shared pytest fixtures: run our LAMMPS (tools/lmp) on an input script."""
import pytest

from bbpd.runner import run_lammps    # python/ is on pytest's pythonpath (pytest.ini)


@pytest.fixture
def lmp(tmp_path):
    """lmp(script, nprocs=1, version=None, check=True) -> CompletedProcess; runs in tmp_path."""
    def _run(script, nprocs=1, version=None, check=True, **kw):
        return run_lammps(script, workdir=tmp_path, nprocs=nprocs, version=version,
                          check=check, **kw)
    return _run
