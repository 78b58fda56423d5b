# SPDX-License-Identifier: GPL-2.0-or-later
"""Run our LAMMPS build (tools/lmp) on an input script, serially or under mpirun."""
import json
import os
import subprocess
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LMP = ROOT / "tools" / "lmp"

MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]
# the examples' pictures (dump image, their variable images): for a person watching a crack,
# not for the scripted runs, which read the dumps; vars={"images": "yes"} turns them on
IMAGES_OFF = {"images": "no"}


class LammpsError(RuntimeError):
    """LAMMPS stopped with an ERROR line; .message holds it."""

    def __init__(self, message, output):
        super().__init__(message)
        self.message = message
        self.output = output

    def __reduce__(self):    # picklable, so it can cross a process pool
        return (type(self), (self.message, self.output))


def error_line(output):
    """The first 'ERROR' line LAMMPS printed, or None."""
    for line in output.splitlines():
        if line.startswith("ERROR") or "ERROR on proc" in line:
            return line.strip()
    return None


def run_or_reuse(script, workdir, vars, nprocs=1, timeout=1800, reuse=False):
    """(LAMMPS's output, wall time in s) of a run of script in workdir, or with reuse=True the
    log.lammps an earlier run left there (measured again without running LAMMPS)"""
    start = time.perf_counter()
    if reuse:
        output = (Path(workdir) / "log.lammps").read_text()
    else:
        output = run_lammps(str(script), workdir, nprocs=nprocs, vars=vars, timeout=timeout).output
    return output, time.perf_counter() - start


def run_noted(script, workdir, vars, case, nprocs=1, reuse=False, timeout=1800):
    """Run script in workdir, unless reuse and an earlier run finished there, and note the case
    (a dict) with the run's wall time and ranks in workdir/case.json; returns that note: what
    measuring the folder again needs without running it."""
    note = Path(workdir) / "case.json"
    if not (reuse and note.is_file()):
        start = time.perf_counter()
        run_lammps(str(script), workdir, nprocs=nprocs, vars=vars, timeout=timeout)
        note.write_text(json.dumps(dict(case, wall_s=time.perf_counter() - start, nprocs=nprocs)))
    return json.loads(note.read_text())


def run_lammps(script, workdir, nprocs=1, version=None, check=True, vars=None, timeout=1800,
               log="log.lammps"):
    """Write `script` to workdir/in.lammps and run it; raise LammpsError on an ERROR if check.
    vars: LAMMPS index variables (-var NAME VALUE); images is "no" unless given."""
    workdir = Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    infile = workdir / "in.lammps"
    if "\n" in script or not Path(script).is_file():
        infile.write_text(script)
    else:
        infile = Path(script)
    cmd = [str(LMP), "-in", str(infile.resolve()), "-log", log]
    for k, v in {**IMAGES_OFF, **(vars or {})}.items():
        cmd += ["-var", str(k), str(v)]
    if nprocs > 1:
        cmd = MPIRUN + ["-np", str(nprocs)] + cmd
    env = dict(os.environ)
    if version:
        env["BBPD_LAMMPS_VERSION"] = str(version)
    proc = subprocess.run(cmd, cwd=workdir, env=env, capture_output=True, text=True,
                          timeout=timeout)
    out = proc.stdout + proc.stderr
    err = error_line(out)
    if check and (err or proc.returncode != 0):
        raise LammpsError(err or f"LAMMPS exited with {proc.returncode}", out)
    proc.output = out
    proc.error = err
    return proc
