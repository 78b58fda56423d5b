"""examples/big-run/in.big on a small block (2 ranks, seconds): it runs, prints the memory lines
(the pair style's memory of the bonds, LAMMPS's per-rank memory) that bbpd.benchmarks.big_run
reads, writes its two alternating restart files, a run continued from the last one gives the
thermo of the continuous run, and -var restart no writes none. The large run of its README is
not part of the tests (minutes and most of the machine's memory)."""
from bbpd import readers
from bbpd.benchmarks import big_run
from bbpd.runner import run_lammps

N = 10             # points per edge: 1000 atoms
RANKS = 2


def test_small_block_prints_its_memory_and_writes_restarts(tmp_path):
    r = big_run.run(N, tmp_path, nprocs=RANKS)
    assert r["atoms"] == N**3 and r["ranks"] == RANKS and r["rss_ranks"] == RANKS
    assert r["bonds"] > 0 and r["steps"] > 0
    # the pair style's own count and LAMMPS's agree in size: both hold the bonds
    assert 0 < r["bonds_pair_mb"] < RANKS * r["lammps_mb_per_rank"]
    assert r["bonds_pair_bytes_per_atom"] > r["bonds_pair_bytes_per_bond"] > 0
    assert r["rss_bytes"] > r["lammps_mb_per_rank"] * big_run.MBYTES
    for name in ("big.a.restart", "big.b.restart"):
        assert (tmp_path / name).stat().st_size > 0, name


CONTINUE = """plugin          load bbpdplugin.so
read_restart    big.b.restart
fix             integrate all nve
thermo_style    custom step atoms pe ke
thermo_modify   format float %.15g
thermo          1
run             {steps}
"""


def test_continued_from_its_restart_equals_the_continuous_run(tmp_path):
    """the file of step 4 (big.b.restart, the second of the pair) holds the whole state"""
    cont, split = tmp_path / "continuous", tmp_path / "split"
    energies = []
    for work, steps in ((cont, 6), (split, 4)):
        out = run_lammps(str(big_run.EXAMPLE), work, nprocs=RANKS,
                         vars={"n": N, "steps": steps}).output
        energies.append(readers.thermo_tables(out)[-1])
    more = run_lammps(CONTINUE.format(steps=2), split, nprocs=RANKS).output
    after = readers.thermo_tables(more)[-1]
    assert after["Step"][-1] == energies[0]["Step"][-1] == 6
    for column in ("PotEng", "KinEng"):
        assert after[column][-1] == energies[0][column][-1], column


def test_restart_no_writes_none(tmp_path):
    big_run.run(N, tmp_path, nprocs=RANKS, restart=False)
    assert not list(tmp_path.glob("*.restart"))


def test_margin_and_fit():
    small = {"atoms": 1000, "bonds": 80_000, "rss_bytes": 100e6}
    large = {"atoms": 3000, "bonds": 240_000, "rss_bytes": 106e6}
    assert big_run.margin(small, large) == (3000.0, 6e6 / 160_000)
    assert big_run.fits([small, large], 106e6 + 3000.0 * 500) == 3500
