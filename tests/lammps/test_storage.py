"""Storage modes and code paths give the same bits: bond/storage compact (12 bytes per bond) vs
the default (a class per bond into a table of distinct pairs, 16 bytes per bond) and its
per-bond fallback (44 bytes per bond), partners as 2-byte offsets vs 4-byte indices (4 bytes
more per bond), and the SIMD force kernel vs the portable loop that also tallies energy.

The scene is a small Kalthoff-Winkler plate with G_c / 10 (6.9e3 J/m^2): the notch cuts 1159
bonds and a crack grows from its tip during the 300 steps (measured: 1479 broken at the end), so
every comparison includes bonds that break during the run.
"""
import re

import pytest

from bbpd.runner import LammpsError
from scenes import impact_plate, peri_preamble

SCENE = peri_preamble(2, lattice="sq 0.001") + """\
region box block 0 40 0 20 -0.5 0.5
create_box 1 box
create_atoms 1 box
""" + impact_plate("bbpd/{kernel} plane/strain thickness 0.001 bond/storage {storage}",
                "6.9e3") + """\
fix n all bbpd/notch segment 0.02 0.0095 0.03 0.0095
compute d all bbpd/damage/atom
compute pe all pe/atom
timestep 8.7e-8
thermo 50
run 300
write_dump all custom final.dump id x y vx vy c_d c_pe modify format float %.17g sort id
run 0
"""


NOTCH_CUT = 1159    # bonds the notch cuts in SCENE


def broken_counts(out):
    """(broken bonds at the first setup, at the last) from the setup reports"""
    counts = [int(b) for b in re.findall(r"total bonds \d+ \((\d+) broken\)", out)]
    assert counts[0] == NOTCH_CUT
    return counts[0], counts[-1]


@pytest.mark.parametrize("kernel", ["triangular", "gaussian"])
def test_compact_storage_is_bit_identical(lmp, tmp_path, kernel):
    dumps, outs = {}, {}
    for storage in ("fast", "compact"):
        out = lmp(SCENE.format(kernel=kernel, storage=storage)).output
        dumps[storage] = (tmp_path / "final.dump").read_text()
        outs[storage] = out
    assert "bond storage: 16.0 bytes per bond" in outs["fast"]
    assert "bond storage: 12.0 bytes per bond" in outs["compact"]
    notch, final = broken_counts(outs["fast"])
    assert final > notch + 100    # a crack grew: bonds broke during the run
    assert broken_counts(outs["compact"]) == (notch, final)
    assert dumps["fast"] == dumps["compact"]


def test_compact_storage_with_two_types_is_bit_identical(lmp, tmp_path):
    """Two types with their own critical stretches take the portable loop, whose compact
    storage looks coefficients up by the partner's type: the same bits as the default."""
    dumps, outs = {}, {}
    for storage in ("fast", "compact"):
        script = SCENE.format(kernel="gaussian", storage=storage).replace(
            "create_box 1 box", "create_box 2 box").replace(
            "pair_coeff 1 1 190e9 6.9e3 0.005", "pair_coeff 1 1 190e9 6.9e3 0.005\n"
            "pair_coeff 2 2 150e9 5e3 0.005\npair_coeff 1 2 170e9 6e3 0.005").replace(
            "set group all volume 1e-9", "set group all volume 1e-9\n"
            "region top block INF INF 10.5 INF INF INF\nset region top type 2")
        outs[storage] = lmp(script).output
        dumps[storage] = (tmp_path / "final.dump").read_text()
    assert "bond storage: 12.0 bytes per bond" in outs["compact"]
    notch, final = broken_counts(outs["fast"])
    assert final > notch + 100
    assert dumps["fast"] == dumps["compact"]


def test_compact_storage_with_two_volumes_is_bit_identical(lmp, tmp_path):
    """Atoms of two volumes: compact storage keys its coefficients by the partner volume too (the
    SIMD kernel compares lengths alone only where every atom has one type and one volume), and
    gives the bits of the default."""
    dumps = {}
    for storage in ("fast", "compact"):
        script = SCENE.format(kernel="gaussian", storage=storage).replace(
            "set group all volume 1e-9", "set group all volume 1e-9\n"
            "region top block INF INF 10.5 INF INF INF\nset region top volume 1.1e-9")
        out = lmp(script).output
        notch, final = broken_counts(out)
        assert final > notch + 100
        dumps[storage] = (tmp_path / "final.dump").read_text()
    assert dumps["fast"] == dumps["compact"]


# atoms at random positions: every bond has its own reference length, more distinct pairs than
# a 2-byte class addresses
IRREGULAR = SCENE.replace("region box block 0 40 0 20", "region box block 0 40 0 40").replace(
    "create_atoms 1 box", "create_atoms 1 random 1600 4711 box overlap 0.0006 maxtry 1000").replace(
    "timestep 8.7e-8", "timestep 4e-8")


def test_per_bond_fallback_is_bit_identical(lmp, tmp_path):
    """A rank with more distinct (reference length, coefficient) pairs than classes keeps them
    per bond: the same bits as compact storage."""
    dumps, outs = {}, {}
    for storage in ("fast", "compact"):
        outs[storage] = lmp(IRREGULAR.format(kernel="gaussian", storage=storage)).output
        dumps[storage] = (tmp_path / "final.dump").read_text()
    assert "bond storage: 44.0 bytes per bond" in outs["fast"]
    assert "bond storage: 12.0 bytes per bond" in outs["compact"]
    broken = [int(b) for b in re.findall(r"total bonds \d+ \((\d+) broken\)", outs["fast"])]
    assert broken[-1] > broken[0] + 100    # bonds broke during the run
    assert dumps["fast"] == dumps["compact"]


# 201 x 171 atoms created top half first, then bottom half: unsorted (atom_modify sort 0), the
# atoms just above the middle line come first in memory and their partners below it about 34,000
# entries later, beyond a 2-byte offset, so the rows beside the middle line keep 4-byte partner
# indices (and the others offsets); LAMMPS's spatial sort brings them within reach of offsets.
# The notch cuts along the middle line.
FAR_PARTNERS = peri_preamble(2, lattice="sq 0.001", atom_modify="sort {sort} 0.0") + """\
region box block 0 200 0 170 -0.5 0.5
create_box 1 box
region top block INF INF 84.5 INF INF INF
region bottom block INF INF INF 84.5 INF INF
create_atoms 1 region top
create_atoms 1 region bottom
""" + impact_plate("bbpd/gaussian plane/strain thickness 0.001 bond/storage {storage}",
                "6.9e3") + """\
fix n all bbpd/notch segment 0.0 0.0845 0.03 0.0845
timestep 8.7e-8
thermo 100
run 300
write_dump all custom final.dump id x y vx vy modify format float %.17g
run 0
"""


def by_position(dump):
    """the atom rows of a dump (x y vx vy as printed), in the order of their positions (tags
    depend on the rank count: create_atoms numbers atoms rank by rank)"""
    rows = [line.split()[1:] for line in dump.split("ITEM: ATOMS")[1].splitlines()[1:] if line]
    return sorted(rows, key=lambda r: (round(float(r[1]), 6), round(float(r[0]), 6)))


def storage_bytes(out):
    """bytes per bond of the bond storage, from the first setup report"""
    return float(re.search(r"bond storage: ([0-9.]+) bytes per bond", out).group(1))


def test_partner_indices_give_the_bits_of_offsets(lmp, tmp_path):
    """Partners out of a 2-byte offset's reach: the rows beside the middle line store 4-byte
    indices, the others offsets, and give the bits of offsets alone (sorted atoms, and 2 ranks),
    with bonds breaking during the run; compact storage with indices gives them too."""
    # on 2 ranks the unsorted atoms are within reach again (half as many per rank): offsets,
    # with ghost partners
    runs = {("offsets", 1): ("1000", "fast", 1), ("indices", 1): ("0", "fast", 1),
            ("unsorted", 2): ("0", "fast", 2), ("compact indices", 1): ("0", "compact", 1)}
    dumps, outs = {}, {}
    for key, (sort, storage, nprocs) in runs.items():
        outs[key] = lmp(FAR_PARTNERS.format(sort=sort, storage=storage), nprocs=nprocs).output
        dumps[key] = by_position((tmp_path / "final.dump").read_text())
    assert storage_bytes(outs[("offsets", 1)]) == 16.0
    assert storage_bytes(outs[("unsorted", 2)]) == 16.0
    # some rows with indices (4 bytes more per bond for them), most with offsets
    assert 16.0 < storage_bytes(outs[("indices", 1)]) < 17.0
    assert 12.0 < storage_bytes(outs[("compact indices", 1)]) < 13.0
    broken = [int(b) for b in re.findall(r"total bonds \d+ \((\d+) broken\)", outs[("offsets", 1)])]
    assert broken[-1] > broken[0] + 100    # bonds broke during the run
    for key in runs:
        assert dumps[key] == dumps[("offsets", 1)], key


def test_compact_storage_rejects_periodic_boundaries(lmp):
    script = SCENE.format(kernel="gaussian", storage="compact").replace("boundary s s p",
                                                                       "boundary p s p")
    with pytest.raises(LammpsError, match="bond/storage compact does not support periodic"):
        lmp(script)


def test_bond_storage_value_is_checked(lmp):
    with pytest.raises(LammpsError, match="bond/storage must be 'fast'"):
        lmp(SCENE.format(kernel="gaussian", storage="tiny"))


def test_energy_steps_do_not_change_the_trajectory(lmp, tmp_path):
    """Thermo on every step runs the portable energy-tallying loop; thermo at the end runs the
    SIMD kernel (AVX-512 or AVX2 where the build has it): both must give the same bits."""
    dumps = {}
    for every in (1, 300):
        script = SCENE.format(kernel="gaussian", storage="fast").replace("thermo 50",
                                                                         f"thermo {every}")
        out = lmp(script).output
        dumps[every] = (tmp_path / "final.dump").read_text()
        notch, final = broken_counts(out)
        assert final > notch + 100
    assert dumps[1] == dumps[300]


@pytest.mark.parametrize("storage", ["fast", "compact"])
def test_openmp_threads_give_the_same_trajectory(lmp, tmp_path, storage):
    """Threads split the atoms of the force loop (each sums only its own bonds; with compact
    storage each has its own coefficient cache): 1 and 2 threads give the same bits, with bonds
    breaking and energy tallied every step."""
    dumps = {}
    for threads in (1, 2):
        script = SCENE.format(kernel="gaussian", storage=storage).replace(
            "units si", f"package omp {threads}\nunits si").replace("thermo 50", "thermo 1")
        out = lmp(script).output
        assert f"1 MPI tasks x {threads} OpenMP threads" in out
        notch, final = broken_counts(out)
        assert final > notch + 100
        dumps[threads] = (tmp_path / "final.dump").read_text()
    assert dumps[1] == dumps[2]


def test_compact_storage_follows_new_coefficients(lmp, tmp_path):
    """Compact storage caches coefficients per thread: a pair_coeff issued between runs (a
    stiffer material) must reach them, as it reaches the default storage."""
    dumps = {}
    for storage in ("fast", "compact"):
        script = SCENE.format(kernel="gaussian", storage=storage).replace(
            "run 300\n", "run 100\npair_coeff 1 1 380e9 6.9e3 0.005\nrun 100\n")
        lmp(script)
        dumps[storage] = (tmp_path / "final.dump").read_text()
    assert dumps["fast"] == dumps["compact"]


# A 3D slab of 121 x 301 x 2 atoms (spacing 1 mm, horizon 3 mm), unsorted: every atom has
# partners in the other layer, 36,421 atoms away in memory, beyond a 2-byte offset: every row
# needs indices and the rank keeps them alone (20 bytes per bond, not the 22 that offsets beside
# indices would cost). Sorted in bins thinner than half the slab (the input's 0.4 mm) the layers
# fall in different bin layers, as far apart; in bins of the family cutoff, which the bond fix
# chooses when the input does not, they share one bin layer and every partner is within an
# offset's reach.
SLAB = peri_preamble(3, lattice="sc 0.001", atom_modify="{sort}") + """region box block 0 120 0 300 0 1
create_box 1 box
create_atoms 1 box
set group all density 7800
set group all volume 1e-9
pair_style bbpd/constant 3d
pair_coeff 1 1 190e9 6.9e3 0.003
neighbor 0.001 bin
fix n all bbpd/notch rectangle 0.02 0.1495 -1 0.04 0 0 0 0 3
region left block INF 3 INF INF INF INF
group left region left
velocity left set 32 0 0 units box
fix 1 all nve
timestep 8.7e-8
run 40
write_dump all custom final.dump id x y z vx vy vz modify format float %.17g
run 0
"""


def by_position_3d(dump):
    rows = [line.split()[1:] for line in dump.split("ITEM: ATOMS")[1].splitlines()[1:] if line]
    return sorted(rows, key=lambda r: (round(float(r[2]), 6), round(float(r[1]), 6),
                                       round(float(r[0]), 6)))


def test_sort_bins_of_the_family_cutoff_keep_3d_partners_within_offsets(lmp, tmp_path):
    """An unsorted slab needs indices in every row and keeps them alone; the input's thin sort
    bins put the slab's layers in two bin layers, also indices; the bins the bond fix chooses
    give offsets throughout. The same bits in all three, with bonds breaking."""
    runs = {"unsorted": "sort 0 0.0", "input bins": "sort 1000 0.0004", "chosen bins": ""}
    outs, dumps = {}, {}
    for key, sort in runs.items():
        outs[key] = lmp(SLAB.format(sort=sort)).output
        dumps[key] = by_position_3d((tmp_path / "final.dump").read_text())
    assert storage_bytes(outs["unsorted"]) == 20.0
    assert "atoms sorted in bins of the family cutoff" in outs["chosen bins"]
    assert storage_bytes(outs["input bins"]) == 20.0
    assert "atoms sorted in bins" not in outs["unsorted"] + outs["input bins"]
    assert storage_bytes(outs["chosen bins"]) == 16.0
    broken = [int(b) for b in re.findall(r"total bonds \d+ \((\d+) broken\)", outs["chosen bins"])]
    assert broken[-1] > broken[0]
    for key in runs:
        assert dumps[key] == dumps["chosen bins"], key


def test_slab_same_bits_on_1_2_and_4_ranks(lmp, tmp_path):
    """The 3D slab in the bins the bond fix chooses, with a notch through it and a band that
    never breaks (two critical stretches: rows of one run the SIMD kernels, rows beside the band
    the portable loop), on 1, 2 and 4 ranks: every rank count gives the same bits."""
    script = SLAB.format(sort="")
    for old, new in (("create_box 1 box", "create_box 2 box"),
                     ("create_atoms 1 box", "create_atoms 1 box\nregion band block INF INF INF 5 INF INF\n"
                      "set region band type 2"),
                     ("pair_coeff 1 1 190e9 6.9e3 0.003", "pair_coeff 1 1 190e9 6.9e3 0.003\n"
                      "pair_coeff 1 2 190e9 none 0.003\npair_coeff 2 2 190e9 none 0.003")):
        assert old in script
        script = script.replace(old, new)
    dumps, outs = {}, {}
    for n in (1, 2, 4):
        outs[n] = lmp(script, nprocs=n).output
        dumps[n] = by_position_3d((tmp_path / "final.dump").read_text())
    assert storage_bytes(outs[1]) == 16.0
    assert storage_bytes(outs[4]) < 17.0    # the largest rank's
    broken = [int(b) for b in re.findall(r"total bonds \d+ \((\d+) broken\)", outs[4])]
    assert broken[-1] > broken[0]
    assert dumps[2] == dumps[1] and dumps[4] == dumps[1]
