# SPDX-License-Identifier: GPL-2.0-or-later
"""Sphinx directive ``markdown-include``: show a Markdown file of the repository
(an example's README.md, doc/performance.md, ...) inside an RST page.

Debian's Sphinx has no Markdown parser (no myst-parser), so this renders the
subset our Markdown files use, building docutils nodes directly: the text is
never parsed as RST, so nothing a Markdown author writes can make the build
warn. Supported: ``#`` headings (as rubrics), paragraphs, ``-``/``*`` and
``1.`` lists (one level), pipe tables, fenced and indented code blocks, ``>``
quotes; inline ```code```, ``**strong**``, ``*emphasis*``, ``[text](url)`` and
``![alt](image)``; one-line ``<!-- comments -->`` are dropped. Relative links to files become download links (a
``figure.png`` code span naming a file beside the Markdown is one too); a relative
link to a missing file or a folder is shown as its text with the path.

    .. markdown-include:: ../examples/kalthoff-winkler/README.md
       :skip-title:          drop the first '# ' heading (the page has its own)
       :optional:            a missing file gives a "not written yet" note
       :figures:             append every linked .png as a figure
"""

import os
import re

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx import addnodes

# [text](target) or ![alt](target); `code`; **strong**; *emphasis* (not around spaces)
INLINE = re.compile(r"(?P<img>!)?\[(?P<text>[^\]]*)\]\((?P<url>[^)\s]+)\)"
                    r"|`(?P<code>[^`]+)`"
                    r"|\*\*(?P<strong>[^*\s](?:[^*]*[^*\s])?)\*\*"
                    r"|\*(?P<em>[^*\s](?:[^*]*[^*\s])?)\*")
TABLE_RULE = re.compile(r"^\s*\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?\s*$")
LIST_ITEM = re.compile(r"^(?P<indent>\s{0,3})(?P<mark>[-*]|\d+[.)])\s+(?P<rest>.*)$")
HEADING = re.compile(r"^(?P<level>#{1,6})\s+(?P<text>.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")
COMMENT_LINE = re.compile(r"^\s*<!--.*-->\s*$")
IMAGE_FILE = re.compile(r"[\w./-]+\.(png|jpg|jpeg|svg)", re.IGNORECASE)


class MarkdownInclude(Directive):
    required_arguments = 1
    option_spec = {"skip-title": directives.flag, "optional": directives.flag,
                   "figures": directives.flag}

    def run(self):
        env = self.env = self.state.document.settings.env
        rel, path = env.relfn2path(self.arguments[0], env.docname)
        self.docdir = os.path.dirname(self.arguments[0])
        self.srcdir = os.path.dirname(path)
        self.images = []
        if not os.path.isfile(path):
            if "optional" in self.options:
                note = nodes.note()
                note += nodes.paragraph(text=f"Not written yet: {self.arguments[0]} does not "
                                              "exist in this checkout.")
                return [note]
            raise self.error(f"markdown-include: no file {path}")
        env.note_dependency(rel)
        with open(path, encoding="utf-8") as fh:
            # one-line HTML comments (the markers of generated blocks) are not shown
            lines = [ln for ln in fh.read().splitlines() if not COMMENT_LINE.match(ln)]
        if "skip-title" in self.options:
            for k, line in enumerate(lines):
                if line.strip():
                    if line.startswith("# "):
                        del lines[k]
                    break
        out = self.blocks(lines)
        if "figures" in self.options:
            seen = set()
            for alt, uri in self.images:
                if uri in seen:
                    continue
                seen.add(uri)
                fig = nodes.figure()
                fig += nodes.image(uri=uri, alt=alt, width="90%")
                fig += nodes.caption(text=alt)
                out.append(fig)
        return out

    # ---------------------------------------------------------------- blocks
    def blocks(self, lines):
        out, i, n = [], 0, len(lines)
        while i < n:
            line = lines[i]
            if not line.strip():
                i += 1
            elif FENCE.match(line):
                fence = FENCE.match(line).group(1)
                j = i + 1
                while j < n and not lines[j].strip().startswith(fence):
                    j += 1
                out.append(self.literal(lines[i + 1:j]))
                i = j + 1
            elif line.startswith("    ") or line.startswith("\t"):
                j = i
                while j < n and (lines[j].startswith("    ") or lines[j].startswith("\t")
                                 or not lines[j].strip()):
                    j += 1
                while j > i and not lines[j - 1].strip():
                    j -= 1
                out.append(self.literal([ln[4:] if ln.startswith("    ") else ln.lstrip("\t")
                                         for ln in lines[i:j]]))
                i = j
            elif HEADING.match(line):
                rubric = nodes.rubric()
                rubric += self.inline(HEADING.match(line).group("text"))
                out.append(rubric)
                i += 1
            elif "|" in line and i + 1 < n and TABLE_RULE.match(lines[i + 1]):
                j = i + 2
                while j < n and lines[j].strip().startswith("|"):
                    j += 1
                out.append(self.table(lines[i], lines[i + 2:j]))
                i = j
            elif LIST_ITEM.match(line):
                i = self.list_block(lines, i, out)
            elif line.lstrip().startswith(">"):
                j = i
                while j < n and lines[j].lstrip().startswith(">"):
                    j += 1
                quote = nodes.block_quote()
                quote += self.blocks([ln.lstrip()[1:].lstrip() for ln in lines[i:j]])
                out.append(quote)
                i = j
            else:
                j = i
                while j < n and lines[j].strip() and not self.starts_block(lines, j):
                    j += 1
                j = max(j, i + 1)
                para = nodes.paragraph()
                para += self.inline(" ".join(ln.strip() for ln in lines[i:j]))
                out.append(para)
                i = j
        return out

    def starts_block(self, lines, j):
        line = lines[j]
        return bool(FENCE.match(line) or HEADING.match(line) or LIST_ITEM.match(line)
                    or line.lstrip().startswith(">")
                    or ("|" in line and j + 1 < len(lines) and TABLE_RULE.match(lines[j + 1])))

    def list_block(self, lines, i, out):
        ordered = LIST_ITEM.match(lines[i]).group("mark")[0].isdigit()
        lst = nodes.enumerated_list() if ordered else nodes.bullet_list()
        n = len(lines)
        while i < n and LIST_ITEM.match(lines[i]):
            m = LIST_ITEM.match(lines[i])
            if m.group("mark")[0].isdigit() != ordered:
                break
            body = [m.group("rest")]
            i += 1
            # continuation: indented lines (nested items are flattened into the text)
            while i < n and lines[i].strip() and (lines[i].startswith("  ") or
                                                  not self.starts_block(lines, i)):
                nested = LIST_ITEM.match(lines[i].strip())
                body.append(("\n" if nested else "") + lines[i].strip())
                i += 1
            item = nodes.list_item()
            for chunk in " ".join(body).split("\n"):
                para = nodes.paragraph()
                para += self.inline(chunk.strip())
                item += para
            lst += item
            while i < n and not lines[i].strip() and i + 1 < n and LIST_ITEM.match(lines[i + 1]):
                i += 1
        out.append(lst)
        return i

    def literal(self, code_lines):
        text = "\n".join(code_lines)
        block = nodes.literal_block(text, text)
        block["language"] = "none"
        return block

    def table(self, header, rows):
        def cells(line):
            line = line.strip()
            if line.startswith("|"):
                line = line[1:]
            if line.endswith("|"):
                line = line[:-1]
            return [c.strip() for c in line.split("|")]
        head = cells(header)
        body = [cells(r) for r in rows]
        ncol = len(head)
        table = nodes.table()
        group = nodes.tgroup(cols=ncol)
        table += group
        # width hints from the content (text and LaTeX writers wrap cells to them)
        for k in range(ncol):
            longest = max(len(r[k]) if k < len(r) else 0 for r in [head] + body)
            group += nodes.colspec(colwidth=min(max(longest, 3), 30))
        for kind, data in ((nodes.thead, [head]), (nodes.tbody, body)):
            section = kind()
            for values in data:
                row = nodes.row()
                for c in (values + [""] * ncol)[:ncol]:
                    entry = nodes.entry()
                    para = nodes.paragraph()
                    para += self.inline(c)
                    entry += para
                    row += entry
                section += row
            group += section
        return table

    # ---------------------------------------------------------------- inline
    def inline(self, text):
        result, pos = [], 0
        for m in INLINE.finditer(text):
            if m.start() > pos:
                result.append(nodes.Text(text[pos:m.start()]))
            if m.group("code") is not None:
                result.append(self.code(m.group("code")))
            elif m.group("strong") is not None:
                result.append(nodes.strong("", "", *self.inline(m.group("strong"))))
            elif m.group("em") is not None:
                result.append(nodes.emphasis("", "", *self.inline(m.group("em"))))
            else:
                result.extend(self.link(m.group("text"), m.group("url"), bool(m.group("img"))))
            pos = m.end()
        if pos < len(text):
            result.append(nodes.Text(text[pos:]))
        return result

    def code(self, text):
        """`code`; a `figure.png` that exists beside the Markdown file is a figure too"""
        if IMAGE_FILE.fullmatch(text) and os.path.isfile(os.path.join(self.srcdir, text)):
            docrel = os.path.normpath(os.path.join(self.docdir, text))
            self.images.append((text, docrel))
            ref = addnodes.download_reference("", "", refdoc=self.env.docname,
                                              refexplicit=True, reftarget=docrel)
            ref += nodes.literal(text, text)
            return ref
        return nodes.literal(text, text)

    def link(self, text, url, image):
        if re.match(r"^[a-z][a-z0-9+.-]*:", url) or url.startswith("#"):
            return [nodes.reference(text, text, refuri=url)]
        target = os.path.normpath(os.path.join(self.srcdir, url))
        docrel = os.path.normpath(os.path.join(self.docdir, url))
        if not os.path.isfile(target):
            return [nodes.Text(f"{text} ("), nodes.literal(url, url), nodes.Text(")")]
        if IMAGE_FILE.fullmatch(url):
            self.images.append((text, docrel))
        if image:
            return [nodes.image(uri=docrel, alt=text)]
        ref = addnodes.download_reference(text, "", refdoc=self.env.docname,
                                          refexplicit=True, reftarget=docrel)
        ref += nodes.Text(text.strip() or url)
        return [ref]


def setup(app):
    app.add_directive("markdown-include", MarkdownInclude)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
