# SPDX-License-Identifier: GPL-2.0-or-later
"""What produced the report: the LAMMPS build, the plugin version, the source revision and the
machine (CPU, cores, OS)."""
import os
import platform
import re
import subprocess
from pathlib import Path

from bbpd.jobs import ROOT


def lammps_build():
    """First line of `tools/lmp -h` (the LAMMPS version) and its MPI line."""
    try:
        out = subprocess.run([str(ROOT / "tools" / "lmp"), "-h"], capture_output=True,
                             text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError) as exc:
        return f"unknown ({exc})"
    version = re.search(r"Simulator - (.+)", out)
    mpi = re.search(r"^MPI v\S+: (Open MPI v[^,]+|[^,\n]+)", out, re.M)
    return ", ".join(x for x in ((version[1].strip() if version else None),
                                 (mpi[1].strip() if mpi else None)) if x) or "unknown"


def plugin_version():
    m = re.search(r"project\(\s*bbpd\s+VERSION\s+(\S+)", (ROOT / "CMakeLists.txt").read_text())
    return m[1] if m else "unknown"


def git_revision():
    try:
        out = subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"],
                             capture_output=True, text=True, timeout=30)
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def vector_isa(flags):
    """The widest vector instruction set of the CPU flags (what the plugin's -march=native
    build uses: its force loops have AVX-512, AVX2 and portable forms)."""
    return "AVX-512" if "avx512f" in flags else "AVX2" if "avx2" in flags else "no AVX2"


def _cpuinfo():
    """(model name, {'cpu family': .., 'model': ..}, flags) of the first CPU in /proc/cpuinfo"""
    model, numbers, flags = platform.processor() or "unknown CPU", {}, set()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            key, _, value = (s.strip() for s in line.partition(":"))
            if key == "model name" and model in ("unknown CPU", platform.processor()):
                model = value
            elif key in ("cpu family", "model"):
                numbers.setdefault(key, value)
            elif key == "flags" and not flags:
                flags = set(value.split())
    except OSError:
        pass
    return model, numbers, flags


def cpu():
    """'CPU model (family F model M), ISA' for the timing columns of the benchmarks' CSVs: a
    model name alone may not tell the generation apart (AMD EPYC: Zen 3 and Zen 4)"""
    model, numbers, flags = _cpuinfo()
    ident = f" (family {numbers['cpu family']} model {numbers['model']})" if len(numbers) == 2 else ""
    return f"{model}{ident}, {vector_isa(flags)}"


def machine():
    """'CPU model (vector ISA), N cores, OS': timings depend on all three."""
    model, _, flags = _cpuinfo()
    name = f"{model} ({vector_isa(flags)})" if flags else model
    osname = platform.platform()
    try:
        rel = dict(re.findall(r'^(\w+)="?([^"\n]*)"?', Path("/etc/os-release").read_text(), re.M))
        osname = f"{rel.get('PRETTY_NAME', osname)}, Linux {platform.release()}"
    except OSError:
        pass
    return f"{name}, {os.cpu_count()} cores, {osname}"
