# SPDX-License-Identifier: GPL-2.0-or-later
"""Check a file's text against the data (every block as rendered, every speed ratio with its
CPU), and write the blocks."""
import re
import textwrap

from bbpd import markers
from bbpd.jobs import ROOT

from .blocks import BLOCKS
from .data import Data

# a speed ratio ("17.6x faster", "| 6.1x |") must name the CPU model in its paragraph, its
# heading or the first paragraph of its section (where a section states its setup): the
# ratio of two codes changes with the CPU and its vector units
SPEED = re.compile(r"\b\d+(\.\d+)?\s?[x×](?=[\s,.;:)*|])(?! \d)")
SPEED_CONTEXT = re.compile(r"faster|slower|speed|loop|pair time|ratio", re.I)
CPU = re.compile(r"Xeon|EPYC|Zen \d|Sapphire Rapids|Ryzen|Core i\d|Apple M\d|Graviton")


WIDTH = {".md": 100, ".rst": 76}
MARKUP_START = re.compile(r"\s*([-+*#>=|]|\d+[.)]|\.\.)(\s|$)")


def render(rel, name, data):
    """The body of block `name` of file `rel`: its function's text, paragraphs and bullets
    wrapped as the file's prose is (table rows stay one line each)."""
    text = BLOCKS[rel][name](data)
    width = WIDTH[".rst" if rel.endswith(".rst") else ".md"]
    out = []
    for para in text.split("\n"):
        if para.startswith("|") or not para.strip():
            out.append(para)
            continue
        indent = "  " if para.startswith("- ") else ""
        lines = textwrap.wrap(para, width, subsequent_indent=indent, break_long_words=False,
                              break_on_hyphens=False)
        i = 1
        while i < len(lines):    # a continuation line must not start a list, heading or quote
            if MARKUP_START.match(lines[i]):
                word, _, rest = lines[i].strip().partition(" ")
                lines[i - 1] += " " + word
                lines[i] = indent + rest
                if not rest:
                    del lines[i]
                continue
            i += 1
        out.append("\n".join(lines))
    return "\n".join(out)


def check_text(rel, text, data=None):
    """Problems of one file's text (rel: its path from the repository root)."""
    data = data or Data()
    problems = []
    expected = BLOCKS.get(rel, {})
    found = {}
    for kind, name, body in markers.blocks(rel, text):
        if name in found:
            problems.append(f"{rel}: block {name} appears twice")
        found[name] = body
        if name not in expected:
            problems.append(f"{rel}: block {name} is not known to bbpd.claims.blocks")
            continue
        try:
            want = render(rel, name, data)
        except FileNotFoundError as exc:
            problems.append(f"{rel}: block {name}: {exc}")
            continue
        if body != want:
            problems.append(f"{rel}: block {name} disagrees with its data:\n"
                            + first_difference(body, want))
    for name in expected:
        if name not in found:
            problems.append(f"{rel}: block {name} is missing (add its markers)")
    problems += speed_without_cpu(rel, text)
    return problems


def first_difference(have, want):
    a, b = have.splitlines(), want.splitlines()
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return f"  line {i + 1}\n  text: {x}\n  data: {y}"
    return f"  text has {len(a)} lines, data {len(b)}"


def speed_without_cpu(rel, text):
    """Speed ratios of the README files whose section names no CPU."""
    if not (rel == "README.md" or ROOT.joinpath(rel).match("examples/*/README.md")):
        return []
    text = re.sub(r"^```.*?^```", lambda m: "\n" * m.group(0).count("\n"), text,
                  flags=re.S | re.M)    # code blocks hold no claims
    out = []
    for section in re.split(r"^(?=#)", text, flags=re.M):
        paras = [p for p in re.split(r"\n\s*\n", section) if p.strip()]
        heading = paras[0] if paras and paras[0].startswith("#") else ""
        intro = next((p for p in paras if not p.startswith("#")), "")
        for para in paras:
            if CPU.search(para) or CPU.search(heading) or CPU.search(intro):
                continue
            for m in SPEED.finditer(para):
                context = para[max(0, m.start() - 80):m.end() + 80]
                if SPEED_CONTEXT.search(context):
                    out.append(f"{rel}: speed ratio '{m.group(0)}' without a CPU: "
                               f"...{' '.join(context.split())}...")
    return out


def files():
    return sorted(set(BLOCKS) | {str(p.relative_to(ROOT)) for p in
                                 [ROOT / "README.md", *ROOT.glob("examples/*/README.md")]})


def check(data=None):
    """Problems of every file (empty: text and data agree)."""
    data = data or Data()
    problems = []
    for rel in files():
        problems += check_text(rel, (ROOT / rel).read_text(encoding="utf-8"), data)
    return problems


def write(data=None):
    """Rewrite every block from the data (a block whose data file is missing is kept);
    returns the files changed."""
    data = data or Data()
    changed = []

    def body(rel, name):
        try:
            return render(rel, name, data) if name in BLOCKS[rel] else None
        except FileNotFoundError:
            return None
    for rel in BLOCKS:
        path = ROOT / rel
        old = path.read_text(encoding="utf-8")
        new = markers.replace(rel, old, lambda kind, name: body(rel, name))
        if new != old:
            path.write_text(new, encoding="utf-8")
            changed.append(rel)
    return changed
