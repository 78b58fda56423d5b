"""A new bond model is a change in one place (doc/architecture.rst, "Adding a bond model").

The plugin is built again with the toy breaking rule of tests/unit/toy_bond_models.h in place of
the default one (cmake -D BBPD_TEST_BOND_MODEL=SymmetricStretchBond: the critical stretch holds
in compression as in tension), with no other change to the sources. A plate stretched by 3 %
along x, with a critical stretch of 1 %, breaks the same bonds in both builds, bit for bit (the
rest of the model is untouched); squeezed by 3 %, it keeps every bond with the default model and
loses with the toy one as many bonds as the stretch broke (a bond at angle t to x has stretch
about -0.03 cos^2 t).
"""
import re

import pytest

from scenes import peri_preamble, sibling

builds = sibling("test_simd_builds")

TOY = ["-D", "BBPD_NATIVE=ON", "-D", "BBPD_TEST_BOND_MODEL=SymmetricStretchBond"]
S0 = 0.01
# 3 %: no bond of the family (offsets up to 4 spacings) has a stretch within 0.0007 of the
# critical one in either direction (the nearest: offset (2, 3), cos^2 t = 4/13, 0.0093 and
# -0.0091), so the second-order difference of pulling and squeezing moves none across it
STRAIN = 0.03
LENGTH = 0.02    # m: 20 spacings

SCENE = peri_preamble(2, lattice="sq 0.001") + f"""\
region box block 0 20 0 10 -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density 7800
set group all volume 1e-9
pair_style bbpd/constant plane/stress thickness 0.001
pair_coeff 1 1 190e9 none 0.0035 critical_stretch {S0}
fix 1 all nve
fix 2 all enforce2d
timestep 1e-8
thermo_style custom step pe
thermo_modify format float %.17g
run 0
displace_atoms all ramp x 0 {{dx}} x 0 {LENGTH} units box
run 0
run 0
write_dump all custom final.dump id x y fx fy modify format float %.17g sort id
"""


def broken(out):
    """bonds broken at the last setup report (printed before that evaluation breaks any: the
    scene's second 'run 0' breaks them, its third reports them)"""
    return int(re.findall(r"total bonds \d+ \((\d+) broken\)", out)[-1])


def state(lmp, tmp_path, strain, plugin=None):
    script = SCENE.format(dx=strain * LENGTH)
    if plugin is not None:
        script = script.replace("plugin load bbpdplugin.so", f"plugin load {plugin}")
    out = lmp(script).output
    return broken(out), (tmp_path / "final.dump").read_text()


@pytest.fixture(scope="module")
def toy_plugin():
    return builds.build_variant("toy-bond-model", TOY)


def test_toy_rule_changes_compression_alone(lmp, tmp_path, toy_plugin):
    pulled_default, pulled_dump = state(lmp, tmp_path, STRAIN)
    pulled_toy, pulled_toy_dump = state(lmp, tmp_path, STRAIN, toy_plugin)
    assert pulled_default > 0 and pulled_toy == pulled_default
    assert pulled_toy_dump == pulled_dump    # same bonds, same forces: the rest is untouched
    squeezed_default, _ = state(lmp, tmp_path, -STRAIN)
    squeezed_toy, squeezed_dump = state(lmp, tmp_path, -STRAIN, toy_plugin)
    assert squeezed_default == 0
    # the toy rule breaks in compression the bonds it breaks in tension (the lattice is
    # symmetric under x -> -x strain sign, bond by bond)
    assert squeezed_toy == pulled_default
    assert squeezed_dump != pulled_dump
