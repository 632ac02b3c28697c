#!/usr/bin/env python3
"""No page speaks of how poundfe was built: README.md, doc/*.md (CHANGELOG.md
excepted), the templates of input/templates/, the string literals of
source/ (the parameter descriptions among them) and, when the binary is
given, the output of `poundfe print-parameters` say what the program does,
never which issue, stop or session added it, nor on how loaded a machine a
figure was taken. Exit 1 listing every offending line as path:line: text.

    no_build_history.py ROOT [POUNDFE]

Each pattern below names one way history leaks into a page; ALLOWED lists
the legitimate English that a pattern would otherwise catch (a Tcl or
ParaView session, "#" in a URL or an HTML entity)."""
import glob
import os
import re
import subprocess
import sys

PATTERNS = [
    (r"\bissues?\s+#?\d+", "an issue number"),
    (r"(?<![\w&/#])#\d+\b", "an issue number (#N)"),
    (r"\bstops?\s+\d+\b(?!\s*(?:s|ms|min|seconds?|steps?|times|%|realizations?|runs?|"
     r"iterations?|values?)\b)", "a development stop"),
    (r"\bthis stop\b", "a development stop"),
    (r"\bsessions?\b", "a working session"),
    (r"\bthis machine\b", "the machine it was built on"),
    (r"\bmachine load\b", "the machine's load"),
    (r"\b(?:quiet|shared|busy|loaded) machine\b", "the machine's load"),
    (r"\bat load \d", "the machine's load"),
    (r"\bfounding\b", "the project's founding"),
    (r"\bleadership\b", "the project's leadership"),
    (r"\bthe issue's\b", "an issue"),
    (r"\bother engineers'", "the people who built it"),
    (r"\bother (?:jobs|builds)\b", "the machine's other work"),
    (r"\bother processes' builds\b", "the machine's other work"),
    (r"\b(?:jobs|builds) running\b", "the machine's other work"),
    (r"\bshared (?:2-core |two-core )?(?:machine|VM)\b", "the machine's load"),
    (r"\b(?:machine|VM) shared with\b", "the machine's load"),
    (r"\bunder heavy load\b", "the machine's load"),
    (r"\bcompile jobs?\b|\bjobs compiling\b|\boverlapping a compile\b"
     r"|\b(?:with|beside) (?:\w+ )?compiles\b", "the machine's other work"),
]
PATTERNS = [(re.compile(p, re.IGNORECASE), why) for p, why in PATTERNS]

# Legitimate uses, removed from a line before the patterns are tried.
ALLOWED = [re.compile(p, re.IGNORECASE) for p in [
    r"\b(?:Tcl|ParaView|Python|interactive|gnuplot|terminal|shell|ssh|login)\s+sessions?\b",
    r"https?://\S+",
    r"&#\d+;",
]]


def offending(text):
    """The reasons a line of text speaks of how the program was built."""
    for allowed in ALLOWED:
        text = allowed.sub(" ", text)
    return [why for pattern, why in PATTERNS if pattern.search(text)]


# The patterns' own check: what each must flag, and legitimate English it must not.
FLAGGED = ["Python module (issue 27 item 3: python/run)", "since stop 30", "Stop 37: hardening",
           "see #51", "measured beside other sessions' builds", "on this machine",
           "under machine load", "on a quiet machine", "measured at load 3",
           "the issue's bound", "Issues 44-50 were not started",
           "load 16 from other engineers' builds", "with other jobs running",
           "beside other builds", "(load average 9, other builds on the 2 cores)",
           "as other processes' builds started", "four builds running",
           "on the shared 2-core machine", "2-core VM shared with four builds",
           "**under heavy load**", "one compile job ran on the other core",
           "three other jobs compiling", "its first runs overlapping a compile",
           "shared the cores with six compiles", "a busy machine"]
LEGITIMATE = ["a Tcl session", "in a ParaView session", "the run stops 2 s later",
              "subset stops 3 times", "&#39;", "https://github.com/x/y/issues/27",
              "the response stops at 5 % of the peak", "Newton stops after 3 iterations",
              "a gnuplot session", "load average 9.4",
              "busy-polling MPI ranks", "a C program the script compiles",
              "the library and the tests compile in batches", "on an idle machine",
              "where the cores are busy with other work", "shared memory"]


def check_patterns():
    wrong = [s for s in FLAGGED if not offending(s)]
    wrong += [s for s in LEGITIMATE if offending(s)]
    if wrong:
        sys.exit("FAIL the patterns misjudge: " + "; ".join(wrong))


def scan_lines(name, lines, bad):
    for number, line in enumerate(lines, 1):
        for why in offending(line):
            bad.append(f"{name}:{number}: {why}: {line.strip()[:160]}")


def string_literals(source):
    """The "..." literals of a C++ file (comments and character literals
    skipped), each with the line it starts on."""
    literals = []
    i, line, n = 0, 1, len(source)
    while i < n:
        c = source[i]
        if source.startswith("//", i):
            end = source.find("\n", i)
            i = n if end < 0 else end
        elif source.startswith("/*", i):
            end = source.find("*/", i + 2)
            end = n if end < 0 else end + 2
            line += source.count("\n", i, end)
            i = end
        elif c == "'":
            m = re.match(r"'(?:\\.|[^'\\])*'", source[i:])
            i += len(m.group(0)) if m else 1
        elif c == '"':
            m = re.match(r'"(?:\\.|[^"\\\n])*"', source[i:])
            if not m:
                i += 1
                continue
            literals.append((line, m.group(0)[1:-1]))
            i += len(m.group(0))
        else:
            if c == "\n":
                line += 1
            i += 1
    return literals


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    check_patterns()
    root = sys.argv[1]
    bad = []
    pages = [os.path.join(root, "README.md")]
    pages += [p for p in sorted(glob.glob(os.path.join(root, "doc", "*.md")))
              if os.path.basename(p) != "CHANGELOG.md"]
    pages += sorted(glob.glob(os.path.join(root, "input", "templates", "*")))
    if len(pages) < 5:
        sys.exit(f"FAIL {root}: README.md, doc/*.md or input/templates/ not found")
    for page in pages:
        with open(page, encoding="utf-8") as f:
            scan_lines(os.path.relpath(page, root), f.read().split("\n"), bad)
    sources = sorted(glob.glob(os.path.join(root, "source", "**", "*.cc"), recursive=True))
    if not sources:
        sys.exit(f"FAIL {root}: no source/**/*.cc")
    for path in sources:
        with open(path, encoding="utf-8") as f:
            for number, text in string_literals(f.read()):
                for why in offending(text):
                    bad.append(f"{os.path.relpath(path, root)}:{number}: {why} "
                               f"in a string: \"{text[:140]}\"")
    if len(sys.argv) == 3:
        shown = subprocess.run([sys.argv[2], "print-parameters"], capture_output=True,
                               text=True, check=True).stdout
        if len(shown.splitlines()) < 100:
            sys.exit("FAIL print-parameters printed fewer than 100 lines")
        scan_lines("poundfe print-parameters", shown.splitlines(), bad)
    for line in bad:
        print(line)
    if bad:
        print(f"FAIL {len(bad)} lines speak of how poundfe was built")
        return 1
    print(f"OK {len(pages)} pages, {len(sources)} source files"
          + (", print-parameters" if len(sys.argv) == 3 else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
