#!/usr/bin/env python3
"""poundfe and OpenSees 3.8 timed on the same corpus scripts, per script and
per transient step.

    speed.py POUNDFE OPENSEES WORK_DIR [ROUNDS]
    speed.py POUNDFE OPENSEES WORK_DIR ROUNDS --compare CASE,...

First form: each round runs every case in both programs, alternating which goes first,
twice: the whole script ("full"; for the "loop" cases its transient
`analyze n dt` as n calls of `analyze 1 dt` in a Tcl loop) and the script
with its transient `analyze` skipped ("setup": start-up, the model, the
record's Tcl loop, the static
steps; bench/opensees/run_with.tcl). A run's time is its wall time and its
CPU time (user + system, os.wait4), the CPU time being less sensitive to
other jobs on the machine. Both programs run with OPENBLAS_NUM_THREADS=1 and
OMP_NUM_THREADS=1: OpenSees 3.8 built on Debian's threaded OpenBLAS has its
idle BLAS threads spin in sched_yield (356 621 calls on fibre_frame_3d.tcl),
which costs it more than its own work where other jobs hold the cores. Prints, per case and program, the medians over
the rounds of the full run's wall and CPU times, and the CPU time of a
transient step, (full - setup) / steps, with the ratios OpenSees / poundfe.
Second form: compare.py's cases as they are (the whole script, alternating
the programs), the medians of wall and CPU times, for doc/verification.md's
table against OpenSees 3.8."""
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402  (its CASES: the corpus scripts and their words)

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "..", "..", "tests", "opensees")
WRAPPER = os.path.join(HERE, "run_with.tcl")
SHEAR_PAIR = os.path.join(HERE, "shear_pair_3storey.tcl")
# case: (script, its words, transient steps: the script's own or set by
# ::bench_steps, whether set, and how the full run steps: "full", one
# `analyze n dt`, or "loop", n calls of `analyze 1 dt` in a Tcl loop)
CASES = {
    "pounding ElasticPPGap, 4000 steps": ("pounding_sticks.tcl", ["ElasticPPGap"], 4000, False,
                                          "full"),
    "pounding ElasticPPGap, 4000 steps, analyze 1 in a loop": (
        "pounding_sticks.tcl", ["ElasticPPGap"], 4000, False, "loop"),
    "pounding ElasticPPGap, 40000 steps": ("pounding_sticks.tcl", ["ElasticPPGap"], 40000, True,
                                           "full"),
    "pounding ViscousDamper, 4000 steps": ("pounding_sticks.tcl", ["ViscousDamper"], 4000, False,
                                           "full"),
    "3-storey shear pair, ImpactMaterial gaps, 4000 steps": (SHEAR_PAIR, [], 4000, False, "full"),
    "3D fibre frame, 300 steps": ("fibre_frame_3d.tcl", [], 300, False, "full"),
    "3D fibre frame, 3000 steps": ("fibre_frame_3d.tcl", [], 3000, True, "full"),
}


def timed(program, case, mode, out):
    """Wall and CPU seconds of one run of the case."""
    script, words, steps, override, stepping = CASES[case]
    return timed_command(program, [WRAPPER, out, str(steps if override else 0),
                                   stepping if mode == "full" else mode,
                                   os.path.join(CORPUS, script)] + words, out)


def timed_command(program, arguments, out):
    """Wall and CPU seconds of the program run on the arguments."""
    os.makedirs(out, exist_ok=True)
    command = [program] + (["opensees"] if program.endswith("poundfe") else []) + arguments
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             env=dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1"))
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{' '.join(command)}: status {status}")
    return wall, usage.ru_utime + usage.ru_stime


def main(poundfe, opensees, work, rounds):
    times = {}  # (case, program, mode) -> [(wall, cpu)]
    for r in range(rounds):
        programs = [("poundfe", poundfe), ("OpenSees", opensees)]
        for case in CASES:
            for name, program in programs if r % 2 == 0 else programs[::-1]:
                for mode in ("full", "setup"):
                    out = os.path.join(work, name, mode)
                    times.setdefault((case, name, mode), []).append(
                        timed(program, case, mode, out))
    print(f"{rounds} rounds, load average before and after: see uptime")
    print("| script | poundfe wall, CPU | OpenSees wall, CPU | CPU ratio | "
          "CPU per step: poundfe, OpenSees | ratio |")
    print("|---|---|---|---|---|---|")
    for case in CASES:
        steps = CASES[case][2]
        row = {}
        for name in ("poundfe", "OpenSees"):
            full, setup = times[(case, name, "full")], times[(case, name, "setup")]
            wall = statistics.median(w for w, _ in full)
            cpu = statistics.median(c for _, c in full)
            step = statistics.median((f[1] - s[1]) / steps for f, s in zip(full, setup))
            row[name] = (wall, cpu, step)
        p, o = row["poundfe"], row["OpenSees"]
        print(f"| {case} | {p[0]:.2f} s, {p[1]:.3f} s | {o[0]:.2f} s, {o[1]:.3f} s | "
              f"{o[1] / p[1]:.2f} | {p[2] * 1e6:.1f} µs, {o[2] * 1e6:.1f} µs | "
              f"{o[2] / p[2]:.2f} |")


def compare_cases(poundfe, opensees, work, rounds, cases):
    """compare.py's cases: medians of the whole scripts' wall and CPU times."""
    times = {}
    for r in range(rounds):
        programs = [("poundfe", poundfe), ("OpenSees", opensees)]
        for case in cases:
            script, words, _ = compare.CASES[case]
            for name, program in programs if r % 2 == 0 else programs[::-1]:
                out = os.path.join(work, case, name)
                times.setdefault((case, name), []).append(
                    timed_command(program, [os.path.join(CORPUS, script), out] + words, out))
    print("| case | poundfe wall, CPU | OpenSees wall, CPU |")
    print("|---|---|---|")
    for case in cases:
        cells = []
        for name in ("poundfe", "OpenSees"):
            runs = times[(case, name)]
            cells.append(f"{statistics.median(w for w, _ in runs):.2f} s, "
                         f"{statistics.median(c for _, c in runs):.3f} s")
        print(f"| {case} | {cells[0]} | {cells[1]} |")


if __name__ == "__main__":
    if len(sys.argv) == 7 and sys.argv[5] == "--compare":
        compare_cases(sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]),
                      sys.argv[6].split(","))
        sys.exit(0)
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]) if len(sys.argv) == 5 else 5)
