#!/usr/bin/env python3
"""No include runs upward (issue 27): every #include <poundfe/M/...> in a
module's sources and headers names a module of a lower layer than its own,
or its own, with the layers read from the table of doc/architecture.md (so
the drawing and the code cannot drift apart). Exit 1 listing every
offending include. Also: no two source files share a name (a header and
its source file excepted), so that a file's name says which room it is in.
And one time loop: no loop of source/ but TimeHistory::run
(source/dynamics/time_history.cc) advances a time stepper step by step."""
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
print(f"{len(files)} files, {len(layer)} modules: {len(bad)} problems (includes against the layers, shared file names, loops over time steps)")
sys.exit(1 if bad else 0)
