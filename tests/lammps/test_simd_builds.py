"""The three force kernels give the same bits: AVX-512, AVX2 and the portable loop.

src/bbpd_row.h picks the kernel at compile time from the target's macros: AVX-512
(__AVX512F__ and __AVX512VL__) before AVX2 (__AVX2__), else the portable loop
(row_force_portable). The default build (-march=native) on an AVX-512 host therefore never runs the
AVX2 kernel. This test builds the plugin again with -mno-avx512f (the AVX2 kernel; in the
default suite) and without -march=native (the portable loop; slow), into build/, checks from
the machine code which kernel each build holds (zmm registers for AVX-512, ymm for AVX2), and
compares the final state of a run in which a crack grows (the scene of test_storage.py) with
the default build's, bit for bit.
"""
import importlib.util
import os
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
VERSION = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
DEFAULT_BUILD = ROOT / "build" / f"lammps-{VERSION}"

_spec = importlib.util.spec_from_file_location("bbpd_test_storage",
                                               Path(__file__).with_name("test_storage.py"))
storage = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(storage)
_spec = importlib.util.spec_from_file_location("bbpd_test_pmb_compat",
                                               Path(__file__).with_name("test_pmb_compat.py"))
pmb_compat = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(pmb_compat)

VARIANTS = {"avx2": ["-D", "BBPD_NATIVE=ON", "-D", "CMAKE_CXX_FLAGS=-mno-avx512f"],
            "portable": ["-D", "BBPD_NATIVE=OFF"]}


def cache_value(key):
    text = (DEFAULT_BUILD / "CMakeCache.txt").read_text()
    return re.search(rf"^{key}:\w+=(.*)$", text, re.M).group(1)


def build_variant(name, flags=None):
    """Configure and build the plugin alone into build/<name>-VERSION with the cmake flags of
    VARIANTS[name] (or the flags given); returns the .so path."""
    folder = ROOT / "build" / f"{name}-{VERSION}"
    configure = ["cmake", "-S", str(ROOT), "-B", str(folder),
                 "-D", f"LAMMPS_SOURCE_DIR={cache_value('LAMMPS_SOURCE_DIR')}",
                 "-D", f"LAMMPS_DIR={cache_value('LAMMPS_DIR')}",
                 "-D", "BBPD_BUILD_TESTS=OFF"] + (VARIANTS[name] if flags is None else flags)
    for cmd in (configure, ["cmake", "--build", str(folder), "--target", "bbpdplugin", "-j",
                            str(os.cpu_count() or 1)]):
        proc = subprocess.run(cmd, capture_output=True, text=True)
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return folder / "bbpdplugin.so"


def registers(path):
    """(zmm used, ymm used) in the machine code of a shared object."""
    code = subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(path)],
                          capture_output=True, text=True, check=True).stdout
    return "%zmm" in code, "%ymm" in code


def host_has(flag):
    return re.search(rf"\b{flag}\b", Path("/proc/cpuinfo").read_text()) is not None


TWO_VOLUMES = ("set group all volume 1e-9", "set group all volume 1e-9\n"
               "region top block INF INF 10.5 INF INF INF\nset region top volume 1.1e-9")


def final_state(lmp, tmp_path, plugin, bond_storage="fast", volumes=1):
    """Final state of the crack scene of test_storage.py; with compact storage the kernel
    compares cached lengths alone (one volume) or lengths, volumes and types (two volumes)."""
    script = storage.SCENE.format(kernel="gaussian", storage=bond_storage)
    if volumes == 2:
        script = script.replace(*TWO_VOLUMES)
    if plugin is not None:
        script = script.replace("plugin load bbpdplugin.so", f"plugin load {plugin}")
    out = lmp(script).output
    notch, final = storage.broken_counts(out)
    assert final > notch + 100    # a crack grew
    return (tmp_path / "final.dump").read_text(), final


def cylinder_state(lmp, tmp_path, plugin=None):
    """Final state of the shattering bbpd/pmb cylinder (the Silling-Askari loop: a fused
    force-and-stretch pass with AVX-512, a stretch pass and the force kernel otherwise)."""
    script = pmb_compat.cylinder("compat")
    if plugin is not None:
        script = script.replace("plugin load     bbpdplugin.so", f"plugin load     {plugin}")
    lmp(script + "write_dump all custom cyl.dump id x y z vx vy vz c_1 modify sort id "
        "format float %.17g\n")
    return (tmp_path / "cyl.dump").read_text()


def far_partners_state(lmp, tmp_path, plugin=None):
    """Final state of a run whose rank keeps 4-byte partner indices (unsorted atoms: partners
    out of an offset's reach; test_storage.py), with bonds breaking."""
    script = storage.FAR_PARTNERS.format(sort="0", storage="fast")
    if plugin is not None:
        script = script.replace("plugin load bbpdplugin.so", f"plugin load {plugin}")
    assert "bond storage: 20.0 bytes per bond" in lmp(script).output    # indices, not offsets
    return (tmp_path / "final.dump").read_text()


@pytest.fixture(scope="module")
def default_state(tmp_path_factory):
    from bbpd.runner import run_lammps
    wd = tmp_path_factory.mktemp("default")
    out = run_lammps(storage.SCENE.format(kernel="gaussian", storage="fast"), wd).output
    return (wd / "final.dump").read_text(), storage.broken_counts(out)[1]


@pytest.mark.skipif(not host_has("avx2"), reason="the host has no AVX2")
def test_avx2_kernel_gives_the_default_bits(lmp, tmp_path, default_state):
    plugin = build_variant("avx2")
    zmm, ymm = registers(plugin)
    assert not zmm and ymm, "the -mno-avx512f build must hold the AVX2 kernel"
    if host_has("avx512f") and host_has("avx512vl"):
        assert registers(DEFAULT_BUILD / "bbpdplugin.so")[0], \
            "the default build on an AVX-512 host must hold the AVX-512 kernel"
    assert final_state(lmp, tmp_path, plugin) == default_state
    assert cylinder_state(lmp, tmp_path, plugin) == cylinder_state(lmp, tmp_path)
    assert far_partners_state(lmp, tmp_path, plugin) == far_partners_state(lmp, tmp_path)
    # compact storage runs in the AVX2 kernel too
    assert final_state(lmp, tmp_path, plugin, "compact") == default_state
    assert final_state(lmp, tmp_path, plugin, "compact", volumes=2) == \
        final_state(lmp, tmp_path, None, "fast", volumes=2)


@pytest.mark.slow
def test_portable_loop_gives_the_default_bits(lmp, tmp_path, default_state):
    plugin = build_variant("portable")
    zmm, ymm = registers(plugin)
    assert not zmm and not ymm, "a build without -march=native must hold the portable loop"
    assert final_state(lmp, tmp_path, plugin) == default_state
    assert cylinder_state(lmp, tmp_path, plugin) == cylinder_state(lmp, tmp_path)
    assert far_partners_state(lmp, tmp_path, plugin) == far_partners_state(lmp, tmp_path)
    assert final_state(lmp, tmp_path, plugin, "compact", volumes=2) == \
        final_state(lmp, tmp_path, None, "fast", volumes=2)
