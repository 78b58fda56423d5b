# SPDX-License-Identifier: GPL-2.0-or-later
"""The plugin's sources depend on each other one way (doc/architecture.rst): a core of headers
with no LAMMPS dependency, the bond storage (fix bbpd/bonds) on top of it, and the pair style,
fix bbpd/notch and the computes on top of the storage. The storage never reaches up."""
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# LAMMPS glue that lives beside the core headers: resolves LAMMPS version differences
GLUE = {"bbpd_compat.h"}
CORE = sorted(p.name for p in SRC.glob("bbpd_*.h") if p.name not in GLUE)
STORAGE = ["fix_bbpd_bonds.h", "fix_bbpd_bonds.cpp"]


def includes(name):
    """quoted includes of src/NAME, and of the src headers it includes, transitively"""
    seen, todo = set(), [name]
    while todo:
        for inc in INCLUDE.findall((SRC / todo.pop()).read_text()):
            if inc not in seen:
                seen.add(inc)
                if (SRC / inc).is_file():
                    todo.append(inc)
    return seen


def test_core_is_found():
    assert {"bbpd_kernel.h", "bbpd_bond_law.h", "bbpd_bond_storage.h", "bbpd_row.h"} <= set(CORE)


@pytest.mark.parametrize("header", CORE)
def test_core_header_needs_no_lammps(header):
    outside = sorted(i for i in includes(header) if i not in CORE)
    assert not outside, f"{header} includes {outside}: the core takes no LAMMPS header"


@pytest.mark.parametrize("name", STORAGE)
def test_storage_knows_neither_pair_style_nor_notch(name):
    reached = includes(name)
    assert not reached & {"pair_bbpd.h", "fix_bbpd_notch.h"}, sorted(reached)
    text = (SRC / name).read_text()
    for cls in ("PairBBPD", "FixBBPDNotch", "FixBBPDAlpha"):
        assert cls not in text, f"{name} names {cls}: the storage must not call its users"
