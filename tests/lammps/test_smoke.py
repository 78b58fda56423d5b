"""The plugin loads and registers every style, serially, under MPI and in the compatibility build."""
import pytest

STYLES = ["pair style plugin bbpd/constant", "pair style plugin bbpd/triangular",
          "pair style plugin bbpd/gaussian", "fix style plugin bbpd/notch",
          "compute style plugin bbpd/damage/atom", "compute style plugin bbpd/dsif",
          "compute style plugin bbpd/jintegral", "compute style plugin bbpd/crack/tip"]

SCRIPT = "plugin load bbpdplugin.so\nplugin list\n"


@pytest.mark.parametrize("nprocs", [1, 2])
def test_plugin_lists_styles(lmp, nprocs):
    out = lmp(SCRIPT, nprocs=nprocs).output
    for style in STYLES:
        assert style in out


def test_compat_build_lists_styles(lmp):
    out = lmp(SCRIPT, version="20250204").output
    assert "LAMMPS (4 Feb 2025" in out
    for style in STYLES:
        assert style in out
