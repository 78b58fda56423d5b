# SPDX-License-Identifier: GPL-2.0-or-later
"""BBPD Python tools.

    bbpd.lammps(**kwargs)   a lammps.lammps instance with bbpdplugin.so loaded (in process)

Submodules (imported explicitly, so that ``bbpd.runner`` keeps working
without numpy/scipy):
    runner     run tools/lmp on an input script (a subprocess, serial or under mpirun)
    inprocess  LAMMPS in this process with the plugin loaded (bbpd.lammps)
    freund     analytic DSIF references (paper eqs. 41-43, mode-II step/ramp)
    metrics    peak and L2 relative errors (eqs. 44-45)
    dsif       displacement-extrapolation DSIFs (eqs. 39-40)
    plots      K(t) plots to PNG (matplotlib, Agg)
"""
from .inprocess import lammps

__all__ = ["lammps"]
