# SPDX-License-Identifier: GPL-2.0-or-later
"""bbpd.readers on small files written the way LAMMPS and the plugin write them: the setup
report and loop-time lines of a log, multi-snapshot text dumps, k.dat with and without the
J-integral columns."""
import numpy as np
import pytest

from bbpd import readers

LOG = """LAMMPS (4 Jul 2026)
Loading plugin: BBPD kernel-weighted bond-based peridynamics v0.1.0 by the BBPD authors
  micromodulus c0 = 1.5e+20  critical_stretch s0 = 0.0123
  stable timestep: eq. 25 1.11187e-07, velocity-Verlet limit 1.57242e-07; timestep = 5e-08 (0.318 of the limit)
   Step          Temp          PotEng
         0   0              0
        10   1.5            -2.25
Loop time of 3.25 on 2 procs for 10 steps with 100 atoms
"""


def test_log_lines():
    assert readers.build_versions(LOG) == {"lammps_version": "4 Jul 2026",
                                           "plugin_version": "0.1.0"}
    assert readers.loop_time(LOG) == (3.25, 2)
    assert readers.pair_setup(LOG) == {"critical_stretch": 0.0123, "dt_bound": 1.57242e-07,
                                       "dt_fraction": 0.318}
    (table,) = readers.thermo_tables(LOG)
    assert table["Step"].tolist() == [0, 10] and table["PotEng"][-1] == -2.25


def test_log_without_those_lines():
    assert readers.loop_time("no run") == (None, None)
    assert set(readers.pair_setup("no pair").values()) == {None}
    assert set(readers.build_versions("").values()) == {None}


def write_dump(path, snapshots):
    """snapshots: [(step, ids, values)] as 'ITEM: ATOMS id v'."""
    lines = []
    for step, ids, values in snapshots:
        lines += ["ITEM: TIMESTEP", str(step), "ITEM: NUMBER OF ATOMS", str(len(ids)),
                  "ITEM: BOX BOUNDS pp pp pp", "0 1", "0 1", "-0.5 0.5", "ITEM: ATOMS id v"]
        lines += [f"{i} {v!r}" for i, v in zip(ids, values)]
    path.write_text("\n".join(lines) + "\n")


def test_dump_snapshots_and_last_snapshot(tmp_path):
    path = tmp_path / "d.dump"
    write_dump(path, [(0, [2, 1, 3], [0.2, 0.1, 0.3]), (50, [3, 1, 2], [3.5, 1.5, 2.5])])
    snaps = readers.dump_snapshots(path)
    assert [s for s, _ in snaps] == [0, 50]
    assert snaps[1][1]["id"].tolist() == [3, 1, 2]             # file order
    last = readers.read_dump(path)
    assert last["id"].tolist() == [1, 2, 3]                     # sorted by id
    assert last["v"].tolist() == [1.5, 2.5, 3.5]


@pytest.mark.parametrize("columns", [4, 7])
def test_k_history_and_j_columns(tmp_path, columns):
    data = np.arange(3 * columns, dtype=float).reshape(3, columns)
    path = tmp_path / "k.dat"
    np.savetxt(path, data, header="step K1 K2 K3" + (" J KI KII" if columns == 7 else ""))
    t, *k = readers.k_history(path, dt=0.5)
    assert t.tolist() == (0.5 * data[:, 0]).tolist()
    assert [c.tolist() for c in k] == [data[:, n].tolist() for n in (1, 2, 3)]
    j = readers.j_history(path)
    if columns == 4:
        assert j is None
    else:
        assert [c.tolist() for c in j] == [data[:, n].tolist() for n in (4, 5, 6)]
