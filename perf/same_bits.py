#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Same bits before and after a refactoring: run a fixed set of small scenes with one plugin
build and keep their logs and full-precision dumps; compare two such folders file by file.

The scenes are the inputs of the LAMMPS tests (tests/lammps), at their test sizes (1-5 s each,
about a minute in all on the 2-core machine): fracture in 2D and 3D on 1 and 2 ranks, contact,
write_restart/read_restart (1 -> 2 ranks, also with compact storage and two types), compact
storage and the per-bond loop, the ported peri/pmb cylinder (bbpd/pmb, compact, two types,
the Silling-Askari rule of bbpd/gaussian/alpha, 2 ranks, restart, a periodic box), bonds
breaking across a periodic boundary, the ported peri/lps cylinder (bbpd/lps) and the LPS kernel
styles breaking (bbpd/lps/KERNEL), the ported peri/ves (1 rank) and peri/eps (2 ranks)
cylinders, and the computes bbpd/dsif and bbpd/jintegral with E and nu inverted from c0. Each run ends with a `run 0` that prints pe, ke and pressure at %.17g.

Usage (from the repository root):
  tools/python perf/same_bits.py run [--build DIR] OUT [--scenes a,b]   # DIR: a plugin build
  tools/python perf/same_bits.py compare REF OUT    # exit 1 if any differ (scenes of OUT only)
  tools/python perf/same_bits.py list
DIR is a folder with bbpdplugin.so and bbpd-env.sh (default: build/lammps-20260704 of this
checkout, what tools/bootstrap builds). OUT gets, per scene, the input scripts, the logs with
their timing lines (and the source lines of warnings) taken out, and the dumps. Record a
reference with an unmodified build first, then `run` the changed build into another folder and
`compare`.
"""
import argparse
import filecmp
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TESTS = ROOT / "tests" / "lammps"
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]
# appended to every run: the energies and the pressure (virial) of the final state, full
# precision (a `run 0` evaluates them whatever the script's thermo_style)
TOTALS = "thermo_style custom step pe ke press\nthermo_modify format float %.17g\nrun 0\n"


def _test_module(name):
    """a file of tests/lammps as a module (the scenes are its inputs), registered under its
    name, so that the test files that import it by name (pytest.ini's pythonpath) find it"""
    if name != "refmodel":    # the test files' helper, which they import by name
        _test_module("refmodel")
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, TESTS / f"{name}.py")
        sys.modules[name] = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(sys.modules[name])
    return sys.modules[name]


def _scenes():
    """{name: [(script, ranks, data writer or None), ...]}: the runs of a scene share a folder;
    a data writer writes the scene's data file into the folder it is given"""
    if (TESTS / "scenes.py").is_file():    # the test files' scene builder, where there is one
        _test_module("scenes")
    mr = _test_module("test_mpi_restart")
    rm = _test_module("test_restart_more")
    st = _test_module("test_storage")
    pc = _test_module("test_pmb_compat")
    rl = _test_module("test_reliability")
    jt = _test_module("test_jintegral")
    lc = _test_module("test_lps_compat")
    _test_module("test_bad_input")    # test_ves_eps_compat imports it by name
    ve = _test_module("test_ves_eps_compat")
    lk = _test_module("test_lps_kernels")

    def atoms_data(write):
        return lambda folder: write(folder / "atoms.data")

    def fresh(scene, n, steps):
        return [(mr.fresh_script(scene, n, steps), n, atoms_data(mr.SCENES[scene]["data"]))]

    def restarted(scene):
        _, first, second = rm.script_pair(scene)
        return [(first, 1, atoms_data(rm.SCENES[scene]["data"])), (second, 2, None)]

    def cylinder(variant, steps=300):
        return pc.cylinder(variant, steps) + ("write_dump all custom end.dump id x y z vx vy vz "
                                              "c_1 modify sort id format float %.17g\n")

    def cylinder_restart():
        script = pc.EXAMPLE.read_text().replace("variable        scale index 1",
                                                "variable        scale index 0.6")
        tail = script.split("fix             1 all nve", 1)[1]
        first = script.replace("variable        steps index 1000",
                               "variable        steps index 150") + "write_restart state.restart\n"
        second = ("plugin load bbpdplugin.so\nread_restart state.restart\nneighbor 0.0010 bin\n"
                  "lattice sc 0.0005\nvariable steps index 150\nfix 1 all nve" + tail
                  + "write_dump all custom end.dump id x y z vx vy vz c_1 modify sort id "
                  "format float %.17g\n")
        return [(first, 1, None), (second, 2, None)]

    def pairs(alpha, n):
        # straddling_pairs writes its data file into the folder it is given
        def data(folder):
            rl.straddling_pairs(folder, alpha=alpha)
        with tempfile.TemporaryDirectory() as tmp:
            script = rl.straddling_pairs(Path(tmp), alpha=alpha)
        return [(script, n, data)]

    def computes(model):
        lines = {"J": "tip 0.0 0.0", "Js": "tip 0.0 0.0 rin 6 rout 15 E 7.1e10 nu 0.3"}
        script = "plugin load bbpdplugin.so\n" + jt.williams_script(model)
        script += "".join(f"compute {n} all bbpd/jintegral {a}\n" for n, a in lines.items())
        script += ("compute K all bbpd/dsif tip 0.0 0.0\n"
                   "compute Ks all bbpd/dsif tip 0.0 0.0 r1 1.5 r2 3.5 E 7.1e10 nu 0.3\n"
                   "thermo_style custom step c_J[1] c_J[2] c_J[3] c_Js[1] c_K[1] c_K[2] c_Ks[1]\n"
                   "run 0\n")
        for n, values in (("J", 3), ("Js", 3), ("K", 2), ("Ks", 2)):
            script += f'print "{n}' + "".join(f" $(c_{n}[{k}]:%.17g)" for k in
                                               range(1, values + 1)) + '"\n'
        return [(script, 1, None)]

    def lps_kernel(kernel, model, n):
        # run_head writes its data file into the folder it is given
        def data(folder):
            lk.run_head(folder, kernel, model)
        with tempfile.TemporaryDirectory() as tmp:
            script = lk.run_head(Path(tmp), kernel, model)
        return [(script + f"fix 1 all nve\nrun {lk.RUN_STEPS}\n" + _test_module("scenes").END_DUMP, n, data)]

    storage = st.SCENE.format
    two_types = storage(kernel="gaussian", storage="compact").replace(
        "create_box 1 box", "create_box 2 box").replace(
        "pair_coeff 1 1 190e9 6.9e3 0.005", "pair_coeff 1 1 190e9 6.9e3 0.005\n"
        "pair_coeff 2 2 150e9 5e3 0.005\npair_coeff 1 2 170e9 6e3 0.005").replace(
        "set group all volume 1e-9", "set group all volume 1e-9\n"
        "region top block INF INF 10.5 INF INF INF\nset region top type 2")
    return {
        "fracture2d-np1": fresh("2d", 1, 200),
        "fracture2d-np2": fresh("2d", 2, 200),
        "fracture3d-np1": fresh("3d", 1, 200),
        "fracture3d-np2": fresh("3d", 2, 200),
        "contact-np1": fresh("contact", 1, 400),
        "contact-np2": fresh("contact", 2, 400),
        "restart2d-1to2": restarted("types"),
        "restart-compact-1to2": restarted("compact"),
        "storage-fast-triangular": [(storage(kernel="triangular", storage="fast"), 1, None)],
        "storage-compact-gaussian": [(storage(kernel="gaussian", storage="compact"), 1, None)],
        "storage-compact-two-types": [(two_types, 1, None)],
        "storage-per-bond": [(st.IRREGULAR.format(kernel="gaussian", storage="fast"), 1, None)],
        "pmb-compat-np1": [(cylinder("compat"), 1, None)],
        "pmb-compat-np2": [(cylinder("compat"), 2, None)],
        "pmb-compact": [(cylinder("compact"), 1, None)],
        "pmb-two-types": [(cylinder("two-types"), 1, None)],
        "alpha-np1": [(cylinder("plain-alpha"), 1, None)],
        "alpha-np2": [(cylinder("plain-alpha"), 2, None)],
        "pmb-restart-1to2": cylinder_restart(),
        "pmb-periodic-np2": [(pc.periodic_cylinder("compat") + "write_dump all custom end.dump "
                              "id x y z vx vy vz c_1 modify sort id format float %.17g\n", 2,
                              None)],
        "periodic-pairs-np1": pairs(False, 1),
        "periodic-pairs-alpha-np2": pairs(True, 2),
        "computes-plane-strain": computes("plane/strain"),
        "computes-plane-stress": computes("plane/stress"),
        "lps-cylinder-np1": [(lc.cylinder() + lc.END_DUMP, 1, None)],
        "lps-cylinder-np2": [(lc.cylinder() + lc.END_DUMP, 2, None)],
        "lps-gaussian-plane-strain-np2": lps_kernel("gaussian", "plane/strain", 2),
        "lps-constant-3d-np1": lps_kernel("constant", "3d", 1),
        "ves-cylinder-np1": [(ve.cylinder("ves") + lc.END_DUMP, 1, None)],
        "eps-cylinder-np2": [(ve.cylinder("eps") + lc.END_DUMP, 2, None)],
    }


# timing and host lines of a LAMMPS log; the table after 'MPI task timing breakdown' goes whole
TIMING = re.compile(r"^(Loop time of|Performance:|.*% CPU use with|Total wall time:|"
                    r"Section \||-{20,}|(Pair|Bond|Neigh|Comm|Output|Modify|Other|Kspace)\s+\|)")


# the seconds that read_data, create_atoms, read_restart, ... report
SECONDS = re.compile(r" CPU = \S+ seconds")
# the SIMD path that simd auto timed fastest, and its timings: every path gives the same bits, so
# which one won is machine noise
AUTO_PATH = re.compile(r"bond loop: \S+ path \(auto: .*")
# the source line of a WARNING or ERROR (moves with any edit of the file)
SOURCE_LINE = re.compile(r"(\.(?:cpp|h)):\d+\)")


def strip_timing(text):
    """the log without what changes from run to run or with an edit that moves lines"""
    lines = []
    for line in text.splitlines():
        line = SOURCE_LINE.sub(r"\1:-)", SECONDS.sub(" CPU = - seconds", line))
        line = AUTO_PATH.sub("bond loop: - path (auto: timed)", line)
        if TIMING.match(line):
            if line.startswith("Loop time of"):    # keep ranks, steps and atoms
                line = re.sub(r"Loop time of \S+", "Loop time of -", line)
            else:
                continue
        lines.append(line)
    return "\n".join(lines) + "\n"


def lammps_env(build):
    """the environment tools/lmp would give, with the plugin of `build`"""
    env_file = build / "bbpd-env.sh"
    if not (build / "bbpdplugin.so").is_file() or not env_file.is_file():
        sys.exit(f"same_bits: {build} holds no bbpdplugin.so and bbpd-env.sh (build it first)")
    settings = dict(re.findall(r"^(\w+)=(.*)$", env_file.read_text(), re.M))
    prefix = Path(settings["BBPD_LAMMPS_PREFIX"])
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = f"{build}:{prefix / 'lib'}" + (
        f":{env['LD_LIBRARY_PATH']}" if env.get("LD_LIBRARY_PATH") else "")
    env["LAMMPS_POTENTIALS"] = str(ROOT / "potentials")
    env["OMP_NUM_THREADS"] = "1"
    return prefix / "bin" / "lmp", env


def run_scene(name, runs, lmp, env, out):
    dest = out / name
    dest.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix=f"same_bits_{name}_") as tmp:
        work = Path(tmp)
        for k, (script, ranks, data) in enumerate(runs, start=1):
            if data is not None:
                data(work)
            (work / f"in.{k}").write_text(script + TOTALS)
            cmd = [str(lmp), "-in", f"in.{k}", "-log", f"log.{k}", "-screen", "none"]
            if ranks > 1:
                cmd = MPIRUN + ["-np", str(ranks)] + cmd
            proc = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True)
            log = work / f"log.{k}"
            if proc.returncode != 0 or not log.is_file():
                tail = log.read_text()[-2000:] if log.is_file() else ""
                sys.exit(f"same_bits: {name} run {k} failed:\n{tail}{proc.stdout[-2000:]}"
                         f"{proc.stderr[-2000:]}")
            (dest / f"log.{k}").write_text(strip_timing(log.read_text()))
            shutil.copy(work / f"in.{k}", dest / f"in.{k}")
        for dump in sorted(work.glob("*.dump")):
            shutil.copy(dump, dest / dump.name)


def compare(ref, out):
    """(files compared, files that differ or exist on one side only, scenes of ref not run in
    out); a scene run with --scenes is compared with the same scene of ref"""
    run = {p.name for p in out.iterdir() if p.is_dir()}
    skipped = sorted(p.name for p in ref.iterdir() if p.is_dir() and p.name not in run)
    diffs = []
    names = sorted({p.relative_to(ref) for p in ref.rglob("*")
                    if p.is_file() and p.relative_to(ref).parts[0] in run}
                   | {p.relative_to(out) for p in out.rglob("*") if p.is_file()})
    for rel in names:
        a, b = ref / rel, out / rel
        if not a.is_file() or not b.is_file():
            diffs.append(f"{rel}: only in {ref if a.is_file() else out}")
        elif not filecmp.cmp(a, b, shallow=False):
            # logs written by an older version of this script: strip them again
            ta, tb = a.read_text(), b.read_text()
            if rel.name.startswith("log."):
                ta, tb = strip_timing(ta), strip_timing(tb)
                if ta == tb:
                    continue
            first = next((i for i, (x, y) in enumerate(zip(ta.splitlines(), tb.splitlines()), 1)
                          if x != y), None)
            diffs.append(f"{rel}: differs" + (f" from line {first}" if first else " in length"))
    return names, diffs, skipped


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="cmd", required=True)
    run = sub.add_parser("run", help="run the scenes with one build")
    run.add_argument("out", type=Path)
    run.add_argument("--build", type=Path, default=ROOT / "build" / "lammps-20260704")
    run.add_argument("--scenes", help="comma-separated subset (default: all)")
    cmp_ = sub.add_parser("compare", help="compare two folders written by run")
    cmp_.add_argument("ref", type=Path)
    cmp_.add_argument("out", type=Path)
    sub.add_parser("list", help="print the scene names")
    args = parser.parse_args()

    if args.cmd == "compare":
        names, diffs, skipped = compare(args.ref, args.out)
        for d in diffs:
            print(d)
        print(f"{len(names) - len(diffs)} of {len(names)} files identical"
              + (f"; {len(skipped)} scenes of {args.ref} not run" if skipped else ""))
        sys.exit(1 if diffs else 0)
    scenes = _scenes()
    if args.cmd == "list":
        print("\n".join(scenes))
        return
    chosen = args.scenes.split(",") if args.scenes else list(scenes)
    unknown = sorted(set(chosen) - set(scenes))
    if unknown:
        sys.exit(f"same_bits: unknown scenes {unknown}; `list` prints them")
    lmp, env = lammps_env(args.build.resolve())
    for name in chosen:
        print(name, flush=True)
        run_scene(name, scenes[name], lmp, env, args.out.resolve())


if __name__ == "__main__":
    main()
