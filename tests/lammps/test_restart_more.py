"""write_restart/read_restart gives the same bits as a continuous run in the cases
test_mpi_restart.py does not cover: a 3D body, compact bond storage, contact, and several
atom types with their own E, G_c and horizon (the scenes and helpers of test_mpi_restart.py).

Each case: `run 2N` against `run N` + write_restart + read_restart (new process, 2 ranks) +
`run N`; the pair style, its coefficients and the broken bonds come back from the file.
"""

import pytest

from scenes import sibling

mr = sibling("test_mpi_restart")

# two materials: the plate ahead of the notch tip (x > 21 mm) is type 2 (softer, weaker,
# shorter horizon), so the crack grows through mixed and type-2 bonds
SETUP_TYPES = mr.SETUP_2D.replace(
    "read_data atoms.data\n", "read_data atoms.data extra/atom/types 1\n"
    "region soft block 0.021 INF INF INF INF INF units box\nset region soft type 2\n").replace(
    "pair_coeff * * {E!r} {GC!r} 0.003015\n".format(E=mr.E, GC=mr.GC),
    f"pair_coeff 1 1 {mr.E!r} {mr.GC!r} 0.003015\n"
    f"pair_coeff 2 2 {0.8 * mr.E!r} {0.5 * mr.GC!r} 0.002515\n"
    f"pair_coeff 1 2 {0.9 * mr.E!r} {0.6 * mr.GC!r} 0.003015\n")

SCENES = {
    "3d": dict(mr.SCENES["3d"], half=100),
    "compact": dict(mr.SCENES["2d"], half=100,
                    setup=mr.SETUP_2D.replace("thickness {THICKNESS!r}".format(
                        THICKNESS=mr.THICKNESS), "thickness {!r} bond/storage compact".format(
                        mr.THICKNESS))),
    "contact": dict(mr.SCENES["contact"], half=200),
    "types": dict(mr.SCENES["2d"], half=100, setup=SETUP_TYPES),
}


def script_pair(scene):
    s = SCENES[scene]
    cont = (s["setup"].format(grid=mr.GRIDS[1]) + s["dynamics"]
            + f"timestep {s['dt']!r}\nrun {2 * s['half']}\n" + mr.FINISH)
    first = (s["setup"].format(grid=mr.GRIDS[1]) + s["dynamics"]
             + f"timestep {s['dt']!r}\nrun {s['half']}\nwrite_restart state.restart\nrun 0\n")
    second = ("plugin load bbpdplugin.so\nread_restart state.restart\n" + s["dynamics"]
              + f"run {s['half']}\n" + mr.FINISH)
    return cont, first, second


def run(workdir, scene, script, nprocs):
    workdir.mkdir(parents=True, exist_ok=True)
    if not (workdir / "atoms.data").exists():
        SCENES[scene]["data"](workdir / "atoms.data")
    return mr.run_lammps(script, workdir=workdir, nprocs=nprocs).output


@pytest.mark.parametrize("scene", list(SCENES))
def test_restart_equals_continuous_run(tmp_path, scene):
    cont, first, second = script_pair(scene)
    ref_out = run(tmp_path / "continuous", scene, cont, 1)
    ref_atoms, ref_total, ref_broken = mr.final_state(tmp_path / "continuous", ref_out)
    wd = tmp_path / "restarted"
    out1 = run(wd, scene, first, 1)
    out2 = run(wd, scene, second, 2)
    report = mr.PAIR_REPORT.search(ref_out).group(1)
    assert mr.PAIR_REPORT.search(out2).group(1) == report
    if scene == "compact":
        assert "12.0 bytes per bond" in out2
    if scene == "contact":
        assert "contact: on" in out2
    if scene == "types":
        assert "types 2 2: E = 1.52e+11" in report and "types 1 2: E = 1.71e+11" in report
    if scene != "contact":
        # a crack grows in both halves: the restart carries bonds broken during the run
        notch, at_write = mr.broken_counts(out1)[0], mr.broken_counts(out1)[-1]
        assert notch < at_write < ref_broken
        assert mr.broken_counts(out2)[0] == at_write
    atoms, total, broken = mr.final_state(wd, out2)
    assert (total, broken) == (ref_total, ref_broken)
    mr.check_identical(ref_atoms, atoms, f"{scene}: restart")
