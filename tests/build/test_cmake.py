# SPDX-License-Identifier: GPL-2.0-or-later
"""Building the plugin the LAMMPS way: sizes and MPI from the LAMMPS it is built for, a serial
(MPI STUBS) LAMMPS, and `cmake --install` into the folder that LAMMPS_PLUGIN_PATH users load from."""
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
VERSION = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
ENVFILE = ROOT / "build" / f"lammps-{VERSION}" / "bbpd-env.sh"


def lammps_prefix():
    for line in ENVFILE.read_text().splitlines():
        if line.startswith("BBPD_LAMMPS_PREFIX="):
            return Path(line.split("=", 1)[1])
    raise AssertionError(f"{ENVFILE} names no BBPD_LAMMPS_PREFIX")


def configure(build, *defs, check=True):
    prefix = lammps_prefix()
    cmd = ["cmake", "-S", str(ROOT), "-B", str(build), f"-DLAMMPS_SOURCE_DIR={prefix}/source",
           "-DBBPD_BUILD_TESTS=OFF", *defs]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if check:
        assert proc.returncode == 0, proc.stdout + proc.stderr
    return proc


def build_plugin(build):
    proc = subprocess.run(["cmake", "--build", str(build), "--target", "bbpdplugin", "-j2"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return build / "bbpdplugin.so"


def run_lmp(workdir, script, env_extra):
    prefix = lammps_prefix()
    env = dict(os.environ, **env_extra)
    env["LD_LIBRARY_PATH"] = f"{prefix}/lib:" + env.get("LD_LIBRARY_PATH", "")
    (workdir / "in.test").write_text(script)
    return subprocess.run([str(prefix / "bin" / "lmp"), "-in", "in.test", "-log", "none"],
                          cwd=workdir, env=env, capture_output=True, text=True, timeout=120)


def test_sizes_and_mpi_come_from_the_lammps_package(tmp_path):
    prefix = lammps_prefix()
    out = configure(tmp_path / "b", f"-DLAMMPS_DIR={prefix}/lib/cmake/LAMMPS").stdout
    assert "sizes smallbig, MPI ON" in out
    cache = (tmp_path / "b" / "CMakeCache.txt").read_text()
    assert "LAMMPS_SIZES:STRING=smallbig" in cache


def test_sizes_that_disagree_with_the_lammps_package_stop_configure(tmp_path):
    prefix = lammps_prefix()
    proc = configure(tmp_path / "b", f"-DLAMMPS_DIR={prefix}/lib/cmake/LAMMPS",
                     "-DLAMMPS_SIZES=bigbig", check=False)
    assert proc.returncode != 0
    assert "LAMMPS_SIZES=bigbig but the LAMMPS" in proc.stderr
    assert "built with smallbig" in proc.stderr


def test_unknown_sizes_stop_configure(tmp_path):
    proc = configure(tmp_path / "b", "-DLAMMPS_SIZES=hugehuge", check=False)
    assert proc.returncode != 0
    assert "use one of smallbig;bigbig;smallsmall" in proc.stderr


def test_serial_lammps_builds_against_mpi_stubs(tmp_path):
    configure(tmp_path / "b", "-DBBPD_MPI=OFF")
    flags = (tmp_path / "b" / "CMakeFiles" / "bbpdplugin.dir" / "flags.make").read_text()
    assert "src/STUBS" in flags and "openmpi" not in flags
    assert build_plugin(tmp_path / "b").is_file()


def test_install_puts_the_plugin_on_the_lammps_plugin_path(tmp_path):
    # the plugin of the bootstrap build, installed alone (component 'plugin')
    build = ENVFILE.parent
    proc = subprocess.run(["cmake", "--install", str(build), "--component", "plugin",
                           "--prefix", str(tmp_path / "inst")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    plugdir = tmp_path / "inst" / "lib" / "lammps" / "plugins"
    assert sorted(p.name for p in (tmp_path / "inst").rglob("*") if p.is_file()) == ["bbpdplugin.so"]
    # LAMMPS loads every *plugin.so on LAMMPS_PLUGIN_PATH at start-up: no 'plugin load' needed
    proc = run_lmp(tmp_path, "plugin list\n", {"LAMMPS_PLUGIN_PATH": str(plugdir)})
    assert "pair style plugin bbpd/gaussian" in proc.stdout, proc.stdout + proc.stderr
