# SPDX-License-Identifier: GPL-2.0-or-later
"""Generated blocks in Markdown and reStructuredText: find them, replace their bodies."""
import re

MD = re.compile(r"<!-- bbpd:(?P<kind>table|text) (?P<name>[\w.-]+) -->\n(?P<body>.*?)"
                r"<!-- /bbpd:(?P=kind) -->", re.S)
RST = re.compile(r"^\.\. bbpd:(?P<kind>table|text) (?P<name>[\w.-]+)\n\n(?P<body>.*?)"
                 r"^\.\. /bbpd:(?P=kind)$", re.S | re.M)


def pattern(path):
    return RST if str(path).endswith(".rst") else MD


def blocks(path, text):
    """[(kind, name, body)] of the blocks of a file's text, in order (body without the final
    newline of Markdown or the blank line of RST)."""
    out = []
    for m in pattern(path).finditer(text):
        body = m.group("body")
        out.append((m.group("kind"), m.group("name"), body[:-2] if str(path).endswith(".rst")
                    else body[:-1]))
    return out


def replace(path, text, render):
    """text with the body of every block replaced by render(kind, name) (None: kept)."""
    rst = str(path).endswith(".rst")

    def sub(m):
        new = render(m.group("kind"), m.group("name"))
        if new is None:
            return m.group(0)
        kind, name = m.group("kind"), m.group("name")
        if rst:
            return f".. bbpd:{kind} {name}\n\n{new}\n\n.. /bbpd:{kind}"
        return f"<!-- bbpd:{kind} {name} -->\n{new}\n<!-- /bbpd:{kind} -->"
    return pattern(path).sub(sub, text)
