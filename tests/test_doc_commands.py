# SPDX-License-Identifier: GPL-2.0-or-later
"""Every shell command in the READMEs and the docs runs as written on a fresh clone.

The fenced shell blocks (```sh in Markdown, ``.. code-block:: sh`` in RST) are read as a user
would run them from the repository root, following ``cd`` and ``REPO=$PWD``: every repository
path they name must exist, no command may name a machine-specific absolute path, and the cheap
ones run: ``--help`` of each program (every option the command uses must be in its help),
``tools/lmp -h``, and pytest commands with ``--collect-only``.
"""
import os
import re
import shlex
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHELL = {"sh", "bash", "shell", "console"}
VERSION = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
BUILT = (ROOT / "build" / f"lammps-{VERSION}" / "bbpd-env.sh").is_file()
GENERATED = ("build", "report")    # folders the commands create; not in a fresh clone
STYLE_WORDS = {"plane/strain", "plane/stress"}    # values of -var model, not paths
NOT_RUN = {"tools/bootstrap", "tools/test", "tools/reproduce", "cmake", "mpirun", "mkdir", "cd",
           "export"}


def doc_files():
    files = [ROOT / "README.md", ROOT / "python" / "README.md"]
    files += sorted((ROOT / "examples").glob("*/README.md"))
    files += sorted((ROOT / "doc").glob("*.md")) + sorted((ROOT / "doc").glob("*.rst"))
    return [f for f in files if f.is_file()]


def code_blocks(path):
    """(language, text, first line) of every fenced / code-block block of a file."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".md":
        for m in re.finditer(r"^```(\S*)[^\n]*\n(.*?)^```", text, re.M | re.S):
            yield m.group(1), m.group(2), text[:m.start()].count("\n") + 1
    else:
        for m in re.finditer(r"^\.\. code-block::\s*(\S+)\n((?:[ \t]*\n|[ \t]+\S[^\n]*\n)+)",
                             text, re.M):
            body = "\n".join(ln[3:] if ln.startswith("   ") else ln
                             for ln in m.group(2).splitlines())
            yield m.group(1), body, text[:m.start()].count("\n") + 1


def shell_blocks():
    for path in doc_files():
        for lang, body, line in code_blocks(path):
            if lang in SHELL:
                yield pytest.param(body, id=f"{path.relative_to(ROOT)}:{line}")


INLINE_COMMAND = re.compile(r"^(\w+=\S+ )*(tools/|perf/|/usr/bin/python3 |mpirun |cmake )")


def inline_commands():
    """Commands written inline (`tools/lmp -in in.script` in Markdown, ``...`` in RST)."""
    for path in doc_files():
        text = path.read_text(encoding="utf-8")
        pattern = r"``([^`]+)``" if path.suffix == ".rst" else r"(?<!`)`([^`]+)`(?!`)"
        for m in re.finditer(pattern, text):
            code = " ".join(m.group(1).split())
            if INLINE_COMMAND.match(code) and " " in code:
                line = text[:m.start()].count("\n") + 1
                yield pytest.param(code, id=f"{path.relative_to(ROOT)}:{line}: {code}")


def split_commands(body):
    """Token lists of the commands of a block (continuations joined, comments dropped)."""
    commands = []
    for line in body.replace("\\\n", " ").splitlines():
        lexer = shlex.shlex(line, posix=True, punctuation_chars=";&|")
        lexer.whitespace_split = True
        command = []
        for token in lexer:
            if token in (";", "&&", "||", "|", "&"):
                commands.append(command)
                command = []
            else:
                command.append(token)
        commands.append(command)
    return [c for c in commands if c]


class Session:
    """A shell started at the repository root: cwd, variables, what the commands name."""

    def __init__(self):
        self.cwd = ROOT
        self.vars = {}

    def expand(self, token):
        def value(m):
            name = m.group(1) or m.group(2)
            if name == "PWD":
                return str(self.cwd)
            assert name in self.vars, f"${name} is used but never set in the block"
            return self.vars[name]
        return re.sub(r"\$\{(\w+)\}|\$(\w+)", value, token)

    def resolve(self, token):
        """The repository path a token names (relative to ROOT), or None."""
        if token.startswith("-") or "/" not in token or token in STYLE_WORDS:
            return None
        path = Path(token) if token.startswith("/") else self.cwd / token
        path = Path(os.path.normpath(path))
        if path == ROOT or ROOT in path.parents:
            return path.relative_to(ROOT)
        assert not re.match(r"^/(work|home|root)/", token), \
            f"machine-specific absolute path {token}: name it relative to the repository"
        return None


def check_path(rel, command):
    head = rel.parts[0]
    if head in GENERATED:
        built_lammps = len(rel.parts) > 1 and rel.parts[1] == f"lammps-{VERSION}"
        if not (built_lammps and BUILT):
            return
    assert (ROOT / rel).exists(), f"{' '.join(command)}: {rel} does not exist"


def run(cmd, cwd, **kw):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=300, **kw)


def check_options(command, helptext):
    used = {t.split("=")[0] for t in command if re.match(r"^--[a-z]", t)}
    missing = sorted(o for o in used if o not in helptext)
    assert not missing, f"{' '.join(command)}: {missing} not in its --help"


def run_cheap(command, session):
    """Run the cheap form of a command; return what was run (or None)."""
    program = session.resolve(command[0])
    name = str(program) if program else command[0]
    if name in NOT_RUN or not BUILT and name.startswith(("tools/lmp", "build/")):
        return None
    module = command[command.index("-m") + 1] if "-m" in command[1:-1] else None
    if module in ("venv", "pip"):
        return None    # the install route is tests/python/test_package.py
    cwd = session.cwd if session.cwd.is_dir() else ROOT
    exe = str(ROOT / program) if program else command[0]
    if name == "tools/python":
        target = command[1:3] if command[1] == "-m" else command[1:2]
        proc = run([exe, *target, "--help"], cwd)
        assert proc.returncode == 0, f"{' '.join(command)}: --help failed\n{proc.stderr}"
        check_options(command, proc.stdout)
    elif name == "tools/lmp":
        proc = run([exe, "-h"], cwd)
        assert proc.returncode == 0 and "Large-scale Atomic/Molecular" in proc.stdout, proc.stderr
    elif program and program.parts[:2] == ("build", f"lammps-{VERSION}"):
        proc = run([exe, "--help"], cwd)
        assert proc.returncode == 0, f"{' '.join(command)}: --help failed\n{proc.stderr}"
        check_options(command, proc.stdout + proc.stderr)
    elif program and program.parts[0] == "perf" and program.suffix == ".sh":
        proc = run([exe, "--help"], cwd)
        assert proc.returncode == 0 and proc.stdout, f"{' '.join(command)}: --help failed\n{proc.stderr}"
    elif command[:3] == ["/usr/bin/python3", "-m", "pytest"]:
        proc = run([*command, "--collect-only", "-p", "no:cacheprovider"], cwd)
        assert proc.returncode == 0, f"{' '.join(command)}: collects no test\n{proc.stdout}"
    elif command[:3] == ["/usr/bin/python3", "-m", "sphinx"]:
        return None    # the docs build is tests/test_docs.py
    else:
        pytest.fail(f"no cheap form known for {' '.join(command)}: teach run_cheap")
    return name


@pytest.mark.parametrize("body", list(shell_blocks()) + list(inline_commands()))
def test_shell_block_runs_as_written(body):
    session = Session()
    for command in split_commands(body):
        command = [session.expand(t) for t in command]
        while command and re.match(r"^\w+=", command[0]):    # VAR=value [command]
            name, value = command.pop(0).split("=", 1)
            if not command:
                session.vars[name] = value
        if not command:
            continue
        for token in command:
            if re.match(r"^(--?[\w-]+|[A-Za-z_]\w*)=", token):    # --out=PATH, NAME=PATH
                token = token.split("=", 1)[1]
            rel = session.resolve(token)
            if rel is not None:
                check_path(rel, command)
        if command[0] == "cd":
            session.cwd = Path(os.path.normpath(session.cwd / command[1]))
            continue
        run_cheap(command, session)


def test_every_markdown_code_block_names_its_language():
    # an unlabelled block could hide a shell command from the test above
    for path in doc_files():
        if path.suffix == ".md":
            for lang, body, line in code_blocks(path):
                assert lang, \
                    f"{path.relative_to(ROOT)}:{line}: ``` without a language (sh, lammps, ...)"


def test_shell_blocks_are_found():
    # guard against a parser that silently finds nothing
    ids = [p.id for p in shell_blocks()]
    assert any(i.startswith("README.md") for i in ids) and any("examples/" in i for i in ids)
    assert any(i.startswith("doc/build.rst") for i in ids)


def test_docs_name_no_machine_specific_paths():
    for path in doc_files():
        text = path.read_text(encoding="utf-8")
        assert "/work/" not in text and str(ROOT) not in text, \
            f"{path.relative_to(ROOT)} names a path of one machine"
