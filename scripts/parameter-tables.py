#!/usr/bin/env python3
"""Markdown tables of poundfe's parameters, generated from `poundfe print-parameters`.

    python3 scripts/parameter-tables.py                 # every section's table on stdout
    python3 scripts/parameter-tables.py --update FILE   # rewrite the tables inside FILE

print-parameters writes deal.II's PRM listing: `subsection NAME` ... `end`, and before
each `set ENTRY = DEFAULT` the entry's help as `# ` comment lines. Each help says its
unit, `Unit: <u>.` (a choice also its values, `Allowed: ...`); entries of Building <i>
that apply to one kind of building start with a tag such as `[frame]`. This script turns
each section's entries into a table: entry (with its tag), default, unit, help.

With --update, every block of FILE between a line `<!-- parameters: SECTION -->` and the
next `<!-- end parameters -->` is replaced by the table of SECTION (its path, e.g.
`Output/Recorders`; its own entries, not those of its subsections).
`<!-- parameters: ALL-REMAINING -->` receives the sections no other block of FILE names,
each under its own heading, so that no section is left out.

The binary is build/poundfe unless --binary or $POUNDFE says otherwise.
"""

import argparse
import os
import re
import subprocess
import sys
from collections import OrderedDict

UNIT = re.compile(r"\s*Unit:\s*(.+?)\.(?=\s|$)")
TAG = re.compile(r"^\s*(\[[A-Za-z0-9, ]+\])\s*")
BLOCK = re.compile(r"(<!-- parameters: (.+?) -->\n)(.*?)(<!-- end parameters -->)", re.S)


def read_listing(binary):
    """The PRM text of `poundfe print-parameters`."""
    return subprocess.run([binary, "print-parameters"], check=True, capture_output=True,
                          text=True).stdout


def parse_sections(text):
    """Section path -> list of (entry, default, help), in declaration order."""
    sections = OrderedDict()
    path = []
    help_lines = []
    for raw in text.splitlines():
        line = raw.strip()
        if not line:
            help_lines = []
        elif line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
            sections.setdefault("/".join(path), [])
            help_lines = []
        elif line == "end":
            path.pop()
            help_lines = []
        elif line.startswith("#"):
            help_lines.append(line[1:].strip())
        elif line.startswith("set "):
            name, _, value = line[len("set "):].partition("=")
            value = value.strip()
            if " # default: " in value:  # printed only when the value is not the default
                value = value.split(" # default: ", 1)[1]
            sections.setdefault("/".join(path), []).append(
                (name.strip(), value, " ".join(help_lines)))
            help_lines = []
        else:
            raise ValueError(f"unexpected line in the parameter listing: {raw!r}")
    return sections


def cell(text):
    """Text safe inside a markdown table cell (no column breaks, no HTML tags)."""
    return text.replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;").strip()


def table(entries):
    """The markdown table of one section's entries."""
    rows = ["| entry | default | unit | meaning |", "|---|---|---|---|"]
    for name, default, help_text in entries:
        unit = ""
        match = UNIT.search(help_text)
        if match:
            unit = match.group(1)
            help_text = (help_text[:match.start()] + help_text[match.end():]).strip()
        tag = ""
        match = TAG.match(help_text)
        if match:
            tag = " " + match.group(1)
            help_text = help_text[match.end():]
        shown_default = f"`{cell(default)}`" if default else "(empty)"
        rows.append(f"| `{cell(name)}`{tag} | {shown_default} | {cell(unit)} | "
                    f"{cell(help_text)} |")
    return "\n".join(rows) + "\n"


def update(path, sections):
    text = open(path, encoding="utf-8").read()
    named = {m.group(2) for m in BLOCK.finditer(text)}
    unknown = named - set(sections) - {"ALL-REMAINING"}
    if unknown:
        sys.exit(f"{path}: no such section in print-parameters: {', '.join(sorted(unknown))}")

    def replacement(match):
        name = match.group(2)
        if name != "ALL-REMAINING":
            body = table(sections[name]) if sections[name] else "(no entries of its own)\n"
        else:
            rest = [s for s, e in sections.items() if s not in named and e]
            body = "".join(f"\n#### {s}\n\n{table(sections[s])}" for s in rest) or \
                "(every section's table is in its chapter)\n"
        return match.group(1) + "\n" + body + "\n" + match.group(4)

    new_text = BLOCK.sub(replacement, text)
    if new_text != text:
        tmp = path + ".tmp"
        with open(tmp, "w", encoding="utf-8") as out:
            out.write(new_text)
        os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default=os.environ.get("POUNDFE", "build/poundfe"))
    parser.add_argument("--update", metavar="FILE")
    args = parser.parse_args()
    sections = parse_sections(read_listing(args.binary))
    if args.update:
        update(args.update, sections)
    else:
        for name, entries in sections.items():
            if entries:
                sys.stdout.write(f"### {name}\n\n{table(entries)}\n")


if __name__ == "__main__":
    main()
