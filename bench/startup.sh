#!/usr/bin/env bash
# Start-up (Release build, from the repository root): what `poundfe --version`, a small
# `modal`, an empty `opensees` script, `import poundfe.opensees` (the lean extension) and
# the full module's core (`import poundfe` and its first name) cost, against the floor of
# loading deal.II alone (a three-line C program compiled here: dlopen of libdeal.ii.so)
# and, when OPENSEES names its binary, OpenSees on the same empty script.
#   bash bench/startup.sh [RUNS]          (default 20 runs of each, alternated)
# Prints, per command, the median and smallest wall time and the median CPU time
# (user + system of the process and its children, from wait4), the load average
# before and after, and the loader's relocations of the modal run (LD_DEBUG=statistics).
set -eu
runs=${1:-20}
poundfe=${POUNDFE:-build/poundfe}
python=${POUNDFE_PYTHON:-python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: > "$work/empty.tcl"
printf '#include <dlfcn.h>\nint main(void) { return dlopen("libdeal.ii.so", RTLD_LAZY | RTLD_GLOBAL) ? 0 : 1; }\n' \
  > "$work/floor.c"
cc -O2 "$work/floor.c" -o "$work/floor" -ldl
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
commands=(
  "poundfe --version|$poundfe --version"
  "poundfe modal input/three-storey-shear.prm|$poundfe modal input/three-storey-shear.prm --output $work/modal"
  "poundfe opensees (empty script)|$poundfe opensees $work/empty.tcl"
  "python3 -c 'import poundfe.opensees'|env PYTHONPATH=build/python $python -c 'import poundfe.opensees'"
  "python3 -c 'import poundfe; poundfe.Input'|env PYTHONPATH=build/python $python -c 'import poundfe; poundfe.Input'"
  "floor: dlopen of libdeal.ii.so|$work/floor"
)
if [ -n "${OPENSEES:-}" ]; then
  commands+=("OpenSees (empty script)|$OPENSEES $work/empty.tcl")
fi
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%s\n' "${commands[@]}" | python3 -c '
import os, statistics, subprocess, sys, time
runs = int(sys.argv[1])
rows = [line.rstrip("\n").split("|", 1) for line in sys.stdin if line.strip()]
wall = {name: [] for name, _ in rows}
cpu = {name: [] for name, _ in rows}
for _ in range(runs):  # alternated, so that a change of load touches every command alike
    for name, command in rows:
        start = time.perf_counter()
        child = subprocess.Popen(command, shell=True, stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        wall[name].append(time.perf_counter() - start)
        cpu[name].append(usage.ru_utime + usage.ru_stime)
        if status != 0:
            sys.exit(f"{name}: exit status {status >> 8}")
print(f"{runs} runs each".ljust(44), "median wall  smallest wall  median CPU")
for name, _ in rows:
    print(f"{name:<44} {statistics.median(wall[name]):9.3f} s  {min(wall[name]):11.3f} s"
          f"  {statistics.median(cpu[name]):8.3f} s")
' "$runs"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
LD_DEBUG=statistics "$poundfe" modal input/three-storey-shear.prm --output "$work/modal" 2>&1 \
  > /dev/null | grep -E 'final number of relocations' | sed 's/^[[:space:]]*[0-9]*:[[:space:]]*//'
