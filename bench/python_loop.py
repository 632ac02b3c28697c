"""A loop of runs from Python: poundfe.run on the default example
(input/two-buildings.prm: 60 equations, 26 hinges, 2 gaps), results in
memory, against the same runs with output= a directory (the command line's
files, read back). Prints the median and best wall time per run and the
median CPU time of the process per run (time.process_time: what the run
itself costs, whatever else the machine runs), for the whole 20 s record
and for shorter End times.

    PYTHONPATH=build/python python3 bench/python_loop.py [--runs 100] [--end 20 1]
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

import poundfe


def per_run(model, runs, output):
    times, cpu = [], []
    for i in range(runs):
        start, start_cpu = time.perf_counter(), time.process_time()
        if output:
            with tempfile.TemporaryDirectory() as directory:
                poundfe.run(model, output=os.path.join(directory, "out"))
        else:
            poundfe.run(model)
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return statistics.median(times), min(times), statistics.median(cpu)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=100)
    parser.add_argument("--end", type=float, nargs="+", default=[20.0, 1.0])
    parser.add_argument("--input", default="input/two-buildings.prm")
    parser.add_argument("--files", action="store_true", help="also time output= a directory")
    arguments = parser.parse_args()
    for end in arguments.end:
        model = poundfe.read(arguments.input, overrides={"Time integration/End time": end,
                                                         "Output/Plots": False})
        steps = poundfe.run(model).steps
        median, best, cpu = per_run(model, arguments.runs, False)
        line = (f"End time {end:g} s ({steps} steps): in memory {1e3 * median:.1f} ms/run median, "
                f"{1e3 * best:.1f} best, {1e6 * median / steps:.2f} us/step; "
                f"CPU {1e3 * cpu:.1f} ms/run median, {1e6 * cpu / steps:.2f} us/step")
        if arguments.files:
            median_f, _, _ = per_run(model, arguments.runs, True)
            line += f"; with files {1e3 * median_f:.1f} ms/run median"
        print(line, flush=True)


if __name__ == "__main__":
    sys.exit(main())
