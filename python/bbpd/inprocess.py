# SPDX-License-Identifier: GPL-2.0-or-later
"""LAMMPS in this Python process, with bbpdplugin.so loaded: the in-process twin of tools/lmp.

    import bbpd
    lmp = bbpd.lammps()                      # a lammps.lammps instance
    lmp.file("in.script")                    # or lmp.command(...), lmp.commands_string(...)
    phi = lmp.numpy.extract_compute("phi", LMP_STYLE_ATOM, LMP_TYPE_VECTOR)   # NumPy array

Needs LAMMPS's own Python module (``lammps``) and its shared library: ``tools/python`` provides
both from the LAMMPS that ``tools/bootstrap`` built; with your own LAMMPS, install its module
(LAMMPS's CMake target ``install-python``).
"""
import os
from pathlib import Path

PLUGIN = "bbpdplugin.so"
DEFAULT_LAMMPS_VERSION = "20260704"    # as tools/env.sh
QUIET = ["-log", "none", "-screen", "none", "-nocite"]
REPOSITORY = Path(__file__).resolve().parents[2]    # only meaningful in a checkout


def plugin_path(plugin=None):
    """The bbpdplugin.so to load: `plugin`, else $BBPD_PLUGIN (set by tools/python), else the
    checkout's build/lammps-$BBPD_LAMMPS_VERSION/ (tools/bootstrap's build)."""
    if plugin is None:
        plugin = os.environ.get("BBPD_PLUGIN")
    if plugin is None:
        version = os.environ.get("BBPD_LAMMPS_VERSION", DEFAULT_LAMMPS_VERSION)
        plugin = REPOSITORY / "build" / f"lammps-{version}" / PLUGIN
    plugin = Path(plugin)
    if not plugin.is_file():
        raise FileNotFoundError(f"no {PLUGIN} at {plugin}: run tools/bootstrap, or pass "
                                f"plugin='/path/to/{PLUGIN}' (or set BBPD_PLUGIN)")
    return plugin.resolve()


def lammps(plugin=None, cmdargs=None, **kwargs):
    """A ``lammps.lammps`` instance with bbpdplugin.so loaded.

    plugin   path of bbpdplugin.so (default: see plugin_path)
    cmdargs  LAMMPS command-line arguments (default: no log file, no screen output)
    kwargs   passed on to ``lammps.lammps`` (name, comm, ...)

    The repository's potentials/ goes on LAMMPS_POTENTIALS unless that is set already, so
    ``pair_coeff * * kalthoff_winkler_steel.bbpd ...`` finds its file from any folder.
    """
    try:
        import lammps as lammps_module
    except ImportError as exc:
        raise ImportError("LAMMPS's Python module is not importable: run Python through "
                          "tools/python, or install the module of your LAMMPS "
                          "(its CMake target install-python)") from exc
    path = plugin_path(plugin)
    potentials = REPOSITORY / "potentials"
    if potentials.is_dir():
        os.environ.setdefault("LAMMPS_POTENTIALS", str(potentials))
    lmp = lammps_module.lammps(cmdargs=QUIET if cmdargs is None else list(cmdargs), **kwargs)
    lmp.command(f"plugin load {path}")
    if not lmp.has_style("pair", "bbpd/gaussian"):    # LAMMPS only logs a failed load
        lmp.close()
        raise RuntimeError(f"LAMMPS could not load {path}: was it built against this LAMMPS "
                           "(tools/bootstrap; BBPD_LAMMPS_VERSION selects the build)?")
    return lmp
