#!/usr/bin/env python3
"""No include runs upward (issue 27): every #include <poundfe/M/...> in a
module's sources and headers names a module of a lower layer than its own,
or its own, with the layers read from the table of doc/architecture.md (so
the drawing and the code cannot drift apart). Exit 1 listing every
offending include. Also: no two source files share a name (a header and
its source file excepted), so that a file's name says which room it is in.
And no rule is decided by a command's name outside the command table: no
`name == "run"` (or `command != "modal"`, ...) against a command of
source/commands/command_table.cc anywhere else in source/ or include/ (the
rules are the table's columns, commands/command.h). And one time loop: no
loop of source/ but TimeHistory::run (source/dynamics/time_history.cc)
advances a time stepper step by step."""
import glob
import os
import re
import sys

root = sys.argv[1]
table = open(os.path.join(root, "doc", "architecture.md"), encoding="utf-8").read()
layer = {m.group(2): int(m.group(1))
         for m in re.finditer(r"^\| (\d+) \| `(\w+)` \|", table, re.M)}
if len(layer) < 10:
    sys.exit("FAIL doc/architecture.md: no layer table found")
bad = []
files = glob.glob(os.path.join(root, "source", "*", "*.cc")) + \
    glob.glob(os.path.join(root, "include", "poundfe", "*", "*.h"))
for path in sorted(files):
    module = os.path.basename(os.path.dirname(path))
    if module not in layer:
        if module != "python":
            bad.append(f"{path}: module '{module}' is not in doc/architecture.md's table")
        continue
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        m = re.match(r"#include <poundfe/(\w+)/", line)
        if not m or m.group(1) == module:
            continue
        target = m.group(1)
        if target not in layer:
            bad.append(f"{path}:{number}: includes module '{target}', not in the table")
        elif layer[target] >= layer[module]:
            bad.append(f"{path}:{number}: {module} (layer {layer[module]}) includes "
                       f"{target} (layer {layer[target]})")
stems = {}
for path in glob.glob(os.path.join(root, "source", "**", "*.cc"), recursive=True) + \
        glob.glob(os.path.join(root, "include", "poundfe", "**", "*.h"), recursive=True):
    stem = os.path.splitext(os.path.basename(path))[0]
    place = os.path.relpath(os.path.dirname(path), root)
    place = place.replace(os.path.join("include", "poundfe"), "source", 1)
    stems.setdefault(stem, set()).add(place)
for stem, places in sorted(stems.items()):
    if len(places) > 1:
        bad.append(f"{stem}: a source file of that name in each of {', '.join(sorted(places))}")
table_file = os.path.join(root, "source", "commands", "command_table.cc")
commands = re.findall(r'^\s*\{"([a-z][a-z-]*)", "', open(table_file, encoding="utf-8").read(), re.M)
if len(commands) < 10:
    bad.append(f"{table_file}: no command rows found")
literal = "|".join(re.escape(c) for c in commands)
named = r"\b\w*(?:name|command)\w*(?:\(\))?"
by_name = re.compile(rf'{named}\s*[!=]=\s*"(?:{literal})"|"(?:{literal})"\s*[!=]=\s*{named}')
for path in sorted(glob.glob(os.path.join(root, "source", "**", "*.cc"), recursive=True) +
                   glob.glob(os.path.join(root, "source", "**", "*.py"), recursive=True) +
                   glob.glob(os.path.join(root, "include", "**", "*.h"), recursive=True)):
    if os.path.samefile(path, table_file):
        continue
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        if by_name.search(line):
            bad.append(f"{path}:{number}: a rule decided by a command's name (make it a column "
                       f"of the command table): {line.strip()}")


def without_comments(text):
    """`text` with its comments and string literals blanked (lines kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def closing(text, start, pair):
    """The index after the bracket that closes the one at `start`."""
    depth = 0
    for i in range(start, len(text)):
        depth += (text[i] == pair[0]) - (text[i] == pair[1])
        if depth == 0:
            return i + 1
    return len(text)


# A time stepper's step (advance() of a history, advance(load) or
# advance([...]) of an integrator) inside the body of a for or while loop.
STEP = re.compile(r"(?:\.|->)\s*advance\s*\(\s*(?:\)|load\b|\[)")
TIME_LOOP = os.path.join("source", "dynamics", "time_history.cc")
for path in sorted(glob.glob(os.path.join(root, "source", "**", "*.cc"), recursive=True)):
    if os.path.relpath(path, root) == TIME_LOOP:
        continue
    text = without_comments(open(path, encoding="utf-8").read())
    for loop in re.finditer(r"\b(?:for|while)\s*\(", text):
        header_end = closing(text, loop.end() - 1, "()")
        brace = re.match(r"\s*\{", text[header_end:])
        body_end = closing(text, header_end + brace.end() - 1, "{}") if brace else \
            text.find(";", header_end) + 1
        if STEP.search(text, header_end, body_end):
            line = text.count("\n", 0, loop.start()) + 1
            bad.append(f"{path}:{line}: a loop over time steps outside TimeHistory::run "
                       f"({TIME_LOOP}): step through TimeHistory with a TimeStepper instead")
for b in bad:
    print("FAIL", b)
print(f"{len(files)} files, {len(layer)} modules, {len(commands)} commands: {len(bad)} problems "
      "(includes against the layers, shared file names, rules by a command's name, "
      "loops over time steps)")
sys.exit(1 if bad else 0)
