"""The plugin built with AddressSanitizer (build/asan-VERSION from tools/bootstrap, CMake option
BBPD_SANITIZE) over scenes that exercise its memory handling: atoms with large families
migrating between ranks (pack/unpack_exchange), bonds breaking (rows shifting), notches,
restart files, contact, and the Silling-Askari loop of bbpd/pmb and the */alpha styles (fused
kernels, short-range forces, the state fix). An out-of-bounds access stops LAMMPS with an AddressSanitizer
report, which fails the run. The default suite keeps one small case of each kind; the larger
scenes are marked slow."""
import os
import subprocess

import pytest

from bbpd.runner import ROOT

import test_crack_tip as ct
import test_lps_compat as lc
import test_mpi_restart as mr  # the scenes of those tests (tests/lammps is on pytest's pythonpath)
import test_pmb_compat as pc
import test_reliability as rel
import test_simd_builds as sb
import test_ves_eps_compat as ve

TIMEOUT = 900


@pytest.fixture(scope="module")
def asan():
    version = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
    build = ROOT / "build" / f"asan-{version}"
    assert (build / "bbpd-env.sh").is_file(), f"{build} is missing: run tools/test (tools/bootstrap --for test builds it)"
    # recompiled here too, so that a direct pytest run after a source edit tests the edit
    proc = subprocess.run(["cmake", "--build", str(build), "--target", "bbpdplugin", "-j2"],
                          capture_output=True, text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout + proc.stderr


@pytest.fixture
def sanitized(asan, monkeypatch):
    """tools/lmp runs the sanitizer build with its runtime preloaded"""
    monkeypatch.setenv("BBPD_SANITIZE", "1")


def clean(out):
    assert "AddressSanitizer" not in out
    return out


def test_sanitizer_build_is_the_one_run(sanitized, lmp):
    """tools/lmp loads the plugin of build/asan-VERSION, linked to the sanitizer runtime, and
    preloads that runtime"""
    out = lmp("""variable pre getenv LD_PRELOAD
variable path getenv LD_LIBRARY_PATH
print "PRELOAD ${pre}"
print "PATH ${path}"
plugin load bbpdplugin.so
""").output
    preload = next(l for l in out.splitlines() if l.startswith("PRELOAD "))
    path = next(l for l in out.splitlines() if l.startswith("PATH "))
    assert "libasan" in preload
    plugin_dir = path.split()[1].split(":")[0]
    assert "/build/asan-" in plugin_dir
    ldd = subprocess.run(["ldd", plugin_dir + "/bbpdplugin.so"], capture_output=True, text=True)
    assert "libasan" in ldd.stdout
    assert "Loading plugin: BBPD pair style, Gaussian kernel" in out


def test_migrating_large_families(sanitized, lmp):
    """m = 6 (1150 partners per atom) crossing between 2 ranks: two exchanges."""
    script = rel.migrating_block(14, 6).replace("run 40", "run 20")
    clean(lmp(script, nprocs=2, timeout=TIMEOUT).output)


def test_fracture_restart_two_ranks(sanitized, tmp_path):
    """the 2D Kalthoff-Winkler plate of test_mpi_restart: notch, breaking bonds, migration,
    write_restart on 2 ranks and read_restart on 1"""
    wd = tmp_path / "restarted"
    first, second = mr.restart_scripts("2d", 2, 100)
    clean(mr.run_in(wd, "2d", first, 2))
    clean(mr.run_in(wd, "2d", second, 1))


@pytest.mark.slow
def test_m7_migration(sanitized, lmp):
    clean(lmp(rel.migrating_block(16, 7), nprocs=2, timeout=TIMEOUT).output)


@pytest.mark.slow
@pytest.mark.parametrize("scene", ["3d", "contact"])
def test_scenes_two_ranks(sanitized, tmp_path, scene):
    wd = tmp_path / scene
    clean(mr.run_in(wd, scene, mr.fresh_script(scene, 2, 200), 2))


@pytest.mark.slow
def test_periodic_breaking(sanitized, lmp, tmp_path):
    clean(lmp(rel.straddling_pairs(tmp_path), nprocs=2, timeout=TIMEOUT).output)


def test_crack_tip_two_ranks(sanitized, lmp, tmp_path):
    """compute bbpd/crack/tip gathers the crack atoms of every rank and searches them while the
    crack grows"""
    clean(lmp(ct.scene(dump=False), nprocs=2, timeout=TIMEOUT).output)
    assert (tmp_path / "tip.dat").is_file()


@pytest.mark.parametrize("variant", ["compat", "plain-alpha"])
def test_silling_askari_two_ranks(sanitized, lmp, variant):
    """the shattering cylinder with bbpd/pmb (bonds that act in the step they break, short-range
    forces) and with bbpd/gaussian/alpha and contact, on 2 ranks"""
    clean(lmp(pc.cylinder(variant, steps=150), nprocs=2, timeout=TIMEOUT).output)


@pytest.mark.parametrize("path", [pytest.param(p, marks=sb.needs_path(p)) for p in ("avx2", "avx512")])
@pytest.mark.parametrize("family", ["ves", "eps"])
def test_history_rows_two_ranks(sanitized, lmp, family, path):
    """the shattering cylinder with bbpd/ves and bbpd/eps on 2 ranks and a vector path (auto
    takes the portable loop in this build): the history rows read and write the bonds' history
    whole in rows that lost no partner (masked vector loads and stores at a row's end) and slot
    by slot in rows that did"""
    out = clean(lmp(sb.with_path(ve.cylinder(family, steps=150), path), nprocs=2,
                    timeout=TIMEOUT).output)
    assert f"bond loop: {path} path" in out


def test_lps_two_ranks_and_restart(sanitized, lmp):
    """the shattering cylinder with bbpd/lps on 2 ranks (the dilatation pass and its ghost
    exchange, bonds breaking in the fused loop, the state fix migrating), then read back from
    its restart file"""
    clean(lmp(lc.cylinder(steps=150) + "write_restart state.restart\n", nprocs=2,
              timeout=TIMEOUT).output)
    clean(lmp("plugin load bbpdplugin.so\nread_restart state.restart\nneighbor 0.0010 bin\n"
              "lattice sc 0.0005\nfix 1 all nve\nrun 20\n", nprocs=2, timeout=TIMEOUT).output)
