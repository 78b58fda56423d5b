# SPDX-License-Identifier: GPL-2.0-or-later
"""How big a run fits: examples/big-run/in.big at a few block sizes on several MPI ranks, with
the memory per atom (peak RSS of every rank, /usr/bin/time) and per bond and the cost per step;
examples/big-run/README.md describes the measures and has the commands.
"""

import re
import subprocess
from pathlib import Path

from bbpd import readers
from bbpd.runner import LMP, MPIRUN, error_line
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "big-run" / "in.big"
TIME = "/usr/bin/time"
# each rank under /usr/bin/time, its peak RSS (kB) into rss.RANK.txt (Open MPI names the rank)
RANK_WRAPPER = f'exec {TIME} -f %M -o rss.$OMPI_COMM_WORLD_RANK.txt "$0" "$@"'
KB = 1024.0
MBYTES = 1024.0 * 1024.0             # LAMMPS's Mbytes


def parse(output, rss_kb=()):
    """The numbers of one run's output (screen) and its ranks' peak RSS in kB."""
    atoms = int(re.search(r"^BIG: n \d+ atoms (\d+)", output, re.M)[1])
    bonds = int(re.search(r"total bonds (\d+)", output)[1])
    mine = re.search(r"memory of the bonds and the pair style: (\S+) Mbytes on the largest rank, "
                     r"(\S+) in all: (\S+) bytes per atom, (\S+) per bond", output)
    per_rank = re.search(r"Per MPI rank memory allocation \(min/avg/max\) = (\S+) \| (\S+) \| "
                         r"(\S+) Mbytes", output)
    loop, ranks = readers.loop_time(output)
    steps = int(re.search(r"Loop time of \S+ on \d+ procs for (\d+) steps", output)[1])
    sections = {m[1]: float(m[2]) for m in
                re.finditer(r"^(Pair|Output|Modify)\s*\|\s*\S+\s*\|\s*(\S+)", output, re.M)}
    rss = [kb * KB for kb in rss_kb]
    return {"atoms": atoms, "bonds": bonds, "ranks": ranks, "steps": steps,
            "bonds_pair_mb": float(mine[2]), "bonds_pair_bytes_per_atom": float(mine[3]),
            "bonds_pair_bytes_per_bond": float(mine[4]),
            "lammps_mb_per_rank": float(per_rank[2]),
            "lammps_bytes_per_atom": float(per_rank[2]) * MBYTES * ranks / atoms,
            "rss_bytes": sum(rss), "rss_ranks": len(rss),
            "loop_s_per_step": loop / steps, "pair_s_per_step": sections["Pair"] / steps,
            "step_s_without_output": (loop - sections["Output"]) / steps,
            "output_s": sections["Output"], "modify_s": sections["Modify"]}


def run(n, workdir, nprocs=2, steps=None, restart=True):
    """in.big with n points per edge on nprocs ranks in workdir; parse() of its output."""
    workdir = Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    for old in workdir.glob("rss.*.txt"):
        old.unlink()
    cmd = MPIRUN + ["-np", str(nprocs), "sh", "-c", RANK_WRAPPER, str(LMP), "-in",
                    str(EXAMPLE), "-var", "n", str(n), "-var", "restart",
                    "yes" if restart else "no"]
    if steps is not None:
        cmd += ["-var", "steps", str(steps)]
    proc = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True)
    out = proc.stdout + proc.stderr
    (workdir / "output.txt").write_text(out)
    err = error_line(out)
    if err or proc.returncode:
        raise RuntimeError(f"in.big n = {n}: {err or f'exit status {proc.returncode}'}")
    rss_kb = [int(f.read_text().split()[-1]) for f in sorted(workdir.glob("rss.*.txt"))]
    return parse(out, rss_kb)


def margin(small, large):
    """Bytes of peak RSS per additional atom and per additional bond between two runs."""
    rss = large["rss_bytes"] - small["rss_bytes"]
    return (rss / (large["atoms"] - small["atoms"]), rss / (large["bonds"] - small["bonds"]))


def fits(runs, memory_bytes):
    """Atoms that fit into memory_bytes by the margin of the two largest runs."""
    small, large = runs[-2], runs[-1]
    per_atom, _ = margin(small, large)
    return int(large["atoms"] + (memory_bytes - large["rss_bytes"]) / per_atom)


def main():
    ap = cli.parser(__doc__, "/tmp/big-run", nprocs=2)
    ap.add_argument("--n", type=int, nargs="+", default=[40, 60, 80],
                    help="points per edge of each block (default 40 60 80)")
    ap.add_argument("--memory-gb", type=float, default=None,
                    help="memory to extrapolate to, GB (default: MemAvailable of /proc/meminfo)")
    args = ap.parse_args()
    runs = []
    print("n atoms bonds | peak RSS MB (all ranks) | LAMMPS MB/rank | bonds+pair B/atom B/bond "
          "| s/step: loop, without output, pair | restart output s")
    for n in args.n:
        r = run(n, Path(args.work) / f"n{n}", nprocs=args.nprocs)
        runs.append(r)
        print(f"{n} {r['atoms']} {r['bonds']} | {r['rss_bytes'] / MBYTES:.1f} | "
              f"{r['lammps_mb_per_rank']:.1f} | {r['bonds_pair_bytes_per_atom']:.0f} "
              f"{r['bonds_pair_bytes_per_bond']:.1f} | {r['loop_s_per_step']:.4f} "
              f"{r['step_s_without_output']:.4f} {r['pair_s_per_step']:.4f} | "
              f"{r['output_s']:.2f}", flush=True)
    if len(runs) > 1:
        per_atom, per_bond = margin(runs[-2], runs[-1])
        available = (args.memory_gb * 1e9 if args.memory_gb else available_bytes())
        print(f"margin: {per_atom:.0f} bytes of peak RSS per atom, {per_bond:.1f} per bond; "
              f"{available / 1e9:.1f} GB hold about {fits(runs, available):.3g} atoms")


def available_bytes():
    """MemAvailable of /proc/meminfo, in bytes"""
    text = Path("/proc/meminfo").read_text()
    return int(re.search(r"^MemAvailable:\s+(\d+) kB", text, re.M)[1]) * KB


if __name__ == "__main__":
    main()
