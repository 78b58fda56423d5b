# SPDX-License-Identifier: GPL-2.0-or-later
"""BBPD Python tools: bbpd.lammps(**kwargs) is a lammps.lammps instance with bbpdplugin.so loaded
(in process). Submodules are imported explicitly, so that bbpd.runner keeps working without
numpy or scipy; doc/architecture.rst lists them by layer.
"""
from .inprocess import lammps

__all__ = ["lammps"]
