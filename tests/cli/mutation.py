#!/usr/bin/env python3
"""Deterministic mutation test of the input readers through the real binary.

Mutates parameter files (input/three-storey-shear.prm, tests/cli/*.json and
a few tests/cli/bad/ files) and AT2 records (tests/fuzz/seeds-at2) with a
fixed seed: deleted, duplicated and swapped lines, random bytes, numbers
replaced by extreme or malformed ones, CR line ends, trailing backslashes,
unbalanced subsection/end, very long lines, deep JSON nesting. Each mutant
goes through `poundfe modal` (parameter files) or `poundfe ground-motion`
(records) with a timeout. Every run must end by itself with exit status 0,
1 or 2 (no signal, no hang), and a failing run must say why in one line
starting with 'poundfe: '. Two mutants run at a time. POUNDFE_KEEP_MUTANTS=DIR
copies the failing mutants to DIR.

usage: mutation.py POUNDFE SOURCE_DIR [N_PARAMETER_MUTANTS N_RECORD_MUTANTS]
"""
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import tempfile

poundfe, source = sys.argv[1], sys.argv[2]
n_parameter_mutants = int(sys.argv[3]) if len(sys.argv) > 3 else 150
n_record_mutants = int(sys.argv[4]) if len(sys.argv) > 4 else 90
rng = random.Random(14)  # fixed: the same mutants every run
timeout = 30  # s; the slowest mutant takes well under 2 s

extreme = ["1e308", "-1", "0", "1e-320", "nan", "inf", "2x", "0.015 junk", "1e-2x",
           "0.02.5", "", "99999999999", "-0", "4.9e-324", "1D-2", "'", "1,2,3,,"]


def mutate_text(text, json):
    lines = text.split("\n")
    kind = rng.randrange(12)
    i = rng.randrange(len(lines))
    if kind == 0:
        del lines[i]
    elif kind == 1:
        lines.insert(i, lines[rng.randrange(len(lines))])
    elif kind == 2:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind == 3:
        line = lines[i]
        k = rng.randrange(len(line) + 1)
        junk = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 6)))
        lines[i] = line[:k] + junk + line[k:]
    elif kind == 4:  # a value replaced
        for _ in range(len(lines)):
            if "=" in lines[i] or ":" in lines[i]:
                break
            i = rng.randrange(len(lines))
        sep = "=" if "=" in lines[i] else ":"
        head = lines[i].split(sep)[0]
        value = rng.choice(extreme)
        lines[i] = head + sep + (' "%s"' % value if json else " " + value)
    elif kind == 5:
        return text[:rng.randrange(len(text) + 1)]
    elif kind == 6:
        return text.replace("\n", "\r")
    elif kind == 7:
        lines[i] += " \\"
    elif kind == 8:
        lines.insert(i, rng.choice(["subsection Model", "end", "subsection Nowhere", "set = 1",
                                    "include /nonexistent.prm", "set Model = 1"]))
    elif kind == 9:
        lines[i] += " " * 3 + ", ".join(["3.0"] * rng.choice([10, 9000]))
    elif kind == 10:
        depth = rng.choice([100, 30000])
        lines.insert(i, "[" * depth + "]" * depth if json else "subsection " + "x" * 30000)
    else:
        lines[i] = lines[i] + "# comment \\"
    return "\n".join(lines)


def mutate_record(text):
    if rng.random() < 0.4:
        header = rng.choice(["NPTS=  10, DT= 2.0D-02 SEC", "NPTS=-5, DT=.01",
                             "NPTS= 99999999999999, DT= .01", "NPTS= 10, DT= 1e999",
                             "NPTS= 10, DT= 0.02.5", "NPTS= 10, DT= 2e-2e", "NPTS= 10, DT= 0",
                             "NPTS= 10, DT= .2D-01", "NPTS= 10 DT .01", "10 0.01 NPTS, DT",
                             "NPTS= 3000000000, DT= 0.01"])
        lines = [l for l in text.split("\n") if "NPTS" not in l]
        lines.insert(min(3, len(lines)), header)
        text = "\n".join(lines)
    value = rng.choice(["1e308", "1e-320", "nan", "0.1D-01", "1..2", "-", "1e999", "3,"])
    words = text.split(" ")
    if len(words) > 4:
        words[rng.randrange(len(words))] = value
    text = " ".join(words)
    return mutate_text(text, False) if rng.random() < 0.5 else text


def run(job):
    command, file, label = job
    out = file + ".out"
    try:
        r = subprocess.run([poundfe, command, file, "--output", out], capture_output=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return label, "hang (no exit within %d s)" % timeout
    message = r.stderr.decode("utf-8", "replace").strip().split("\n")
    if r.returncode not in (0, 1, 2):
        return label, "exit status %d: %s" % (r.returncode, message[-1][:300])
    if r.returncode != 0 and (len(message) != 1 or not message[0].startswith("poundfe: ")):
        return label, "exit %d without a one-line message: %r" % (r.returncode, message[:3])
    return label, None


def main():
    seeds = [(os.path.join(source, "input", "three-storey-shear.prm"), False),
             (os.path.join(source, "tests", "cli", "three-storey-shear.json"), True),
             (os.path.join(source, "tests", "cli", "bad", "bad-barrier.prm"), False),
             (os.path.join(source, "tests", "cli", "bad", "bad-force.prm"), False)]
    at2 = os.path.join(source, "tests", "fuzz", "seeds-at2")
    records = sorted(f for f in os.listdir(at2) if f.endswith(".at2"))
    keep = os.environ.get("POUNDFE_KEEP_MUTANTS")  # a directory: failing mutants are copied there
    with tempfile.TemporaryDirectory() as work:
        jobs = []  # every mutant is written first (the random stream stays fixed), then run
        for n in range(n_parameter_mutants):
            seed, json = seeds[n % len(seeds)]
            text = open(seed, encoding="latin-1").read()
            for _ in range(rng.randrange(1, 4)):
                text = mutate_text(text, json)
            file = os.path.join(work, "mutant%d%s" % (n, ".json" if json else ".prm"))
            with open(file, "w", encoding="latin-1") as f:
                f.write(text)
            jobs.append(("modal", file, file))
        for n in range(n_record_mutants):
            name = records[n % len(records)]
            text = open(os.path.join(at2, name), encoding="latin-1").read()
            record = os.path.join(work, "record%d.at2" % n)
            with open(record, "w", encoding="latin-1") as f:
                f.write(mutate_record(text))
            prm = os.path.join(work, "record%d.prm" % n)
            with open(prm, "w") as f:
                f.write("subsection Ground motion\n  set Type = record\n  subsection Record\n"
                        "    set File = record%d.at2\n    set Target PGA = 0.3\n  end\nend\n"
                        "subsection Output\n  set Plots = false\nend\n" % n)
            jobs.append(("ground-motion", prm, record))
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            results = list(pool.map(run, jobs))
        failures = [(label, problem) for label, problem in results if problem]
        for label, problem in failures:
            print("FAIL %s: %s" % (os.path.basename(label), problem))
            if keep:
                os.makedirs(keep, exist_ok=True)
                shutil.copy(label, keep)
    print("%d parameter mutants, %d record mutants, %d failures"
          % (n_parameter_mutants, n_record_mutants, len(failures)))
    return 1 if failures else 0


sys.exit(main())
