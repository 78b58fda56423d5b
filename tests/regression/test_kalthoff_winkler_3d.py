"""The 3D Kalthoff-Winkler runs (bbpd.benchmarks.kalthoff_winkler_3d): the faces' damage dump
holds the two faces only, the monitor cadence keeps the monitors' rows at their steps, and the
table and the report's lines follow the rows."""
import numpy as np

from bbpd import readers
from bbpd.benchmarks import kalthoff_winkler_3d as kw3d
from bbpd.runner import run_lammps

COARSE_DX = 3.0e-3    # three layers: faces and mid-plane distinct, a second of CPU
SHORT = 4.0e-6


def test_faces_dump_and_monitor_cadence(tmp_path):
    v = kw3d.case_vars(COARSE_DX)
    v.update(tend=repr(SHORT), monitor="3")
    run_lammps(str(kw3d.projectile.EXAMPLE_3D), tmp_path, vars=v)
    z = np.concatenate([d["f_ref[3]"] for _, d in
                        readers.dump_snapshots(tmp_path / "damage_faces.dump")])
    assert len(z) > 0
    layers = np.unique(np.round(z / COARSE_DX - 0.5).astype(int))
    assert list(layers) == [0, 2]    # first and last of three layers, not the middle one
    steps = np.loadtxt(tmp_path / "tips.dat", comments="#")[:, 0]
    assert np.all(np.diff(steps) == 3) and steps[0] % 3 == 0
    fig = kw3d.log_figures((tmp_path / "log.lammps").read_text())
    assert fig["atoms"] > 0 and fig["bonds"] > fig["atoms"] and fig["memory_MB"] > 0


def row(setup, dx, fit, faces=(None, None)):
    return {"setup": setup, "kernel": "gaussian", "dx_mm": dx, "m": 3.0, "delta_mm": 3 * dx,
            "horizons_through": 9.0 / (3 * dx) if setup == "3d" else None, "atoms": 1000.0,
            "bonds": 1.0e5, "steps": 100.0, "first_bond_us": 15.0, "band_us": 20.0,
            "initial_deg": fit - 2.0, "fit_deg": fit, "chord_deg": fit + 1.0,
            "fit_face_lo_deg": faces[0], "fit_face_hi_deg": faces[1], "chord_face_deg": None,
            "length_end_mm": 80.0, "crack_stops": "edge 81", "loop_s": 10.0, "memory_MB": 100.0,
            "nprocs": 2.0 if setup == "3d" else 1.0}


def test_summary_follows_the_rows():
    rows = [row("3d", 1.0, 60.0, (58.0, 58.5)), row("2d", 1.0, 62.5),
            row("3d", 0.75, 61.0, (59.0, 59.0)), row("2d", 0.75, 63.0)]
    pairs, refine = kw3d.against_2d(rows)
    assert [(d3["dx_mm"], d2["dx_mm"], diff) for d3, d2, diff in pairs] == [(1.0, 1.0, -2.5), (0.75, 0.75, -2.0)]
    assert refine == 1.0
    assert kw3d.table(rows).count("\n") == len(rows) + 1
