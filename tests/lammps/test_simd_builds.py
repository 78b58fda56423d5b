"""One plugin, three paths of the bond loops, the same bits.

The default build (BBPD_NATIVE=OFF) holds the portable loop and the AVX2 and AVX-512 kernels,
each compiled for its own instruction set in its own file (src/bbpd_row_paths.h);
`pair_style ... simd` forces a path or (auto, the default) times the paths the CPU runs and
takes the fastest. These tests check from the machine code that each path's file holds its
instruction set and that no other file holds any wide instruction (the plugin runs on any
x86-64 CPU), that the path files define no symbol another file defines too (the linker would
keep one copy, perhaps the AVX-512 one, for every caller), that every forced path and auto give
the portable loop's bits (the crack scene of test_storage.py with default and compact storage,
the shattering bbpd/pmb cylinder, a rank with 4-byte partner indices), that the log names the
path and why, that a forced path the CPU lacks is an ERROR, and that a restart written on a
forced path reads back (on auto: the keyword is not stored) with the bits of a continuous run. The CPU here may run every
path: the test hook BBPD_SIMD_HIDE (a list of paths) makes the plugin treat the paths it names
as unsupported, as a CPU without them. A build with BBPD_NATIVE=ON (every file compiled with
-march=native) gives the same bits too.
"""
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref

from scenes import sibling

ROOT = Path(__file__).resolve().parents[2]
VERSION = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
DEFAULT_BUILD = ROOT / "build" / f"lammps-{VERSION}"
OBJECTS = DEFAULT_BUILD / "CMakeFiles" / "bbpdplugin.dir" / "src"
PATH_FILES = {"avx2": "bbpd_row_avx2.cpp.o", "avx512": "bbpd_row_avx512.cpp.o"}
storage = sibling("test_storage")
pmb_compat = sibling("test_pmb_compat")
lps_compat = sibling("test_lps_compat")
ves_eps_compat = sibling("test_ves_eps_compat")


def cache_value(key):
    text = (DEFAULT_BUILD / "CMakeCache.txt").read_text()
    return re.search(rf"^{key}:\w+=(.*)$", text, re.M).group(1)


def build_variant(name, flags):
    """Configure and build the plugin alone into build/<name>-VERSION with the cmake flags
    given; returns the .so path."""
    folder = ROOT / "build" / f"{name}-{VERSION}"
    configure = ["cmake", "-S", str(ROOT), "-B", str(folder),
                 "-D", f"LAMMPS_SOURCE_DIR={cache_value('LAMMPS_SOURCE_DIR')}",
                 "-D", f"LAMMPS_DIR={cache_value('LAMMPS_DIR')}",
                 "-D", "BBPD_BUILD_TESTS=OFF"] + flags
    for cmd in (configure, ["cmake", "--build", str(folder), "--target", "bbpdplugin", "-j",
                            str(os.cpu_count() or 1)]):
        proc = subprocess.run(cmd, capture_output=True, text=True)
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return folder / "bbpdplugin.so"


def disassembly(path):
    return subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(path)],
                          capture_output=True, text=True, check=True).stdout


def host_has(*flags):
    text = Path("/proc/cpuinfo").read_text()
    return all(re.search(rf"\b{f}\b", text) for f in flags)


# what each path needs of the CPU (src/bbpd_row_paths.cpp asks cpuid for the same)
NEEDS = {"portable": (), "avx2": ("avx2", "fma"),
         "avx512": ("avx2", "fma", "avx512f", "avx512vl", "avx512bw", "avx512dq")}


def needs_path(path):
    return pytest.mark.skipif(not host_has(*NEEDS[path]), reason=f"the CPU cannot run {path}")


def with_path(script, path, plugin=None):
    """the script with 'simd PATH' on its bbpd pair style (and another plugin if given)"""
    if path:
        script, n = re.subn(r"^(pair_style\s+bbpd/.*)$", rf"\1 simd {path}", script, count=1,
                            flags=re.M)
        assert n == 1
    if plugin:
        script = re.sub(r"^plugin load\s+bbpdplugin.so", f"plugin load {plugin}", script, flags=re.M)
    return script


TWO_VOLUMES = ("set group all volume 1e-9", "set group all volume 1e-9\n"
               "region top block INF INF 10.5 INF INF INF\nset region top volume 1.1e-9")


def crack_state(lmp, tmp_path, path, bond_storage="fast", volumes=1, plugin=None):
    """Final state of the crack scene of test_storage.py, with the log; with compact storage
    the kernel compares cached lengths alone (one volume) or lengths, volumes and types (two)."""
    script = storage.SCENE.format(kernel="gaussian", storage=bond_storage)
    if volumes == 2:
        script = script.replace(*TWO_VOLUMES)
    out = lmp(with_path(script, path, plugin)).output
    notch, final = storage.broken_counts(out)
    assert final > notch + 100    # a crack grew
    return (tmp_path / "final.dump").read_text(), out


def cylinder_state(lmp, tmp_path, path, plugin=None):
    """Final state of the shattering bbpd/pmb cylinder (the Silling-Askari loop: the fused
    force-and-stretch kernel on a SIMD path, a stretch pass and the force loop on the portable
    one)."""
    lmp(with_path(pmb_compat.cylinder("compat"), path, plugin) +
        "write_dump all custom cyl.dump id x y z vx vy vz c_1 modify sort id "
        "format float %.17g\n")
    return (tmp_path / "cyl.dump").read_text()


def far_partners_state(lmp, tmp_path, path):
    """Final state of a run whose rows beside the middle line keep 4-byte partner indices and the
    others offsets (unsorted atoms: partners out of an offset's reach; test_storage.py), with
    bonds breaking."""
    script = storage.FAR_PARTNERS.format(sort="0", storage="fast")
    assert 16.0 < storage.storage_bytes(lmp(with_path(script, path)).output) < 17.0
    return (tmp_path / "final.dump").read_text()


# a band of atoms whose bonds never break along the bottom edge: rows of one critical stretch (the
# band's, infinite, and the plate's) run the SIMD kernels, rows beside the band the portable loop
NO_FAIL_BAND = (("create_box 1 box", "create_box 2 box"),
                ("create_atoms 1 box", "create_atoms 1 box\nregion band block INF INF INF 3 INF INF\n"
                 "set region band type 2"),
                ("pair_coeff 1 1 190e9 6.9e3 0.005", "pair_coeff 1 1 190e9 6.9e3 0.005\n"
                 "pair_coeff 1 2 190e9 none 0.005\npair_coeff 2 2 190e9 none 0.005"))


def band_state(lmp, tmp_path, path):
    """Final state of the crack scene with a no-fail band (two critical stretches)"""
    script = storage.SCENE.format(kernel="gaussian", storage="fast")
    for old, new in NO_FAIL_BAND:
        assert old in script
        script = script.replace(old, new)
    notch, final = storage.broken_counts(lmp(with_path(script, path)).output)
    assert final > notch + 100    # a crack grew
    return (tmp_path / "final.dump").read_text()


def all_indices_state(lmp, tmp_path, path):
    """Final state of the unsorted 3D slab of test_storage.py, whose rank keeps indices alone"""
    script = storage.SLAB.format(sort="sort 0 0.0")
    assert storage.storage_bytes(lmp(with_path(script, path)).output) == 20.0
    return (tmp_path / "final.dump").read_text()


def states(lmp, tmp_path, path):
    return {"crack": crack_state(lmp, tmp_path, path)[0],
            "compact": crack_state(lmp, tmp_path, path, "compact")[0],
            "compact, two volumes": crack_state(lmp, tmp_path, path, "compact", volumes=2)[0],
            "cylinder": cylinder_state(lmp, tmp_path, path),
            "far partners": far_partners_state(lmp, tmp_path, path),
            "all indices": all_indices_state(lmp, tmp_path, path),
            "no-fail band": band_state(lmp, tmp_path, path)}


# a periodic LPS block set moving until bonds break: its rows are decided from local lengths
# with a margin and, near breaking, from the canonical ones (PairBBPD::breaking_length)
PERIODIC_LPS = """plugin load bbpdplugin.so
atom_style peri
units si
boundary p p p
atom_modify map array
lattice sc 0.0005
region box block 0 10 0 10 0 10 units lattice
create_box 1 box
create_atoms 1 box
pair_style bbpd/lps 3d
pair_coeff * * 14.9e9 14.9e9 0.0015001 0.0005 0.25
set group all density 2200
set group all volume 1.25e-10
variable L equal 0.005
variable vx atom 1.5*sin(2*PI*x/v_L)+0.5*sin(2*PI*y/v_L)
variable vy atom 1.5*sin(2*PI*z/v_L)
variable vz atom 1.5*sin(2*PI*x/v_L)
velocity all set v_vx v_vy v_vz units box
compute 1 all bbpd/damage/atom
compute dmean all reduce ave c_1
thermo_style custom step pe ke c_dmean
thermo 300
write_dump all custom start.dump id x y z modify sort id format float %.17g
fix 1 all nve
timestep 1.0e-7
run 300
"""


def state_based_states(lmp, tmp_path, path):
    """Final states of the state-based rows (dilatation and force passes): the shattering LPS,
    VES and EPS cylinders (free boundaries) and the periodic LPS block, bonds breaking in each"""
    scripts = {"lps cylinder": lps_compat.cylinder(),
               "ves cylinder": ves_eps_compat.cylinder("ves"),
               "eps cylinder": ves_eps_compat.cylinder("eps"),
               "lps periodic": PERIODIC_LPS}
    found = {}
    for scene, script in scripts.items():
        out = lmp(with_path(script, path) + lps_compat.END_DUMP).output
        assert ref.thermo_tables(out)[-1]["c_dmean"][-1] > 0.005, scene    # bonds broke
        found[scene] = (tmp_path / "end.dump").read_text()
    return found


@pytest.fixture(scope="module")
def portable_state_based(tmp_path_factory):
    from bbpd.runner import run_lammps
    wd = tmp_path_factory.mktemp("portable-state-based")
    return state_based_states(lambda s: run_lammps(s, workdir=wd), wd, "portable")


@pytest.fixture(scope="module")
def portable_states(tmp_path_factory):
    from bbpd.runner import run_lammps
    wd = tmp_path_factory.mktemp("portable")
    return states(lambda s: run_lammps(s, workdir=wd), wd, "portable")


def loop_line(out):
    m = re.search(r"^  bond loop: (\w+) path \((.*)\)$", out, re.M)
    assert m, "the setup report names the path of the bond loops"
    return m.group(1), m.group(2)


# ---------------------------------------------------------------------- the plugin's files

@pytest.fixture(scope="module")
def objects():
    if cache_value("BBPD_NATIVE").upper() in ("ON", "TRUE", "1", "YES"):
        pytest.skip("the default build was configured with BBPD_NATIVE=ON")
    found = sorted(OBJECTS.glob("*.o"))
    assert found, f"no object files in {OBJECTS}"
    return {p.name: p for p in found}


def test_each_path_file_holds_its_instruction_set_alone(objects):
    for path, name in PATH_FILES.items():
        assert name in objects, f"the default build must hold the {path} path ({name})"
    avx512, avx2 = (disassembly(objects[PATH_FILES[p]]) for p in ("avx512", "avx2"))
    assert "%zmm" in avx512
    assert "%ymm" in avx2 and "%zmm" not in avx2
    # every other file is baseline x86-64: no VEX or EVEX instruction (mnemonics v...), so the
    # plugin loads and runs its portable path on any x86-64 CPU
    vex = re.compile(r"^\s*[0-9a-f]+:\s+v[a-z0-9]+\s", re.M)
    for name, obj in objects.items():
        if name not in PATH_FILES.values():
            code = disassembly(obj)
            assert not vex.search(code), f"{name} holds a VEX/EVEX instruction: {vex.search(code).group(0)}"


def defined_symbols(obj):
    out = subprocess.run(["nm", "--defined-only", "--extern-only", str(obj)], capture_output=True,
                         text=True, check=True).stdout
    return {line.split()[-1] for line in out.splitlines() if line.strip()}


def test_path_files_define_no_symbol_another_file_defines(objects):
    """An inline function emitted by a path file and by another file is one symbol to the
    linker, which keeps either copy for every caller: the portable code could then run an
    AVX-512 copy. So a path file's symbols must be its own (its kernels' templates)."""
    others = {}
    for name, obj in objects.items():
        for s in defined_symbols(obj):
            others.setdefault(s, set()).add(name)
    for name in PATH_FILES.values():
        shared = {s: sorted(others[s] - {name}) for s in defined_symbols(objects[name])
                  if others[s] - {name}}
        assert not shared, f"{name} shares symbols with other files: {shared}"


# ---------------------------------------------------------------------- the same bits

EVERY_PATH = [pytest.param("avx2", marks=needs_path("avx2")),
              pytest.param("avx512", marks=needs_path("avx512")), "auto"]


def assert_portable_bits(got, portable, path):
    for scene, state in portable.items():
        assert got[scene] == state, f"{scene}: simd {path} differs from simd portable"


@pytest.mark.parametrize("path", EVERY_PATH)
def test_every_path_gives_the_portable_bits(lmp, tmp_path, portable_states, path):
    assert_portable_bits(states(lmp, tmp_path, path), portable_states, path)


@pytest.mark.parametrize("path", EVERY_PATH)
def test_state_based_rows_give_the_portable_bits(lmp, tmp_path, portable_state_based, path):
    assert_portable_bits(state_based_states(lmp, tmp_path, path), portable_state_based, path)


def test_periodic_lps_block_is_the_same_on_1_2_4_ranks(lmp, tmp_path):
    """bonds decided near breaking from the canonical lengths: the same bits on any rank count
    (atoms ordered by their starting positions: create_atoms numbers them by rank)"""
    ends = []
    for nprocs in (1, 2, 4):
        lmp(PERIODIC_LPS + lps_compat.END_DUMP, nprocs=nprocs)
        ends.append(lps_compat.end_state(tmp_path))
    for other in ends[1:]:
        for key in lps_compat.KEYS:
            np.testing.assert_array_equal(ends[0][key], other[key])


def test_native_build_gives_the_portable_bits(lmp, tmp_path, portable_states):
    plugin = build_variant("native", ["-D", "BBPD_NATIVE=ON"])
    assert crack_state(lmp, tmp_path, "auto", plugin=plugin)[0] == portable_states["crack"]
    assert cylinder_state(lmp, tmp_path, "auto", plugin=plugin) == portable_states["cylinder"]


# ---------------------------------------------------------------------- choice and errors

SMALL = storage.SCENE.format(kernel="gaussian", storage="fast")


def test_log_names_the_path_and_why(lmp):
    path, why = loop_line(lmp(with_path(SMALL, "portable")).output)
    assert (path, why) == ("portable", "forced by the simd keyword")
    path, why = loop_line(lmp(SMALL).output)    # the default: auto
    runnable = [p for p in ("avx512", "avx2") if host_has(*NEEDS[p])]
    if runnable:
        assert why.startswith("auto: the fastest over "), why
        for p in runnable + ["portable"]:
            assert f"{p} " in why, f"auto timed {p}: {why}"
        times = {p: float(t) for p, t in re.findall(r"(\w+) ([0-9.eE+-]+) ms", why)}
        assert path == min(times, key=times.get)


@pytest.mark.parametrize("style", ["lps", "ves", "eps"])
def test_state_based_styles_report_their_path(lmp, style):
    """the LPS rows run on the path asked for, and the report says so (it once named the path
    while the rows ran the portable loop whatever 'simd' said)"""
    from test_bad_input import BASE_3D, script
    extra = {"lps": "", "ves": " 0.5 1.0e-3", "eps": " 1.0e8"}[style]
    text = script(BASE_3D, pair_style=f"pair_style bbpd/{style} 3d",
                  pair_coeff=f"pair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25{extra}")
    for path in ("portable",) + tuple(p for p in ("avx2", "avx512") if host_has(*NEEDS[p])):
        assert loop_line(lmp(with_path(text, path)).output) == (path, "forced by the simd keyword")
    path, why = loop_line(lmp(text).output)
    assert why.startswith("auto: ") and path in ("portable", "avx2", "avx512")


def test_silling_askari_kernel_styles_report_their_path(lmp):
    """bbpd/KERNEL/alpha runs the path asked for (its rules once left out the field that said
    it had SIMD rows, and it ran the portable loop whatever 'simd' said)"""
    from test_bad_input import script
    text = script(pair_style="pair_style bbpd/triangular/alpha plane/strain thickness 0.001",
                  pair_coeff="pair_coeff * * 190.0e9 6.9e4 0.003015 alpha 0.25")
    for path in ("portable",) + tuple(p for p in ("avx2", "avx512") if host_has(*NEEDS[p])):
        assert loop_line(lmp(with_path(text, path)).output) == (path, "forced by the simd keyword")


def test_auto_takes_only_paths_the_cpu_runs(lmp, monkeypatch):
    monkeypatch.setenv("BBPD_SIMD_HIDE", "avx512,avx2")
    assert loop_line(lmp(SMALL).output) == ("portable", "auto: the only path every rank's CPU runs")
    monkeypatch.setenv("BBPD_SIMD_HIDE", "avx512")
    path, why = loop_line(lmp(SMALL).output)
    assert path in ("avx2", "portable") and "avx512" not in why


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("path", ["avx2", "avx512"])
def test_forced_path_the_cpu_lacks_is_an_error(lmp, monkeypatch, path, nprocs):
    monkeypatch.setenv("BBPD_SIMD_HIDE", path)
    proc = lmp(with_path(SMALL, path), nprocs=nprocs, check=False)
    assert proc.returncode != 0
    assert proc.error and f"simd {path} needs a CPU with" in proc.error, proc.output[-2000:]
    assert "hidden by the environment variable BBPD_SIMD_HIDE" in proc.error
    assert "use simd auto or one of portable" in proc.error


mpi_restart = sibling("test_mpi_restart")


@needs_path("avx2")
def test_restart_written_on_a_forced_path_reads_back_on_auto(tmp_path):
    """The simd keyword is not in the restart file (the CPU that reads it may lack the path):
    a run written with simd avx2 and read back continues on auto, with the continuous run's bits."""
    scene, half = "2d", 100
    ref_dir = tmp_path / "continuous"
    ref_out = mpi_restart.run_in(ref_dir, scene, mpi_restart.fresh_script(scene, 1, 2 * half), 1)
    first, second = mpi_restart.restart_scripts(scene, 1, half)
    wd = tmp_path / "restarted"
    out1 = mpi_restart.run_in(wd, scene, with_path(first, "avx2"), 1)
    out2 = mpi_restart.run_in(wd, scene, second, 1)
    assert loop_line(out1) == ("avx2", "forced by the simd keyword")
    assert loop_line(out2)[1].startswith("auto: ")
    assert mpi_restart.final_state(wd, out2) == mpi_restart.final_state(ref_dir, ref_out)
