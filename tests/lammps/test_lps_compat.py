"""'pair_style bbpd/lps 3d' against LAMMPS's own peri/lps.

Forces: the perturbed 3D block of test_pmb_compat.py (reference lattice from a data file at
%.17g, so both styles start from the same doubles; three atoms pushed towards a neighbour so
that the short-range force acts), after a first 'run 0' has built the families and the
weighted volumes at the reference positions. The two styles sum the same terms in different
orders (peri/lps in neighbour-list order with its own grouping of the products, ours in the
order of the reference offsets), so they agree to round-off, not bitwise.

The runs: LAMMPS's examples/peri/in.peri.lps ported (examples/peri-lps-dropin), smaller, on
1, 2 and 4 ranks and across write_restart/read_restart.
"""
from pathlib import Path

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from test_pmb_compat import (DELTA, DENSITY, DX, PERTURBATION, SEED, block, perturbed, run_forces,
                              short_range_pairs)

BULK = 14.9e9       # the peri/lps example's K and G
SHEAR = 14.9e9
S00_ELASTIC = 0.5   # nothing breaks under the perturbation
ALPHA = 0.25
FORCE_RTOL = 1.0e-12    # of the largest force: different summation order only
NUMBERS = f"{BULK!r} {SHEAR!r} {DELTA!r} {S00_ELASTIC!r} {ALPHA!r}"
ENERGY = "thermo_style custom step pe\nthermo_modify format float %.17g\n"


def pe_of(out):
    return ref.thermo_tables(out)[-1]["PotEng"][-1]


@pytest.mark.parametrize("boundary", ["s s s", "p p p"])
def test_forces_equal_peri_lps(lmp, tmp_path, boundary):
    """bbpd/lps gives peri/lps's forces (LPS bonds with the volume ramp, weighted volumes,
    dilatations, short-range forces) to 1e-12 of the largest force (measured 4.7e-16) and its
    energy to 1e-12, on 1, 2 and 4 ranks; ours are the same bits on every rank count.

    p p p: a periodic box one lattice period long, every atom bonded across the boundaries.
    There peri/lps differs (measured: 0.38 of the largest force): fix_peri_neigh.cpp sums its
    weighted volume from x0_i - x0_j without the minimum image (its force loop takes it), so a
    bond across the boundary enters m with the length of the box; bbpd/lps takes the minimum
    image in both (test_periodic_difference_is_peri_lps_weighted_volume shows that this is
    where they part). The periodic case checks our rank counts only."""
    periodic = boundary == "p p p"
    x0, box = block(3, periodic)
    y = perturbed(x0, 3)
    assert short_range_pairs(x0, y) >= 3    # the short-range force is exercised
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    out_lps, f_lps = run_forces(lmp, tmp_path, f"pair_style peri/lps\npair_coeff * * {NUMBERS}\n"
                                + ENERGY, plugin=False, boundary=boundary)
    ours = f"pair_style bbpd/lps 3d\npair_coeff * * {NUMBERS}\n" + ENERGY
    results = [run_forces(lmp, tmp_path, ours, plugin=True, nprocs=n, boundary=boundary)
               for n in (1, 2, 4)]
    out1 = results[0][0]
    assert "BBPD pair style bbpd/lps" in out1 and "peri/lps state" in out1
    assert "max 122" in out1    # |xi| <= delta: 122 partners of an interior atom
    scale = np.linalg.norm(f_lps, axis=1).max()
    assert scale > 0.0
    for out, f in ([] if periodic else results):
        err = np.linalg.norm(f - f_lps, axis=1).max() / scale
        print(f"max per-atom force difference to peri/lps: {err:.3g} of the largest force")
        assert err < FORCE_RTOL, f"max per-atom force error {err:.3g} of the largest force"
        e_ref, e = pe_of(out_lps), pe_of(out)
        print(f"energy: peri/lps {e_ref!r}, bbpd/lps {e!r}")
        assert abs(e - e_ref) <= FORCE_RTOL * abs(e_ref)
    for _, f in results[1:]:
        np.testing.assert_array_equal(results[0][1], f)


def test_periodic_difference_is_peri_lps_weighted_volume(lmp, tmp_path):
    """Where peri/lps and bbpd/lps part in a periodic box: a periodic block of 15^3 atoms,
    randomly perturbed. An atom whose partners' families reach across no boundary (its lattice
    indices 6..8: every pair of its partners and their partners is at most 3 spacings apart in
    the raw x0, less than half the box) gets peri/lps's force to 1e-12; elsewhere the forces
    differ by more than 1e-3 of the largest force, as peri/lps's weighted volume of an atom
    bonded across the boundary counts that bond with the raw distance."""
    n = 15
    x0 = refmodel.square_lattice((n, n, n), DX)
    box = [(x0[:, k].min() - 0.5 * DX, x0[:, k].max() + 0.5 * DX) for k in range(3)]
    rng = np.random.default_rng(SEED)
    y = x0 + PERTURBATION * DX * rng.uniform(-1.0, 1.0, x0.shape)
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    _, f_lps = run_forces(lmp, tmp_path, f"pair_style peri/lps\npair_coeff * * {NUMBERS}\n",
                          plugin=False, boundary="p p p")
    _, f = run_forces(lmp, tmp_path, f"pair_style bbpd/lps 3d\npair_coeff * * {NUMBERS}\n",
                      plugin=True, boundary="p p p")
    scale = np.linalg.norm(f_lps, axis=1).max()
    err = np.linalg.norm(f - f_lps, axis=1) / scale
    index = np.rint((x0 - x0.min(axis=0)) / DX).astype(int)
    inner = np.all((index >= 6) & (index <= 8), axis=1)
    assert inner.sum() == 27
    print(f"inner atoms: {err[inner].max():.3g}, all atoms: {err.max():.3g} of the largest force")
    assert err[inner].max() < FORCE_RTOL
    assert err.max() > 1e-3


def test_dilatation_is_needed(lmp, tmp_path):
    """The comparison can fail: bbpd/pmb with peri/lps's short-range stiffness (the PMB c of the
    same K) misses the LPS state and is far from peri/lps's forces."""
    x0, box = block(3)
    y = perturbed(x0, 3)
    refmodel.write_data(tmp_path / "body.data", x0, DX**3, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    _, f_lps = run_forces(lmp, tmp_path, f"pair_style peri/lps\npair_coeff * * {NUMBERS}\n",
                          plugin=False)
    c = 18.0 * BULK / (np.pi * DELTA**4)
    _, f_pmb = run_forces(lmp, tmp_path, f"pair_style bbpd/pmb 3d\npair_coeff * * {c!r} {DELTA!r} "
                          f"{S00_ELASTIC!r} {ALPHA!r}\n", plugin=True)
    scale = np.linalg.norm(f_lps, axis=1).max()
    assert np.linalg.norm(f_pmb - f_lps, axis=1).max() / scale > 1e-3


EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "peri-lps-dropin" / "in.bbpd.lps"
END_DUMP = "write_dump all custom end.dump id x y z vx vy vz c_1 modify sort id format float %.17g\n"
KEYS = ("x", "y", "z", "vx", "vy", "vz", "c_1")


def cylinder(steps=300, scale=0.6):
    """The ported example, smaller and shorter; it dumps the starting positions, by which
    end_state() orders the atoms (create_atoms numbers them differently on 4 ranks)."""
    script = EXAMPLE.read_text()
    for name, value in (("steps", steps), ("scale", scale)):
        line = next(l for l in script.splitlines() if l.startswith(f"variable        {name} index"))
        script = script.replace(line, f"variable        {name} index {value}")
    return script.replace("run             ${steps}", "write_dump all custom start.dump id x y z "
                          "modify sort id format float %.17g\nrun             ${steps}")


def end_state(tmp_path, start="start.dump"):
    """end.dump ordered by the atoms' starting positions"""
    first, end = ref.read_dump(tmp_path / start), ref.read_dump(tmp_path / "end.dump")
    assert np.array_equal(first["id"], end["id"])
    order = np.lexsort((first["x"], first["y"], first["z"]))
    return {key: np.asarray(end[key])[order] for key in KEYS}


def test_cylinder_bitwise_on_1_2_4_ranks(lmp, tmp_path):
    """The ported peri/lps cylinder (smaller, shattering: bonds break with alpha on every step,
    the short-range forces act) ends in the same bits on 1, 2 and 4 MPI ranks."""
    states = []
    for nprocs in (1, 2, 4):
        out = lmp(cylinder() + END_DUMP, nprocs=nprocs).output
        assert ref.thermo_tables(out)[-1]["c_dmean"][-1] > 0.05    # bonds broke
        states.append(end_state(tmp_path))
    for other in states[1:]:
        for key in KEYS:
            np.testing.assert_array_equal(states[0][key], other[key])


def test_cylinder_bitwise_on_1_and_2_threads(lmp, tmp_path):
    """bbpd/lps on 2 OpenMP threads ends in the bits of 1 thread."""
    states = []
    for threads in (1, 2):
        script = cylinder().replace("units           si", f"package omp {threads}\nunits           si", 1)
        out = lmp(script + END_DUMP).output
        assert f"1 MPI tasks x {threads} OpenMP threads" in out
        states.append(end_state(tmp_path))
    for key in KEYS:
        np.testing.assert_array_equal(states[0][key], states[1][key])


def test_cylinder_restart_equals_continuous_run(lmp, tmp_path):
    """bbpd/lps across write_restart/read_restart (new process, 1 rank then 2): the weighted
    volumes, the last dilatations and the smallest stretches come back, and the run continues
    in the same bits as without the restart."""
    script = cylinder(steps=300)
    head, tail = script.split("fix             1 all nve", 1)
    lmp(script + END_DUMP)
    straight = end_state(tmp_path)
    (tmp_path / "start.dump").rename(tmp_path / "start1.dump")
    lmp(cylinder(steps=150) + "write_restart state.restart\n")
    second = ("plugin load bbpdplugin.so\nread_restart state.restart\nneighbor 0.0010 bin\n"
              "lattice sc 0.0005\nvariable steps index 150\nfix 1 all nve" + tail + END_DUMP)
    for nprocs in (1, 2):
        lmp(second, nprocs=nprocs)
        restarted = end_state(tmp_path, "start1.dump")
        assert straight["c_1"].mean() > 0.05
        for key in KEYS:
            np.testing.assert_array_equal(straight[key], restarted[key])


def test_cylinder_follows_peri_lps(lmp, tmp_path):
    """The smaller cylinder with peri/lps and with bbpd/lps: the same mean damage within 2 %
    at every thermo step once bonds have broken."""
    ours = cylinder()
    theirs = (ours.replace("plugin load     bbpdplugin.so\n", "")
              .replace("pair_style      bbpd/lps 3d", "pair_style      peri/lps")
              .replace("bbpd/damage/atom", "damage/atom"))
    tables = [ref.thermo_tables(lmp(s).output)[-1] for s in (theirs, ours)]
    d_ref, d = np.asarray(tables[0]["c_dmean"]), np.asarray(tables[1]["c_dmean"])
    assert d_ref[-1] > 0.05
    print("mean damage peri/lps", list(d_ref), "bbpd/lps", list(d))
    broken = d_ref > 0.01
    np.testing.assert_allclose(d[broken], d_ref[broken], rtol=0.02)


def test_periodic_cylinder_bitwise_on_1_and_2_ranks(lmp, tmp_path):
    """The smaller cylinder in a box periodic in x and z (its bounding box): the rim atoms are
    bonded across the boundary and bonds break there, each decided alike at both ends (from
    the owners' unshifted positions); the run ends in the same bits on 1 and 2 ranks."""
    script = cylinder().replace("boundary        s s s", "boundary        p s p")
    states = []
    for nprocs in (1, 2):
        out = lmp(script + END_DUMP, nprocs=nprocs).output
        assert "Periodic" not in out
        assert ref.thermo_tables(out)[-1]["c_dmean"][-1] > 0.05
        states.append(end_state(tmp_path))
    for key in KEYS:
        np.testing.assert_array_equal(states[0][key], states[1][key])


def test_compact_storage_gives_the_same_bits(lmp, tmp_path):
    """bond/storage compact (the weighted partner volumes recomputed from x0 through the bond
    law) ends the cylinder in the bits of the default storage."""
    states = []
    for storage in ("", " bond/storage compact"):
        script = cylinder().replace("pair_style      bbpd/lps 3d", f"pair_style      bbpd/lps 3d{storage}")
        out = lmp(script + END_DUMP).output
        # 6 bytes per bond end with compact storage (tag and partner offset), 8 by default
        assert f"{'6.0' if storage else '8.0'} per bond end" in out
        states.append(end_state(tmp_path))
    assert states[0]["c_1"].mean() > 0.05
    for key in KEYS:
        np.testing.assert_array_equal(states[0][key], states[1][key])
