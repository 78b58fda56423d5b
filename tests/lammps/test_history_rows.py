"""The history of bbpd/ves and bbpd/eps (fix bbpd/history: one row per local atom, as long as
its family) travels with its atoms and is sized by what it holds.

The scene: a periodic block of 10^3 atoms, each moved by a seeded random displacement of 4 %
of the spacing (the same on every rank count), then free: the bonds stretch and shrink, some
break, the EPS bonds yield and the VES back extensions move. Half-way through, every atom is
moved by half the box: on 2 ranks each atom goes to the other rank, its history with it.
- the final %.17g dump on 2 ranks equals the one on 1 rank (bits);
- a run written to a restart file half-way and read back on 2 ranks equals the same run on 1
  rank without the file;
- the memory the setup report gives per bond is that of bbpd/lps on the same bonds plus the
  history itself (BOND_HISTORY doubles per bond end), where each row's slots start (an int per
  atom: no row here lost a partner, so none keeps slots of its own), a row header per atom slot and up to HISTORY_BLOCK - 1 slots per row that fill its last block
  (bbpd_history_blocks.h); before the rows, every atom slot, ghosts included, held maxpartner
  slots of history (2.5 times as much on this block).
"""
import re
from pathlib import Path

import pytest

from bbpd.runner import run_lammps

DT = 1.0e-7
HALF = 100              # steps before and after the shift
BOND_HISTORY = 2        # doubles per bond end, VES and EPS (bbpd_ves.h, bbpd_eps.h)
ATOM_HISTORY = {"ves": 0, "eps": 2}    # doubles per atom (the same headers)
NATOMS = 10 ** 3
S00 = 0.02              # small enough that bonds break in the run
COEFFS = {
    "ves": "0.5 2.0e-6",    # lambda, tau = 20 steps
    "eps": "1.0e7",         # a yield stress reached in the first steps
    "lps": "",
}
# a row header per atom slot (16 bytes), ghosts included; LAMMPS grows its atom slots 16384 at
# a time (AtomVec::DELTA), and this block has about 4,100 local and ghost atoms
ROW_HEADER_BYTES = 16.0
HISTORY_BLOCK = 4       # slots per block of a row's history (bbpd_history_blocks.h)
MAX_PARTNERS = 122      # partners of an inner atom, simple cubic, delta = 3.015 spacings
ATOM_SLOTS = 16384
SETUP = """plugin load bbpdplugin.so
atom_style peri
units si
boundary p p p
atom_modify map array
neighbor 0.0005 bin
lattice sc 0.0005
region box block 0 10 0 10 0 10 units lattice
create_box 1 box
create_atoms 1 box
pair_style bbpd/{family} 3d
pair_coeff * * 14900000000.0 14900000000.0 0.0015001 {s00!r} 0.25 {coeffs}
set group all density 2200
set group all volume 1.25e-10
displace_atoms all random 2e-5 2e-5 2e-5 4711 units box
"""
DYNAMICS = f"""fix 1 all nve
timestep {DT!r}
thermo_style custom step pe ke
thermo {HALF}
"""
SHIFT = "displace_atoms all move 0.0025 0.0 0.0 units box\n"    # half the box along x
FINISH = ("write_dump all custom final.dump id x y z vx vy vz "
          "modify sort id format float %.17g\n")
MEMORY_RE = re.compile(r"memory of the bonds and the pair style: .* ([\d.]+) per bond")
BONDS_RE = re.compile(r"total bonds (\d+)")
BROKEN_RE = re.compile(r"total bonds \d+ \((\d+) broken\)")


def scene(family):
    return SETUP.format(family=family, s00=S00, coeffs=COEFFS[family])


def run(wd, script, nprocs):
    return run_lammps(script, workdir=wd, nprocs=nprocs).output


def final_dump(wd):
    return (wd / "final.dump").read_text()


@pytest.fixture(scope="module", params=["ves", "eps"])
def one_rank(request, tmp_path_factory):
    family = request.param
    wd = tmp_path_factory.mktemp(f"history-{family}")
    out = run(wd, scene(family) + DYNAMICS + f"run {HALF}\n" + SHIFT + f"run {HALF}\n" + FINISH,
              1)
    return family, out, final_dump(wd)


def test_history_migrates_with_its_atoms(tmp_path, one_rank):
    family, out1, dump1 = one_rank
    broken = [int(b) for b in BROKEN_RE.findall(out1)]
    assert broken[0] == 0 and broken[-1] > 0    # bonds break: the rows' slots shift
    out2 = run(tmp_path, scene(family) + DYNAMICS + f"run {HALF}\n" + SHIFT + f"run {HALF}\n"
               + FINISH, 2)
    assert "1 by 1 by 2" in out2 or "2 by 1 by 1" in out2 or "1 by 2 by 1" in out2
    assert BROKEN_RE.findall(out2) == BROKEN_RE.findall(out1)
    assert final_dump(tmp_path) == dump1


def test_history_without_it_differs(tmp_path, one_rank):
    """the control: with the history's effect off (VES lambda = 0, EPS a yield stress never
    reached), the same run ends elsewhere, so the bits above compare the history"""
    family, _, dump1 = one_rank
    off = {"ves": "0.0 2.0e-6", "eps": "1.0e30"}[family]
    script = (scene(family).replace(COEFFS[family], off) + DYNAMICS + f"run {HALF}\n" + SHIFT
              + f"run {HALF}\n" + FINISH)
    run(tmp_path, script, 1)
    assert final_dump(tmp_path) != dump1


def test_history_restarts(tmp_path, one_rank):
    family, _, _ = one_rank
    # two runs: the setup between them puts the atoms back in the periodic box as the restart
    # file does, which moves the last bits of the positions' periodic images
    cont = scene(family) + DYNAMICS + f"run {HALF}\nrun {HALF}\n" + FINISH
    run(tmp_path / "continuous", cont, 1)
    wd = tmp_path / "restarted"
    run(wd, scene(family) + DYNAMICS + f"run {HALF}\nwrite_restart state.restart\n", 1)
    run(wd, "plugin load bbpdplugin.so\nread_restart state.restart\nlattice sc 0.0005\n" + DYNAMICS
        + f"run {HALF}\n" + FINISH, 2)
    assert final_dump(wd) == final_dump(tmp_path / "continuous")


def memory_per_bond(wd, family):
    """the setup report's bytes per bond of the bonds and the pair style, and the bonds"""
    out = run(wd, scene(family) + DYNAMICS + "run 0\n", 1)
    return float(MEMORY_RE.search(out).group(1)), int(BONDS_RE.search(out).group(1))


def test_history_memory_is_what_it_holds(tmp_path, one_rank):
    family, _, _ = one_rank
    lps, bonds = memory_per_bond(tmp_path / "lps", "lps")
    ours, _ = memory_per_bond(tmp_path / family, family)
    history = 2 * BOND_HISTORY * 8.0 + ATOM_HISTORY[family] * 8.0 * NATOMS / bonds
    # an int per atom where its slots start, and 0, 1, 2, ...: no row here lost a partner, so
    # none keeps slots of its own (bbpd_bond_slots.h; an int per bond end before)
    slots = 4.0 * (NATOMS + MAX_PARTNERS) / bonds
    headers = ROW_HEADER_BYTES * ATOM_SLOTS / bonds
    blocks = (HISTORY_BLOCK - 1) * BOND_HISTORY * 8.0 * NATOMS / bonds
    assert lps + history <= ours <= lps + history + slots + headers + blocks


# LAMMPS's benchmark deck (perf/vs_bpm.py): a periodic 16^3 block, held still; only the setup
# report is read
DECK = SETUP.replace("region box block 0 10 0 10 0 10", "region box block 0 16 0 16 0 16").replace(
    "displace_atoms all random 2e-5 2e-5 2e-5 4711 units box\n", "")
DECK_COEFFS = {"pmb": "1.6863e22 0.0015001 0.5 0.25",
               "lps": "14900000000.0 14900000000.0 0.0015001 0.5 0.25",
               "ves": "14900000000.0 14900000000.0 0.0015001 0.5 0.25 0.5 0.001",
               "eps": "14900000000.0 14900000000.0 0.0015001 0.5 0.25 1.0e9"}
DOC = Path(__file__).resolve().parents[2] / "doc"


def test_the_deck_memory_of_the_docs_is_the_setup_report(tmp_path):
    """doc/performance.md's bytes per bond on the deck (and the VES and LPS figures of
    doc/pair_bbpd_ves_eps.rst) are the setup report's"""
    measured = {}
    for model, coeffs in DECK_COEFFS.items():
        script = re.sub(r"pair_coeff \* \* .*\n", f"pair_coeff * * {coeffs}\n",
                        DECK.format(family=model, s00=S00, coeffs=""))
        out = run(tmp_path / model, script + DYNAMICS + "run 0\n", 1)
        measured[model] = float(MEMORY_RE.search(out).group(1))
    text = " ".join((DOC / "performance.md").read_text().split())
    m = re.search(r"this deck\): PMB ([\d.]+), LPS ([\d.]+), VES ([\d.]+), EPS ([\d.]+)\.", text)
    assert m, "doc/performance.md: the deck's bytes per bond"
    assert [float(v) for v in m.groups()] == [round(measured[k], 1) for k in DECK_COEFFS]
    rst = " ".join((DOC / "pair_bbpd_ves_eps.rst").read_text().split())
    assert (f"{measured['ves']:.0f} bytes per bond for the bonds, the pair style and its state, "
            f"the LPS's {measured['lps']:.0f} plus") in rst
