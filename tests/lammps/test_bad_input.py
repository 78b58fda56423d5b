"""Every bad argument of every bbpd style stops LAMMPS with a clear ERROR line.

Each case is a small input script (a valid base with one command changed) and a substring of
the ERROR message the user must see. A case passes only if LAMMPS printed that ERROR and
exited through its normal error path (exit code 1, no crash, no signal, no NaN).
"""
import re

import pytest

from bbpd.jobs import ROOT
from bbpd.runner import run_lammps

# A valid 2D plate (10 x 10 atoms, 1 mm) and a valid 3D block (6 x 6 x 6 atoms, 1 mm):
# each case overrides some of these commands.
BASE_2D = dict(
    units="units si", dimension="dimension 2", boundary="boundary s s p",
    atom_style="atom_style peri", map="atom_modify map array",
    lattice="lattice sq 0.001", region="region box block 0 10 0 10 -0.5 0.5",
    ntypes="1", types="create_atoms 1 box",
    props="set group all density 7800.0\nset group all volume 1.0e-9",
    pair_style="pair_style bbpd/triangular plane/strain thickness 0.001",
    pair_coeff="pair_coeff * * 190.0e9 6.9e4 0.003015",
    extra="", run="run 0")
BASE_3D = dict(BASE_2D, dimension="dimension 3", boundary="boundary s s s",
               lattice="lattice sc 0.001", region="region box block 0 6 0 6 0 6",
               props="set group all density 7800.0\nset group all volume 1.0e-9",
               pair_style="pair_style bbpd/gaussian 3d")
ORDER = ["units", "dimension", "boundary", "atom_style", "map", "lattice", "region"]
AFTER = ["types", "props", "pair_style", "pair_coeff", "extra", "run"]

# a material file for the cases below that need a broken one
BAD_FILE = """# DATE: 2026-11-23 UNITS: si CONTRIBUTOR: test
# material  E  Gc  rho  nu
typo_steel  190.0e9x  6.9e4  7800.0  0.25
short_steel  190.0e9
"""


def script(base=BASE_2D, **changes):
    c = dict(base, **changes)
    lines = ["plugin load bbpdplugin.so"] + [c[k] for k in ORDER]
    lines += [f"create_box {c['ntypes']} box"] + [c[k] for k in AFTER]
    return "\n".join(l for l in lines if l) + "\n"


TWO_TYPES = dict(ntypes="2", types="create_atoms 1 box\nregion half block 0 5 INF INF INF INF\n"
                 "set region half type 2")
PMB = dict(pair_style="pair_style peri/pmb",
           pair_coeff="pair_coeff * * 1.0e22 0.003015 0.001 0.0")
NOTCH_2D = "fix n all bbpd/notch segment 0 0.0045 0.004 0.0045"
JINT = "compute J all bbpd/jintegral {}\nthermo_style custom step c_J[1] c_J[2] c_J[3]"
TIP = "compute tip all bbpd/crack/tip {}\nthermo_style custom step c_tip[3]"
ENERGY = "compute e all bbpd/energy\nthermo_style custom step c_e[5]"

# a case's script from its row's value: one command of the 2D plate or 3D block changed
def style(line): return script(pair_style=line)
def style3(line): return script(BASE_3D, pair_style=line)
def coeff(line): return script(pair_coeff=line)
def extra(lines): return script(extra=lines)
def extra3(lines): return script(BASE_3D, extra=lines)
def jint(args): return script(extra=JINT.format(args))
def tip(args): return script(extra=TIP.format(args))
# the pair_coeff line of a 3D block of bbpd/pmb, bbpd/lps and bbpd/lps/gaussian
def pmb(line): return script(BASE_3D, pair_style="pair_style bbpd/pmb 3d", pair_coeff=line)
def lps(line): return script(BASE_3D, pair_style="pair_style bbpd/lps 3d", pair_coeff=line)
def lpsk(line): return script(BASE_3D, pair_style="pair_style bbpd/lps/gaussian 3d", pair_coeff=line)
def pair(lines): return script(pair_style=lines, pair_coeff="")    # its pair_style and pair_coeff
def pair3(lines): return script(BASE_3D, pair_style=lines, pair_coeff="")
def given(text): return text    # a script that changes more than one command


# (id, how its script is made, the value that makes it, expected substring of the ERROR line)
ROWS = [
    # ---- pair_style bbpd/KERNEL [model] MODEL [thickness h] [area A] [spacing dx] [dt/safety f]
    ("style-no-model", style, "pair_style bbpd/gaussian",
     "needs a model"),
    ("style-model-keyword-only", style, "pair_style bbpd/gaussian model",
     "needs a model"),
    ("style-unknown-model", style, "pair_style bbpd/gaussian plane thickness 0.001",
     "unknown model 'plane'"),
    ("style-unknown-keyword", style, "pair_style bbpd/gaussian plane/strain thickness 0.001 horizon 0.003",
     "Unknown pair_style bbpd/gaussian keyword: horizon"),
    ("style-keyword-no-value", style, "pair_style bbpd/gaussian plane/strain thickness",
     "Illegal pair_style bbpd/gaussian thickness command: missing argument"),
    ("style-non-numeric", style, "pair_style bbpd/gaussian plane/strain thickness 1mm",
     "Expected floating point parameter instead of '1mm'"),
    ("style-thickness-zero", style, "pair_style bbpd/gaussian plane/strain thickness 0",
     "thickness must be > 0"),
    ("style-thickness-negative", style, "pair_style bbpd/gaussian plane/stress thickness -0.001",
     "thickness must be > 0"),
    ("style-thickness-3d", style3, "pair_style bbpd/gaussian 3d thickness 0.001",
     "keyword thickness does not apply to model 3d"),
    ("style-thickness-1d", style, "pair_style bbpd/gaussian 1d thickness 0.001",
     "keyword thickness does not apply to model 1d"),
    ("style-area-plane", style, "pair_style bbpd/gaussian plane/stress area 1.0e-6",
     "keyword area does not apply to model plane/stress"),
    ("style-area-3d", style3, "pair_style bbpd/gaussian 3d area 1.0e-6",
     "keyword area does not apply to model 3d"),
    ("style-area-zero", style, "pair_style bbpd/gaussian 1d area 0.0",
     "area must be > 0"),
    ("style-no-thickness", style, "pair_style bbpd/gaussian plane/stress",
     "needs the thickness"),
    ("style-no-area", style, "pair_style bbpd/constant 1d",
     "needs the cross-section"),
    ("style-dt-safety-zero", style3, "pair_style bbpd/gaussian 3d dt/safety 0",
     "dt/safety must be in (0,1]"),
    ("style-dt-safety-above-one", style3, "pair_style bbpd/gaussian 3d dt/safety 1.5",
     "dt/safety must be in (0,1]"),
    ("style-spacing-zero", style3, "pair_style bbpd/gaussian 3d spacing 0",
     "spacing must be > 0"),
    ("style-spacing-negative", style3, "pair_style bbpd/gaussian 3d spacing -0.001",
     "spacing must be > 0"),
    ("style-contact-not-boolean", style, "pair_style bbpd/gaussian plane/strain thickness 0.001 contact maybe",
     "Expected boolean parameter instead of 'maybe'"),
    ("style-contact-no-value", style, "pair_style bbpd/gaussian plane/strain thickness 0.001 contact",
     "Illegal pair_style bbpd/gaussian contact command: missing argument"),
    ("style-contact-distance-zero", style, "pair_style bbpd/gaussian plane/strain thickness 0.001 contact yes contact/distance 0",
     "contact/distance must be in (0,1]"),
    ("style-contact-distance-above-one", style, "pair_style bbpd/gaussian plane/strain thickness 0.001 contact/distance 1.5",
     "contact/distance must be in (0,1]"),
    # ---- pair_style ... simd auto|portable|avx2|avx512 (a forced path the CPU lacks:
    # tests/lammps/test_simd_builds.py, which hides paths with BBPD_SIMD_HIDE)
    ("style-simd-unknown", style, "pair_style bbpd/triangular plane/strain thickness 0.001 simd sse4",
     "simd must be auto (the fastest path this CPU runs), portable, avx2 or avx512, got 'sse4'"),
    ("style-simd-no-value", style, "pair_style bbpd/triangular plane/strain thickness 0.001 simd",
     "Illegal pair_style bbpd/triangular simd command: missing argument"),
    ("style-simd-upper-case", style3, "pair_style bbpd/pmb 3d simd AVX2",
     "got 'AVX2'"),
    # ---- pair_coeff I J E Gc delta [critical_stretch s0] | I J FILE MATERIAL delta [...]
    ("coeff-4-args", coeff, "pair_coeff * * 190.0e9 6.9e4",
     "got 4 arguments"),
    ("coeff-6-args", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 critical_stretch",
     "got 6 arguments"),
    ("coeff-8-args", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 critical_stretch 0.01 0.02",
     "got 8 arguments"),
    ("coeff-type-out-of-range", coeff, "pair_coeff 1 2 190.0e9 6.9e4 0.003015",
     "Numeric index 2 is out of bounds"),
    ("coeff-E-non-numeric", coeff, "pair_coeff * * 190GPa 6.9e4 0.003015",
     "not a number"),
    ("coeff-Gc-non-numeric", coeff, "pair_coeff * * 190.0e9 tough 0.003015",
     "Expected floating point parameter instead of 'tough'"),
    ("coeff-delta-non-numeric", coeff, "pair_coeff * * 190.0e9 6.9e4 3mm",
     "Expected floating point parameter instead of '3mm'"),
    ("coeff-E-zero", coeff, "pair_coeff * * 0.0 6.9e4 0.003015",
     "Young's modulus E must be > 0"),
    ("coeff-E-negative", coeff, "pair_coeff * * -190.0e9 6.9e4 0.003015",
     "Young's modulus E must be > 0"),
    ("coeff-Gc-zero", coeff, "pair_coeff * * 190.0e9 0.0 0.003015",
     "fracture energy Gc must be > 0"),
    ("coeff-delta-zero", coeff, "pair_coeff * * 190.0e9 6.9e4 0.0",
     "horizon delta must be > 0"),
    ("coeff-delta-negative", coeff, "pair_coeff * * 190.0e9 6.9e4 -0.003015",
     "horizon delta must be > 0"),
    ("coeff-critical-stretch-zero", coeff, "pair_coeff * * 190.0e9 none 0.003015 critical_stretch 0",
     "critical_stretch must be > 0"),
    ("coeff-critical-stretch-non-numeric", coeff, "pair_coeff * * 190.0e9 none 0.003015 critical_stretch big",
     "Expected floating point parameter instead of 'big'"),
    ("coeff-unknown-keyword", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 s0 0.01",
     "Unknown pair_coeff bbpd/triangular keyword: s0"),
    ("coeff-alpha-negative", pair, "pair_style bbpd/triangular/alpha plane/strain thickness 0.001\npair_coeff * * 190.0e9 6.9e4 0.003015 alpha -0.25",
     "alpha must be >= 0"),
    ("coeff-alpha-missing-value", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 critical_stretch 0.01 alpha",
     "got 8 arguments"),
    # ---- pair_coeff ... bonds no: two bodies, for two different types only
    ("coeff-bonds-no-same-type", coeff, "pair_coeff * * 190.0e9 none 0.003015 bonds no",
     "'bonds no' is for two different types"),
    ("coeff-bonds-no-critical-stretch", given,
     script(**TWO_TYPES, pair_coeff="pair_coeff * * 190.0e9 6.9e4 0.003015\n"
            "pair_coeff 1 2 190.0e9 none 0.003015 critical_stretch 0.01 bonds no"),
     "has no bonds to break"),
    ("coeff-bonds-not-logical", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 bonds maybe",
     "Expected boolean parameter instead of 'maybe'"),
    ("fix-with-internal-id", extra, "fix BBPD_WATCHDOG all nve",
     "needs its internal fix BBPD_WATCHDOG of style bbpd/watchdog"),
    # ---- the rules of other styles asked of a kernel style
    ("compat-is-own-style", style3, "pair_style bbpd/constant 3d compat pmb",
     "'compat pmb' is now its own style: write 'pair_style bbpd/pmb 3d'"),
    ("alpha-is-own-style", coeff, "pair_coeff * * 190.0e9 6.9e4 0.003015 alpha 0.25",
     "a rule of pair style bbpd/triangular/alpha"),
    # ---- bbpd/pmb: pair_coeff I J c delta s00 alpha, as peri/pmb
    ("pmb-coeff-E-Gc", style3, "pair_style bbpd/pmb 3d",
     "expected 'I J c delta s00 alpha'"),
    ("pmb-coeff-s00-zero", pmb, "pair_coeff * * 1.0e22 0.003015 0.0 0.25",
     "s00 must be > 0"),
    ("pmb-coeff-alpha-negative", pmb, "pair_coeff * * 1.0e22 0.003015 0.001 -1",
     "alpha must be >= 0"),
    ("pmb-with-contact", pair3, "pair_style bbpd/pmb 3d contact yes\npair_coeff * * 1.0e22 0.003015 0.001 0.25",
     "drop 'contact yes'"),
    ("pmb-horizon-below-short-range", pmb, "pair_coeff * * 1.0e22 0.0012 0.001 0.25",
     "shorter than the short-range distance"),
    ("pmb-lattice-not-cubic", given,
     script(BASE_3D, lattice="lattice custom 0.001 a1 1 0 0 a2 0 1 0 a3 0 0 2 basis 0 0 0",
            pair_style="pair_style bbpd/pmb 3d", pair_coeff="pair_coeff * * 1.0e22 0.003015 0.001 0.25"),
     "same constant in x, y and z"),
    # ---- bbpd/lps: pair_style bbpd/lps 3d, pair_coeff I J K G delta s00 alpha, as peri/lps
    ("lps-coeff-pmb-numbers", lps, "pair_coeff * * 1.0e22 0.003015 0.001 0.25",
     "expected 'I J K G delta s00 alpha'"),
    ("lps-coeff-too-many", lps, "pair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25 1",
     "got 8 arguments"),
    ("lps-coeff-shear-zero", lps, "pair_coeff * * 14.9e9 0 0.003015 0.001 0.25",
     "the shear modulus G must be > 0"),
    ("lps-model-not-3d", pair, "pair_style bbpd/lps plane/strain thickness 0.001\npair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25",
     "peri/lps is the 3D linear peridynamic solid, write 'pair_style bbpd/lps 3d'"),
    ("lps-2d-box", pair, "pair_style bbpd/lps 3d\npair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25",
     "model 3d requires 'dimension 3'"),
    ("lps-atom-style-not-peri", given,
     script(BASE_3D, atom_style="atom_style atomic", props="", pair_style="pair_style bbpd/lps 3d",
            pair_coeff="pair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25"),
     "requires atom_style peri"),
    ("lps-with-contact", pair3, "pair_style bbpd/lps 3d contact yes\npair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25",
     "drop 'contact yes'"),
    # ---- bbpd/lps/KERNEL: pair_style bbpd/lps/KERNEL MODEL, pair_coeff I J E nu Gc|none delta
    ("lpsk-coeff-missing", lpsk, "pair_coeff * * 190.0e9 0.3 0.003015",
     "expected 'I J E nu Gc delta'"),
    ("lpsk-coeff-extra", lpsk, "pair_coeff * * 190.0e9 0.3 6.9e4 0.003015 1",
     "got 7 arguments"),
    ("lpsk-nu-half-3d", pair3, "pair_style bbpd/lps/constant 3d\npair_coeff * * 190.0e9 0.5 6.9e4 0.003015",
     "Poisson's ratio 0.5 is outside -1 < nu < 0.5 of model 3d"),
    ("lpsk-nu-plane-strain", pair, "pair_style bbpd/lps/triangular plane/strain thickness 0.001\npair_coeff * * 190.0e9 0.6 6.9e4 0.003015",
     "outside -1 < nu < 0.5 of model plane/strain"),
    ("lpsk-nu-plane-stress", pair, "pair_style bbpd/lps/triangular plane/stress thickness 0.001\npair_coeff * * 190.0e9 1.0 6.9e4 0.003015",
     "outside -1 < nu < 1 of model plane/stress"),
    ("lpsk-nu-minus-one", lpsk, "pair_coeff * * 190.0e9 -1.0 6.9e4 0.003015",
     "outside -1 < nu < 0.5"),
    ("lpsk-youngs-zero", lpsk, "pair_coeff * * 0 0.3 6.9e4 0.003015",
     "Young's modulus E must be > 0"),
    ("lpsk-horizon-zero", lpsk, "pair_coeff * * 190.0e9 0.3 6.9e4 0",
     "the horizon delta must be > 0"),
    ("lpsk-gc-negative", lpsk, "pair_coeff * * 190.0e9 0.3 -1 0.003015",
     "the fracture energy Gc must be > 0 (or 'none'"),
    ("lpsk-model-1d", pair3, "pair_style bbpd/lps/constant 1d area 1e-6\npair_coeff * * 190.0e9 0.3 6.9e4 0.003015",
     "model 1d is not available"),
    ("lpsk-2d-box-3d-model", pair, "pair_style bbpd/lps/constant 3d\npair_coeff * * 190.0e9 0.3 6.9e4 0.003015",
     "model 3d requires 'dimension 3'"),
    ("lpsk-no-thickness", pair, "pair_style bbpd/lps/constant plane/stress\npair_coeff * * 190.0e9 0.3 6.9e4 0.003015",
     "needs the thickness"),
    ("lpsk-with-contact", pair3, "pair_style bbpd/lps/gaussian 3d contact yes\npair_coeff * * 190.0e9 0.3 6.9e4 0.003015",
     "drop 'contact yes'"),
    ("lpsk-no-lattice", lpsk, "pair_coeff * * 190.0e9 0.3 6.9e4 0.003015\nlattice none 1.0",
     "needs a lattice command"),
    ("coeff-file-unknown-material", coeff, "pair_coeff * * kalthoff_winkler_steel.bbpd unobtainium 0.003015",
     "Material unobtainium not found"),
    ("coeff-file-missing", coeff, "pair_coeff * * no_such_file.bbpd maraging_steel 0.003015",
     "no_such_file.bbpd"),
    ("coeff-file-unit-mismatch", given,
     script(units="units metal", lattice="lattice sq 1.0",
            props="set group all density 7.8\nset group all volume 1.0",
            pair_style="pair_style bbpd/triangular plane/strain thickness 1.0",
            pair_coeff="pair_coeff * * kalthoff_winkler_steel.bbpd maraging_steel 3.015"),
     "requires si units but metal units are in use"),
    ("coeff-file-bad-number", coeff, "pair_coeff * * bad.bbpd typo_steel 0.003015",
     "190.0e9x"),
    ("coeff-file-short-line", coeff, "pair_coeff * * bad.bbpd short_steel 0.003015",
     "Incorrect format in bbpd potential file"),
    # ---- checks at init (run)
    ("init-atom-style-atomic", given,
     script(atom_style="atom_style atomic", props="mass 1 7800.0"),
     "requires atom_style peri"),
    ("init-missing-pair-coeff-12", given,
     script(**TWO_TYPES,
            pair_coeff="pair_coeff 1 1 190.0e9 6.9e4 0.003015\n"
            "pair_coeff 2 2 190.0e9 6.9e4 0.003015"),
     "pair_coeff for types 1 2 is missing"),
    ("init-missing-pair-coeff-22", given,
     script(**TWO_TYPES, pair_coeff="pair_coeff 1 * 190.0e9 6.9e4 " "0.003015"),
     "All pair coeffs are not set"),
    ("init-horizon-below-spacing", coeff, "pair_coeff * * 190.0e9 6.9e4 0.0005",
     "is smaller than the grid spacing"),
    ("init-no-volume", given,
     script(props="set group all density 7800.0"),
     "volume"),
    ("init-plane-in-3d", style3, "pair_style bbpd/gaussian plane/strain thickness 0.001",
     "requires 'dimension 2'"),
    ("init-3d-in-2d", style, "pair_style bbpd/gaussian 3d",
     "requires 'dimension 3'"),
    ("init-no-atom-map", given,
     script(map=""),
     "requires an atom map"),
    # ---- fix ID group bbpd/notch segment x1 y1 x2 y2 ... | rectangle cx cy cz ax ay az bx by bz
    #      | groups G1 G2
    ("notch-no-args", extra, "fix n all bbpd/notch",
     "Illegal fix bbpd/notch command: missing argument"),
    ("notch-segment-3-numbers", extra, "fix n all bbpd/notch segment 0 0.005 0.004",
     "segment needs 4 numbers"),
    ("notch-segment-zero-length", extra, "fix n all bbpd/notch segment 0.004 0.005 0.004 0.005",
     "has zero length"),
    ("notch-unknown-keyword", extra, "fix n all bbpd/notch line 0 0.005 0.004 0.005",
     "Unknown fix bbpd/notch keyword: line"),
    ("notch-extra-number", extra, "fix n all bbpd/notch segment 0 0.005 0.004 0.005 0.006",
     "Unknown fix bbpd/notch keyword: 0.006"),
    ("notch-rectangle-in-2d", extra, "fix n all bbpd/notch rectangle 0 0.005 0 0.004 0 0 0 0 0.001",
     "'rectangle' is for dimension 3"),
    ("notch-segment-in-3d", extra3, NOTCH_2D,
     "'segment' is for dimension 2"),
    ("notch-rectangle-8-numbers", extra3, "fix n all bbpd/notch rectangle 0 0.003 0 0.004 0 0 0 0",
     "rectangle needs 9 numbers"),
    ("notch-rectangle-parallel", extra3, "fix n all bbpd/notch rectangle 0 0.003 0 0.004 0 0 0.002 0 0",
     "rectangle edges are parallel"),
    ("notch-non-numeric", extra, "fix n all bbpd/notch segment 0 a 0.004 0.005",
     "Expected floating point parameter instead of 'a'"),
    ("notch-groups-one-name", extra, "group lo id 1:50\nfix n all bbpd/notch groups lo",
     "groups needs two group IDs"),
    ("notch-groups-no-name", extra, "fix n all bbpd/notch groups",
     "groups needs two group IDs"),
    ("notch-groups-unknown", extra, "group lo id 1:50\nfix n all bbpd/notch groups lo hi",
     "no group named hi"),
    ("notch-groups-empty", extra, "group lo id 1:50\nregion out block 20 30 20 30 INF INF\ngroup none region out\nfix n all " "bbpd/notch groups lo none",
     "group none has no atoms"),
    ("notch-groups-deleted", extra, "group lo id 1:50\ngroup hi id 51:100\nfix n all bbpd/notch groups lo hi\ngroup hi delete",
     "group hi no longer exists"),
    ("notch-atom-style-atomic", given,
     script(atom_style="atom_style atomic", props="mass 1 7800.0", pair_style="", pair_coeff="",
            extra=NOTCH_2D),
     "requires atom_style peri"),
    ("notch-without-bbpd-pair", given,
     script(**PMB, extra=NOTCH_2D),
     "bbpd/notch requires a bbpd"),
    # ---- compute ID group bbpd/damage/atom
    ("damage-extra-arg", extra, "compute d all bbpd/damage/atom 1",
     "takes no arguments"),
    ("damage-without-bbpd-pair", given,
     script(**PMB, extra="compute d all bbpd/damage/atom"),
     "requires a bbpd/* pair style"),
    # ---- compute ID group bbpd/jintegral tip X Y [rin R1] [rout R2] [gradient RG] ...
    #      (plate [0, 10 mm]^2, horizon 3.015 mm: the default annulus 2..5 delta does not fit)
    ("jint-no-tip", jint, "rin 0.001 rout 0.002",
     "expected 'compute ID group bbpd/jintegral tip X Y"),
    ("jint-rout-below-rin", jint, "tip 0.005 0.005 rin 0.003 rout 0.002",
     "need rout > rin, got rin = 0.003 rout = 0.002; increase rout"),
    ("jint-rin-above-default-rout", jint, "tip 0.005 0.005 rin 0.02",
     "need rout > rin"),
    ("jint-annulus-outside", jint, "tip 0.005 0.005 rin 0.001 rout 0.006",
     "reaches outside the body"),
    ("jint-default-annulus-outside", jint, "tip 0.005 0.005",
     "choose rout <= 0.005"),
    ("jint-tip-outside", jint, "tip 0.02 0.005 rin 0.001 rout 0.002",
     "lies outside the body"),
    ("jint-3d", extra3, JINT.format("tip 0.003 0.003 rin 0.001 rout 0.002"),
     "works with the 2D models only: pair model is 3d"),
    ("jint-1d", given,
     script(pair_style="pair_style bbpd/gaussian 1d area 1.0e-6",
            extra=JINT.format("tip 0.005 0.005 rin 0.001 rout 0.002")),
     "works with the 2D models only: pair model is 1d"),
    ("jint-without-bbpd-pair", given,
     script(**PMB, extra=JINT.format("tip 0.005 0.005 rin 0.001 " "rout 0.002")),
     "without a bbpd/* pair style needs"),
    ("jint-gradient-below-spacing", jint, "tip 0.005 0.005 rin 0.001 rout 0.002 gradient 0.0005",
     "increase gradient (at least the grid spacing)"),
    ("jint-unknown-keyword", jint, "tip 0.005 0.005 r1 0.001",
     "unknown keyword 'r1'"),
    ("jint-rin-zero", jint, "tip 0.005 0.005 rin 0 rout 0.002",
     "rin must be > 0"),
    ("jint-plane-typo", jint, "tip 0.005 0.005 plane strian",
     "plane must be stress or strain, got strian"),
    ("jint-nu-half", jint, "tip 0.005 0.005 nu 0.5",
     "nu must lie in (-1, 0.5)"),
    ("jint-direction-zero", jint, "tip 0.005 0.005 direction 0 0",
     "direction 0 0 has zero length"),
    ("jint-tip-variable-missing", jint, "tip v_tx 0.005 rin 0.001 rout 0.002",
     "tip variable tx does not exist"),
    # ---- compute ID group bbpd/crack/tip X Y [threshold T] [link L] [span S] [window W]
    #      [direction DX DY] [branches yes|no] [branch B] [maxtips N]
    ("tip-no-xy", tip, "threshold 0.3",
     "expected 'compute ID group bbpd/crack/tip X Y"),
    ("tip-one-coordinate", tip, "0.005",
     "expected 'compute ID group bbpd/crack/tip X Y"),
    ("tip-threshold-zero", tip, "0.005 0.0045 threshold 0",
     "threshold must lie in (0, 1], got 0"),
    ("tip-threshold-above-one", tip, "0.005 0.0045 threshold 1.5",
     "threshold must lie in (0, 1], got 1.5"),
    ("tip-threshold-no-value", tip, "0.005 0.0045 threshold",
     "keyword threshold needs a value"),
    ("tip-window-negative", tip, "0.005 0.0045 window -1e-6",
     "window must be >= 0 (a time), got -1e-06"),
    ("tip-link-zero", tip, "0.005 0.0045 link 0",
     "link must be > 0"),
    ("tip-span-negative", tip, "0.005 0.0045 span -0.001",
     "span must be > 0"),
    ("tip-direction-zero", tip, "0.005 0.0045 direction 0 0",
     "direction 0 0 has zero length"),
    ("tip-unknown-keyword", tip, "0.005 0.0045 horizon 0.003",
     "unknown keyword 'horizon'"),
    ("tip-link-below-spacing", tip, "0.005 0.0045 link 0.0005",
     "link 0.0005 is below the grid spacing 0.001"),
    ("tip-without-bbpd-pair", given,
     script(**PMB, extra=TIP.format("0.005 0.0045")),
     "bbpd/crack/tip requires a bbpd/* pair style"),
    ("tip-3d", extra3, TIP.format("0.003 0.003"),
     "works in 2D only"),
    # ---- compute ID group bbpd/energy (no arguments); fix bbpd/work is its internal fix
    ("energy-with-args", extra, "compute e all bbpd/energy all",
     "takes no arguments"),
    ("energy-without-bbpd-pair", given,
     script(**PMB, extra=ENERGY),
     "bbpd/energy requires a bbpd/* pair style"),
    ("energy-atom-style-atomic", given,
     script(atom_style="atom_style atomic", props="mass * 1.0",
            pair_style="pair_style lj/cut 0.003", pair_coeff="pair_coeff * * 1.0 0.001",
            extra="compute e all bbpd/energy"),
     "needs atom_style peri"),
    ("energy-work-fix-deleted", extra, ENERGY + "\nunfix BBPD_WORK_e",
     "its fix BBPD_WORK_e was deleted"),
    ("energy-respa", extra, ENERGY + "\nrun_style respa 2 2",
     "run_style verlet only"),
    ("work-fix-by-hand", extra, "fix w all bbpd/work 1",
     "created by compute bbpd/energy"),
    # [branches yes|no] [branch B] [maxtips N]
    ("tip-branches-no-value", tip, "0.005 0.0045 branches",
     "keyword branches needs yes or no"),
    ("tip-branches-not-boolean", tip, "0.005 0.0045 branches maybe",
     "Expected boolean parameter instead of 'maybe'"),
    ("tip-branch-zero", tip, "0.005 0.0045 branches yes branch 0",
     "branch must be > 0 (a length), got 0"),
    ("tip-maxtips-zero", tip, "0.005 0.0045 branches yes maxtips 0",
     "maxtips must be >= 1 (rows of the array), got 0"),
    ("tip-maxtips-not-integer", tip, "0.005 0.0045 branches yes maxtips 2.5",
     "Expected integer parameter instead of '2.5'"),
    ("tip-branch-without-branches", tip, "0.005 0.0045 branch 0.002",
     "keywords branch and maxtips need 'branches yes'"),
    ("tip-maxtips-without-branches", tip, "0.005 0.0045 branches no maxtips 4",
     "keywords branch and maxtips need 'branches yes'"),
    # ---- fix bbpd/bonds is internal (created by the pair style)
    ("bonds-fix-with-args", extra, "fix b all bbpd/bonds 1",
     "takes no arguments"),
    ("bonds-fix-without-bbpd-pair", given,
     script(**PMB, extra="fix b all bbpd/bonds"),
     "requires a bbpd/* pair style"),
    # ---- fix bbpd/history is internal (created by bbpd/ves and bbpd/eps with their widths)
    ("history-fix-no-widths", extra, "fix h all bbpd/history",
     "takes the doubles of history per atom and per bond end"),
    ("history-fix-other-widths", given,
     script(BASE_3D, pair_style="fix BBPD_HISTORY all bbpd/history 2 2\npair_style bbpd/ves 3d",
            pair_coeff="pair_coeff * * 14.9e9 14.9e9 0.003015 0.001 0.25 0.5 0.001"),
     "holds 2 doubles of history per atom and 2 per bond end, this model needs 0 and 2"),
]

CASES = {name: (build(value), expected) for name, build, value, expected in ROWS}

# cases where the plugin is not (yet) as clear as it should be (strict xfail, with the reason)
XFAIL = {}


def params():
    for name, (text, expected) in CASES.items():
        marks = ([pytest.mark.xfail(strict=True, raises=AssertionError, reason=XFAIL[name])]
                 if name in XFAIL else [])
        yield pytest.param(text, expected, id=name, marks=marks)


def check_error_exit(proc, expected):
    out = proc.output
    for crash in ("Segmentation", "signal", "Exception:", "terminate called"):
        assert crash not in out, f"crash marker {crash!r}:\n{out[-2000:]}"
    assert not re.search(r"\bnan\b", out, re.I), out[-2000:]
    assert proc.error is not None, f"accepted silently (exit {proc.returncode}):\n{out[-2000:]}"
    assert expected in proc.error, proc.error
    assert proc.returncode == 1


def run_case(tmp_path, text, nprocs=1):
    (tmp_path / "bad.bbpd").write_text(BAD_FILE)
    return run_lammps(text, workdir=tmp_path, nprocs=nprocs, check=False, timeout=60)


@pytest.mark.parametrize("text,expected", params())
def test_bad_input_stops_with_error(tmp_path, text, expected):
    check_error_exit(run_case(tmp_path, text), expected)


def test_readme_counts_these_cases():
    """doc/verification.md's 'Verified against theory' list states how many bad-input cases there are"""
    readme = (ROOT / "doc" / "verification.md").read_text()
    stated = re.search(r"(\d+) bad-input cases each end in a LAMMPS `ERROR:`", readme)
    assert stated and int(stated.group(1)) == len(list(params()))


# errors raised on rank 0 only (file reading) or collectively (settings, init) under MPI:
# the other ranks must not hang in a collective call
@pytest.mark.parametrize("name", ["coeff-file-unknown-material", "coeff-file-unit-mismatch",
                                  "init-horizon-below-spacing", "notch-segment-zero-length",
                                  "notch-groups-empty",
                                  "jint-annulus-outside", "tip-link-below-spacing"])
def test_bad_input_stops_under_mpi(tmp_path, name):
    text, expected = CASES[name]
    check_error_exit(run_case(tmp_path, text, nprocs=2), expected)
