# SPDX-License-Identifier: GPL-2.0-or-later
"""The plugin's sources depend on each other one way (doc/architecture.rst): a core of headers
with no LAMMPS dependency, the bond storage (fix bbpd/bonds) on top of it, and the pair style,
fix bbpd/notch and the computes on top of the storage. The storage never reaches up, and no
include runs in a circle. The Python package is layered the same way: its imports, all at
module level, run one way and in no circle."""
import ast
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# LAMMPS glue that lives beside the core headers: resolves LAMMPS version differences
GLUE = {"bbpd_compat.h"}
CORE = sorted(p.name for p in SRC.glob("bbpd_*.h") if p.name not in GLUE)
STORAGE = ["fix_bbpd_bonds.h", "fix_bbpd_bonds.cpp"]


def includes(name):
    """quoted includes of src/NAME, and of the src headers it includes, transitively"""
    seen, todo = set(), [name]
    while todo:
        for inc in INCLUDE.findall((SRC / todo.pop()).read_text()):
            if inc not in seen:
                seen.add(inc)
                if (SRC / inc).is_file():
                    todo.append(inc)
    return seen


def test_core_is_found():
    assert {"bbpd_kernel.h", "bbpd_bond_law.h", "bbpd_bond_storage.h", "bbpd_row.h"} <= set(CORE)


@pytest.mark.parametrize("header", CORE)
def test_core_header_needs_no_lammps(header):
    outside = sorted(i for i in includes(header) if i not in CORE)
    assert not outside, f"{header} includes {outside}: the core takes no LAMMPS header"


@pytest.mark.parametrize("name", STORAGE)
def test_storage_knows_neither_pair_style_nor_notch(name):
    reached = includes(name)
    assert not reached & {"pair_bbpd.h", "fix_bbpd_notch.h"}, sorted(reached)
    text = (SRC / name).read_text()
    for cls in ("PairBBPD", "FixBBPDNotch", "FixBBPDAlpha"):
        assert cls not in text, f"{name} names {cls}: the storage must not call its users"


# --------------------------------------------------------------------------- no circles

def include_graph(src=SRC):
    """{file: files of src it includes (quoted includes)} over src/*.h and src/*.cpp"""
    files = {p.name: p for p in sorted(src.glob("*.h")) + sorted(src.glob("*.cpp"))}
    return {name: {inc for inc in INCLUDE.findall(p.read_text()) if inc in files}
            for name, p in files.items()}


def circles(graph):
    """the strongly connected components of graph with more than one node or a self-edge,
    each sorted (Tarjan's algorithm)"""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1 or v in graph.get(v, ()):
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


# the arithmetic of one bond, as the loops wrote it before the bond model (bbpd_bond_model.h)
# held it: force c elong / r, energy 1/4 c elong^2, the test elong + margin > s0 xi0, their
# intrinsics forms, and the Silling-Askari s00 - alpha smax
BOND_ARITHMETIC = re.compile(
    r"coef\s*\*\s*elong|0\.25\s*\*\s*coef|elong\s*\+\s*margin\s*>|>\s*s0\s*\*\s*xi0"
    r"|_div_pd\(\s*_mm(?:256|512)_mul_pd\(\s*\w*coef|_mul_pd\(\s*\w*quarter"
    r"|_sub_pd\(\s*vs00\s*,\s*_mm(?:256|512)_mul_pd\(\s*valpha")
BOND_MODEL = "bbpd_bond_model.h"


def bond_arithmetic(text):
    """lines of code (comments dropped) that compute a bond's force, energy or breaking test"""
    code = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    code = re.sub(r"//[^\n]*", "", code)
    return [n + 1 for n, line in enumerate(code.splitlines()) if BOND_ARITHMETIC.search(line)]


@pytest.mark.parametrize("name", sorted(p.name for p in SRC.glob("*.[hc]*") if p.name != BOND_MODEL))
def test_bond_arithmetic_lives_in_the_bond_model(name):
    lines = bond_arithmetic((SRC / name).read_text())
    assert not lines, f"{name}:{lines}: what a bond does belongs in {BOND_MODEL} (doc/architecture.rst)"


def test_bond_arithmetic_is_found():
    """negative control: the loops as they were before the bond model"""
    assert bond_arithmetic("    const double fbond = coef * elong / r;\n") == [1]
    assert bond_arithmetic("    if (FRACTURE) broken |= elong + margin > s0_of(j) * xi0;\n") == [1]
    assert bond_arithmetic("  return breaking_length(i, j) - xi0 > s0 * xi0;\n") == [1]
    assert bond_arithmetic("x;\nconst __m256d fbond = _mm256_div_pd(_mm256_mul_pd(coef, elong), r);") == [2]
    assert bond_arithmetic("const __m256d s0 = _mm256_sub_pd(vs00, _mm256_mul_pd(valpha, smax));") == [1]
    assert bond_arithmetic("// coef * elong / r in a comment\n/* elong + margin > s0 xi0 */\n") == []
    assert bond_arithmetic((SRC / BOND_MODEL).read_text())    # the model itself has them


# The loops take the bond model, the breaking rule and the family's weighting as parameters
# and name none: a model is added beside the others, not swapped in (doc/architecture.rst).
# The model headers define them; bbpd_plugin_model.h lists those the plugin is compiled with,
# and a style picks its own where it calls a loop (eval_bonds, init_rules).
MODEL_HEADERS = ("bbpd_bond_model.h", "bbpd_pmb_rules.h", "bbpd_bond_weighting.h")
# whole files that are loops (pair_bbpd_rows.h: the row driver eval_rows of every style), and
# the loop functions of the pair styles. bbpd/lps's rows (PairBBPDLPS::Row, pair_bbpd_lps.cpp)
# and their bond loop (bbpd_lps_row.h) are not among them: they are the LPS model itself, whose
# force state reads both ends and is not a bond model (doc/architecture.rst, "The row driver").
LOOP_FILES = ("bbpd_row.h", "bbpd_stretch_row.h", "bbpd_row_path_kernels.h", "bbpd_row_avx2.cpp",
              "bbpd_row_avx512.cpp", "pair_bbpd_rows.h")
LOOP_FUNCTIONS = {"pair_bbpd.cpp": ("eval", "row_force"),
                  "pair_bbpd_silling_askari.cpp": ("eval_silling_askari", "broken_bond_force")}
# a family named in code: the template switches the loops had before (bool PMB, law.pmb, ...)
FAMILY_WORD = r"\b(?:PMB|pmb|LPS|lps)\b"


def without_comments(text):
    code = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", code)


def model_names():
    """the bond models, rules and weightings the model headers define"""
    names = set()
    for h in MODEL_HEADERS:
        names |= set(re.findall(r"^\s*(?:template\s*<[^>]*>\s*)?struct\s+(\w+)",
                                without_comments((SRC / h).read_text()), re.M))
    return names


def function_bodies(text, name):
    """the bodies of the member functions NAME defined in text (Class::NAME(...) ... { ... })"""
    code, bodies = without_comments(text), []
    for m in re.finditer(rf"^[^\n;]*\b\w+::{name}\s*\(", code, re.M):
        start = code.index("{", m.end())
        if ";" in code[m.end():start] and ")" not in code[m.end():start].split(";")[0]:
            continue    # a call or declaration, not a definition
        depth, k = 0, start
        while True:
            depth += {"{": 1, "}": -1}.get(code[k], 0)
            k += 1
            if depth == 0:
                break
        bodies.append(code[start:k])
    return bodies


def models_named(code, names):
    """the model names and family words in a loop's code"""
    pattern = re.compile(r"\b(?:" + "|".join(sorted(names)) + r")\b|" + FAMILY_WORD)
    return sorted(set(pattern.findall(code)))


def loop_codes():
    for f in LOOP_FILES:
        yield f, without_comments((SRC / f).read_text())
    for f, functions in LOOP_FUNCTIONS.items():
        for fn in functions:
            bodies = function_bodies((SRC / f).read_text(), fn)
            assert bodies, f"{f}: no definition of {fn} found (renamed? update LOOP_FUNCTIONS)"
            for b in bodies:
                yield f"{f}:{fn}", b


def test_model_headers_define_the_models():
    assert {"CriticalStretchBond", "SillingAskariRule", "PeriPmbRule", "KernelWeighting",
            "PmbWeighting", "LpsWeighting", "LpsKernelWeighting"} <= model_names()


@pytest.mark.parametrize("where,code", list(loop_codes()), ids=lambda v: v if len(v) < 60 else "")
def test_no_loop_names_a_model(where, code):
    named = models_named(code, model_names())
    assert not named, (f"{where} names {named}: a loop takes the bond model, rule and weighting "
                       "as parameters (doc/architecture.rst, 'Adding a model')")


def test_a_loop_naming_a_model_is_found():
    """negative control: the Silling-Askari loop as it was, with a switch per family"""
    before = ("template <int EVFLAG, bool PMB> void PairBBPDAlpha::eval_silling_askari()\n{\n"
              "  double elong = CriticalStretchBond::elongation(r, xi0);  // PMB: zero\n"
              "  if (PMB && std::fabs(elong) < NEAR_ZERO) elong = 0.0;\n}\n"
              "void f() { eval_silling_askari<1, true>(); }\n")
    bodies = function_bodies(before, "eval_silling_askari")
    assert len(bodies) == 1
    assert models_named(bodies[0], model_names()) == ["CriticalStretchBond", "PMB"]
    assert models_named("  if (law.lps) coef = omega;\n", model_names()) == ["lps"]
    assert models_named("  const double e = Rule::settled_elongation(Model::elongation(r, xi0));",
                        model_names()) == []


def style_questions(header):
    """the virtual yes/no questions a base class header asks its derived classes
    ('virtual bool name(...) const'): what a style is belongs in a value it hands over"""
    return re.findall(r"\bvirtual\s+bool\s+(\w+)\s*\([^)]*\)\s*const", without_comments(header))


def test_the_base_class_asks_no_style_what_it_is():
    """PairBBPD reads the rules a style gives it (PairBBPD::Rules at construction), and asks
    no derived class whether it is one kind or another (doc/architecture.rst)"""
    assert style_questions((SRC / "pair_bbpd.h").read_text()) == []
    assert "Rules" in (SRC / "pair_bbpd.h").read_text()


def test_a_style_question_is_found():
    """negative control: the hooks as they were"""
    before = ("  virtual bool silling_askari() const { return false; }    // alpha is a rule\n"
              "  virtual bool pmb_rules() const { return false; }\n"
              "  virtual double bond_stiffness(int i, int k) const;\n")
    assert style_questions(before) == ["silling_askari", "pmb_rules"]


# ------------------------------------------------------------- a flat class picture

# the pair classes' bases, from their declarations ('class Name : public Base {', also 'final'
# and several bases); LAMMPS's Pair is the root
CLASS_DECL = re.compile(r"\bclass\s+(\w+)\s*(?:final\s*)?:\s*([^{;]+)\{")
# at most two levels below LAMMPS's Pair (PairBBPD and one thin style class): what the styles
# share is held (the Silling-Askari state) or called (the Silling-Askari loop, peri/pmb's
# pieces), not inherited, and a style's variants are values it holds (the LPS family, where its
# coefficients come from), not subclasses (doc/architecture.rst, "The class picture")
MAX_LEVELS_BELOW_PAIR = 2


def pair_class_bases(texts):
    """{class: [bases]} of the classes declared with bases in the header texts"""
    bases = {}
    for text in texts:
        for name, spec in CLASS_DECL.findall(without_comments(text)):
            bases[name] = [b.split()[-1] for b in spec.split(",")]
    return bases


def levels_below_pair(bases):
    """{class: its levels below Pair on its longest path} for the classes whose bases lead to
    Pair (a class derived from Pair: 1, a class derived from that: 2, ...)"""
    def levels(name, seen=()):
        assert name not in seen, f"circular bases at {name}"
        paths = []
        for b in bases.get(name, []):
            up = 0 if b == "Pair" else levels(b, seen + (name,)) if b in bases else None
            if up is not None:
                paths.append(up + 1)
        return max(paths, default=None)
    return {name: n for name in bases if (n := levels(name)) is not None}


def too_deep(texts):
    return sorted(n for n, lv in levels_below_pair(pair_class_bases(texts)).items()
                  if lv > MAX_LEVELS_BELOW_PAIR)


def test_no_pair_class_sits_more_than_two_levels_below_pair():
    texts = [p.read_text() for p in sorted(SRC.glob("pair_*.h"))]
    levels = levels_below_pair(pair_class_bases(texts))
    # the parser sees every style class of the plugin
    assert {"PairBBPD", "PairBBPDAlpha", "PairBBPDPMB", "PairBBPDLPS"} <= set(levels), levels
    assert levels["PairBBPD"] == 1
    assert too_deep(texts) == [], levels


def test_a_deep_pair_class_is_found():
    """negative controls: a class three levels below Pair, the chain of one class per feature,
    and the kernel LPS styles as a class below PairBBPDLPS"""
    three = ("class PairA : public PairBBPD {\n};\nclass PairB final : public PairA {\n};\n"
             "class PairC : public PairB, public Other {\n};\n")
    base = "class PairBBPD : public Pair {\n};\n"
    assert levels_below_pair(pair_class_bases([base, three])) == {
        "PairBBPD": 1, "PairA": 2, "PairB": 3, "PairC": 4}
    assert too_deep([base, three]) == ["PairB", "PairC"]
    chain = base + ("class PairBBPDAlpha : public PairBBPD {\n};\n"
                    "class PairBBPDPMB : public PairBBPDAlpha {\n};\n"
                    "class PairBBPDLPS : public PairBBPDPMB {\n};\n"
                    "class PairBBPDLPSKernel : public PairBBPDLPS {\n};\n")
    assert too_deep([chain]) == ["PairBBPDLPS", "PairBBPDLPSKernel", "PairBBPDPMB"]
    kernel_subclass = base + ("class PairBBPDLPS : public PairBBPD {\n};\n"
                              "class PairBBPDLPSKernel : public PairBBPDLPS {\n};\n")
    assert too_deep([kernel_subclass]) == ["PairBBPDLPSKernel"]


# the per-atom state of the internal fixes is grown, migrated and written to restart files in
# one place, FixBBPDAtomState (fix_bbpd_atom_state.h), when each atom has the same width; the
# bond storage and the bonds' history keep rows as long as each atom's family, through the
# rows of bbpd_partner_rows.h, and pack them themselves
STATE_BASE = "FixBBPDAtomState"
ROWS = "BBPD::PartnerRows<"
OWN_PER_ATOM_RESTART = {"FixBBPDAtomState", "FixBBPDBonds", "FixBBPDHistory"}


def per_atom_restart_classes(texts):
    """the classes declared in the header texts that write per-atom restart data themselves
    (declare pack_restart)"""
    found = set()
    for text in texts:
        code = without_comments(text)
        decls = list(re.finditer(r"\bclass\s+(\w+)\s*(?:final\s*)?:[^{;]+\{", code))
        for k, m in enumerate(decls):
            body = code[m.end():decls[k + 1].start() if k + 1 < len(decls) else len(code)]
            if re.search(r"\bpack_restart\s*\(", body):
                found.add(m.group(1))
    return found


def test_fixes_with_per_atom_state_share_one_base():
    texts = [p.read_text() for p in sorted(SRC.glob("fix_*.h"))]
    assert per_atom_restart_classes(texts) == OWN_PER_ATOM_RESTART
    bases = pair_class_bases(texts)
    for fix in ("FixBBPDAlpha", "FixBBPDWork", "FixBBPDLPS"):
        assert bases[fix] == [STATE_BASE], (fix, bases.get(fix))
    for header in ("fix_bbpd_bonds.h", "fix_bbpd_history.h"):
        assert ROWS in (SRC / header).read_text(), header


def test_a_fix_with_its_own_per_atom_restart_is_found():
    """negative control: fix bbpd/lps as it was, its three arrays packed by itself"""
    before = ("class FixBBPDLPS : public Fix {\n public:\n  void grow_arrays(int) override;\n"
              "  int pack_restart(int, double *) override;\n  double *dilatation;\n};\n")
    assert per_atom_restart_classes([before]) == {"FixBBPDLPS"}


def row_loops_outside_the_driver(files):
    """{file: n}: calls of the threaded row loop for_each_row outside the row driver
    (PairBBPD::eval_rows), in the code of files {name: text}"""
    found = {}
    for name, text in files.items():
        code = without_comments(text)
        for body in function_bodies(code, "eval_rows"):
            code = code.replace(body, "")
        calls = len(re.findall(r"\bfor_each_row\s*<", code))    # its definition has no <...>
        if calls:
            found[name] = calls
    return found


def test_every_style_runs_its_rows_through_the_driver():
    files = {f.name: f.read_text() for f in sorted(SRC.glob("*.cpp")) + sorted(SRC.glob("*.h"))}
    assert "eval_rows" in without_comments(files["pair_bbpd_rows.h"])
    for name in ("pair_bbpd.cpp", "pair_bbpd_silling_askari.cpp", "pair_bbpd_lps.cpp"):
        assert re.search(r"\beval_rows\s*<", without_comments(files[name])), name
    assert row_loops_outside_the_driver(files) == {}


def test_a_row_loop_outside_the_driver_is_found():
    """negative control: the LPS loop as it was, a for_each_row of its own"""
    before = ("template <int EVFLAG> void PairBBPDLPS::eval_lps()\n{\n"
              "  for_each_row<EVFLAG>([&](int i, double *fi, double *acc, CoefCache *c) {});\n}\n")
    assert row_loops_outside_the_driver({"pair_bbpd_lps.cpp": before}) == {"pair_bbpd_lps.cpp": 1}


def test_architecture_doc_shows_the_tested_toy_model():
    """the bond model of the walkthrough is the one the unit test runs through every width and
    the test build puts in the plugin (tests/unit/toy_bond_models.h)"""
    doc = (SRC.parent / "doc" / "architecture.rst").read_text()
    block = re.search(r"\.\. code-block:: c\+\+\n\n(.*?)\n\n", doc, re.S).group(1)
    test = (SRC.parent / "tests" / "unit" / "toy_bond_models.h").read_text()
    squeeze = lambda t: " ".join(t.split())
    assert "struct SymmetricStretchBond : BBPD::CriticalStretchBond" in block
    assert squeeze(block) in squeeze(test)


def test_src_includes_have_no_circle():
    assert circles(include_graph()) == []


PYTHON = Path(__file__).resolve().parents[1] / "python"
# what a function may import: modules outside bbpd that are optional or only for plotting
LAZY_IMPORTS = {
    "matplotlib": "plotting only: the Agg backend is chosen before pyplot is imported, and the "
                  "analysis that every run job imports does without it",
    "lammps": "LAMMPS's own Python module exists only with a LAMMPS build (bbpd.inprocess)",
}


def python_modules(root=PYTHON, package="bbpd"):
    """{dotted name: path} of the package's modules (a package by the name of its folder)"""
    mods = {}
    for p in sorted((root / package).rglob("*.py")):
        parts = list(p.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        mods[".".join(parts)] = p
    return mods


def imports_of(module, path, mods):
    """[(line, imported module, inside a function)] of one module; `from P import x` names the
    submodule P.x where there is one; relative imports resolved"""
    tree = ast.parse(path.read_text())
    inside = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            inside.update(id(n) for n in ast.walk(node) if n is not node)
    here = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(here[:len(here) - node.level + 1] + ([base] if base else []))
            names = [f"{base}.{a.name}" if f"{base}.{a.name}" in mods else base
                     for a in node.names]
        else:
            continue
        found += [(node.lineno, name, id(node) in inside) for name in names]
    return found


def python_import_graph(root=PYTHON, package="bbpd"):
    """{module: modules of the package that importing it imports}: the modules it names, at
    module level or in a function, and the packages above them (their __init__ runs first)
    that are not its own"""
    mods = python_modules(root, package)
    graph = {}
    for module, path in mods.items():
        own = {".".join(module.split(".")[:k]) for k in range(1, module.count(".") + 1)}
        edges = set()
        for _, name, _ in imports_of(module, path, mods):
            parts = name.split(".")
            edges |= {".".join(parts[:k]) for k in range(1, len(parts) + 1)} & set(mods)
        graph[module] = edges - own - {module}
    return graph


def imports_in_functions(root=PYTHON, package="bbpd"):
    mods = python_modules(root, package)
    return sorted({f"{path.relative_to(root)}:{line}: import {name} inside a function"
                   for module, path in mods.items()
                   for line, name, inner in imports_of(module, path, mods)
                   if inner and name.split(".")[0] not in LAZY_IMPORTS})


def test_python_imports_no_module_inside_a_function():
    """an import inside a function hides an edge of the import graph (it was used to dodge
    circles): import at module level, except the optional modules of LAZY_IMPORTS"""
    assert imports_in_functions() == []


def test_python_imports_have_no_circle():
    assert circles(python_import_graph()) == []


def folder_graph(graph, mods):
    """the import graph between the package's folders (bbpd, bbpd.benchmarks, bbpd.report, ...):
    a module belongs to the folder of its file"""
    def folder(m):
        return ".".join(m.split(".")[:-1]) if mods[m].name != "__init__.py" else m
    out = {}
    for m, targets in graph.items():
        out.setdefault(folder(m), set()).update(folder(t) for t in targets if folder(t) != folder(m))
    return out


def test_python_folders_import_one_way():
    """no folder imports one that imports it back (bbpd.report and bbpd.work_precision did)"""
    mods = python_modules()
    assert circles(folder_graph(python_import_graph(), mods)) == []


# the layers of doc/architecture.rst, from the bottom up: a module imports its own layer or
# those below
PYTHON_LAYERS = [
    {"bbpd", "bbpd.inprocess", "bbpd.jobs", "bbpd.kernels", "bbpd.readers", "bbpd.reference",
     "bbpd.runner", "bbpd.freund", "bbpd.metrics", "bbpd.dsif", "bbpd.plots",
     "bbpd.crack_tip", "bbpd.crack_branches", "bbpd.crack_motion", "bbpd.kink", "bbpd.crack_path",
     "bbpd.provenance", "bbpd.csvfile", "bbpd.markers", "bbpd.markdown", "bbpd.snapshots"},
    {"bbpd.benchmarks", "bbpd.benchmarks.dispersion", "bbpd.benchmarks.kalthoff_winkler",
     "bbpd.benchmarks.kalthoff_winkler_study", "bbpd.benchmarks.mode1", "bbpd.benchmarks.mode2",
     "bbpd.benchmarks.stability", "bbpd.benchmarks.mode1_propagation",
     "bbpd.benchmarks.kalthoff_winkler_projectile", "bbpd.benchmarks.kink",
     "bbpd.benchmarks.kink_kalthoff_winkler", "bbpd.benchmarks.kink_convergence",
     "bbpd.benchmarks.kink_limit", "bbpd.benchmarks.kalthoff_winkler_grid",
     "bbpd.benchmarks.kalthoff_winkler_deck", "bbpd.benchmarks.kalthoff_winkler_3d",
     "bbpd.benchmarks.strip", "bbpd.benchmarks.strip_closure", "bbpd.benchmarks.branching",
     "bbpd.benchmarks.mode1_lps", "bbpd.benchmarks.cli",
     "bbpd.benchmarks.big_run", "bbpd.benchmarks.plate_hole", "bbpd.benchmarks.center_crack",
     "bbpd.benchmarks.center_crack_growth", "bbpd.benchmarks.quasi_static",
     "bbpd.benchmarks.dcb_growth", "bbpd.benchmarks.kfield_probe"},
    {"bbpd.report", "bbpd.report.runs", "bbpd.report.tables",
     "bbpd.report.sections", "bbpd.report.results",
     "bbpd.report.work_precision_figure"},
    {"bbpd.report.work_precision"},
    {"bbpd.report.document", "bbpd.report.make", "bbpd.report.__main__"},
    {"bbpd.claims", "bbpd.claims.__main__", "bbpd.claims.blocks", "bbpd.claims.checks",
     "bbpd.claims.data", "bbpd.claims.paper", "bbpd.claims.times", "bbpd.claims.crack",
     "bbpd.claims.perf"},
]


def test_python_layers_cover_the_package():
    assert set().union(*PYTHON_LAYERS) == set(python_modules())


def test_python_imports_run_one_way():
    layer = {m: k for k, mods in enumerate(PYTHON_LAYERS) for m in mods}
    up = sorted(f"{m} imports {t}" for m, targets in python_import_graph().items()
                for t in targets if layer[t] > layer[m])
    assert up == []


# negative controls: the checks above find what they are for

def test_a_folder_circle_is_found(tmp_path):
    """negative control: bbpd.report.x imports bbpd.y, which imports bbpd.report.z"""
    pkg = tmp_path / "toy"
    (pkg / "report").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "report" / "__init__.py").write_text("")
    (pkg / "report" / "x.py").write_text("from toy import y\n")
    (pkg / "report" / "z.py").write_text("")
    (pkg / "y.py").write_text("from toy.report import z\n")
    mods = python_modules(tmp_path, "toy")
    assert circles(python_import_graph(tmp_path, "toy")) == []
    assert circles(folder_graph(python_import_graph(tmp_path, "toy"), mods)) == [["toy", "toy.report"]]


def test_a_circle_is_found():
    assert circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert circles({"a": {"a"}, "b": set()}) == [["a"]]
    assert circles({"a": {"b"}, "b": set()}) == []


def test_an_include_circle_is_found(tmp_path):
    (tmp_path / "a.h").write_text('#include "b.h"\n')
    (tmp_path / "b.h").write_text('#include "c.h"\n#include <vector>\n')
    (tmp_path / "c.h").write_text('#include "a.h"\n')
    (tmp_path / "d.cpp").write_text('#include "a.h"\n')
    assert circles(include_graph(tmp_path)) == [["a.h", "b.h", "c.h"]]


def test_a_hidden_import_circle_is_found(tmp_path):
    """the pattern removed from python/bbpd: a package whose __init__ imports its top module,
    which imports a module outside that imports the package's building blocks in a function"""
    pkg = tmp_path / "toy"
    (pkg / "report").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "report" / "__init__.py").write_text("from .make import reproduce\n")
    (pkg / "report" / "make.py").write_text("from toy import extra\n\ndef reproduce():\n"
                                            "    return extra.more()\n")
    (pkg / "report" / "runs.py").write_text("RUNS = 1\n")
    (pkg / "extra.py").write_text("import math\n\n\ndef more():\n"
                                  "    from toy.report.runs import RUNS\n"
                                  "    import matplotlib\n    return RUNS\n")
    assert imports_in_functions(tmp_path, "toy") == [
        "toy/extra.py:5: import toy.report.runs inside a function"]
    assert circles(python_import_graph(tmp_path, "toy")) == [
        ["toy.extra", "toy.report", "toy.report.make"]]
