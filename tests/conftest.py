"""Shared pytest fixtures: run our LAMMPS (tools/lmp) on an input script."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "python"))

from bbpd.runner import run_lammps  # noqa: E402


@pytest.fixture
def lmp(tmp_path):
    """lmp(script, nprocs=1, version=None, check=True) -> CompletedProcess; runs in tmp_path."""
    def _run(script, nprocs=1, version=None, check=True, **kw):
        return run_lammps(script, workdir=tmp_path, nprocs=nprocs, version=version,
                          check=check, **kw)
    return _run
