#!/usr/bin/env bash
# poundfe::locateEvents in OpenSees scripts (tests/opensees/locate_events.tcl,
# a 2D pounding pair of cantilevers at dt = 0.01 s, R = 6), against a
# reference run of the same script without it at dt/2^R:
#  1. off: the recorder's file and the impact log are byte for byte those of
#     a script that turned it on and off again before analyze, and the run
#     with it on has the rows of the run without it, byte for byte, up to the
#     step of the first impact (no event, no other step);
#  2. on, for a linear gap (ElasticPPGap) and a soft JankowskiImpact: the
#     first impact's start within dt/2^R of the reference's; every episode's
#     start (matched to the reference's nearest) closer on average than the
#     run without it, and the peak contact force closer;
#  3. the impact log's start and end times lie in recorded sub-steps of at
#     most dt/2^R (each located one's own sub-step);
#  4. poundfe::energy's balance within 1e-8 of its largest term with it on
#     (the sub-steps summed);
#  5. a stiff Hertzdamp, whose first impact step Newton fails at dt = 0.01
#     (status -3 without it, as OpenSees's): with it on the analysis
#     completes, its first impact within dt/2^R of the reference's;
#  6. the same on a pair the tolerances were not set on (other masses,
#     periods, gap and ground motion);
#  7. the linear gap as a twoNodeLink along X (the zeroLength's deformation):
#     with it on, the recorder's rows and the impact log those of the
#     zeroLength's run to 1e-9 (its own elements, the same physics); and in
#     Series with a stiff Elastic spring (a Series's force is ~1e-22 N out of
#     contact: the gap's own force decides): located as in 3., the first
#     impact within dt/2^R of its own reference's;
# (its refusals and query: opensees_poundfe.sh).
#   opensees_locate.sh POUNDFE CORPUS_DIR PYTHON3
set -u
poundfe=$1 corpus=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"
dt=0.01 levels=6
for model in tuned other; do
  for law in linear Jankowski Hertzdamp; do
    for mode in off on fine; do
      "$poundfe" opensees "$corpus/locate_events.tcl" "$work" $law $mode $dt $levels $model \
        > "$work/${law}_${model}_$mode.log" 2>&1
    done
  done
done
for link in twoNodeLink Series; do
  for mode in off on fine; do
    "$poundfe" opensees "$corpus/locate_events.tcl" "$work" linear $mode $dt $levels tuned $link \
      > "$work/linear_tuned_${mode}_$link.log" 2>&1
  done
done
# off and on-then-off: the same bytes
sed 's/^poundfe::impacts on$/poundfe::impacts on; poundfe::locateEvents on 6; poundfe::locateEvents off/' \
  "$corpus/locate_events.tcl" > "$work/toggled.tcl"
cp "$corpus/record.tcl" "$work/"
mkdir -p "$work/toggled"
"$poundfe" opensees "$work/toggled.tcl" "$work/toggled" linear off $dt $levels tuned > /dev/null 2>&1 \
  || fail "the toggled script"
for ext in out csv; do
  cmp -s "$work/toggled/linear_tuned_off.$ext" "$work/linear_tuned_off.$ext" \
    || fail "locateEvents on then off: its .$ext differs from the script without it"
done
"$python" - "$work" $dt $levels <<'PY' || fail "poundfe::locateEvents"
import csv, sys
work, dt, levels = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
finest = dt / 2**levels
failed = False

def check(ok, what):
    global failed
    print(("ok   " if ok else "FAIL ") + what)
    failed = failed or not ok

def status(law, model, mode):
    line = open(f"{work}/{law}_{model}_{mode}.log").read().splitlines()[-1]
    words = line.split()
    return int(words[words.index("status") + 1]), float(words[-1])

def rows(law, model, mode):
    with open(f"{work}/{law}_{model}_{mode}.out") as f:
        return [l for l in f.read().splitlines() if l.strip()]

def episodes(law, model, mode):
    with open(f"{work}/{law}_{model}_{mode}.csv") as f:
        return [(float(e["start_time"]), float(e["end_time"]), float(e["peak_force"]))
                for e in csv.DictReader(f)]

def start_errors(run, ref):
    """Each reference episode's start from the run's nearest start."""
    return [min(abs(s - r[0]) for s, _, _ in run) for r in ref]

def in_short_substeps(times, recorded):
    """Every time inside a recorded step of at most dt/2^R (at a step's
    end: the shorter of the two steps that hold it)."""
    steps = list(zip(recorded, recorded[1:]))
    return all(min(b - a for a, b in steps if a <= t <= b) <= finest * (1 + 1e-9)
               for t in times)

for model in ("tuned", "other"):
    for law in ("linear", "Jankowski", "Hertzdamp"):
        name = f"{law} {model}"
        on_status, on_residual = status(law, model, "on")
        off_status, _ = status(law, model, "off")
        check(on_status == 0 and status(law, model, "fine")[0] == 0,
              f"{name}: completes with locateEvents on and at dt/2^R")
        check(on_residual <= 1e-8, f"{name}: energy balance {on_residual:.2e} of the largest term")
        ref, on = episodes(law, model, "fine"), episodes(law, model, "on")
        off = episodes(law, model, "off")
        recorded = [float(r.split()[0]) for r in rows(law, model, "on")]
        check(bool(on) and in_short_substeps([e[0] for e in on] +
                                             [e[1] for e in on if e[1] >= 0], recorded),
              f"{name}: the log's {len(on)} starts and ends in sub-steps of <= dt/2^R")
        first = abs(on[0][0] - ref[0][0])
        check(first <= finest, f"{name}: first impact at {on[0][0]:.6f} s, "
              f"{first:.2e} s from the reference's (dt/2^R {finest:.2e} s)")
        # before the first impact's step the same steps, the same bytes
        n_before = int(ref[0][0] / dt)
        check(rows(law, model, "on")[:n_before] == rows(law, model, "off")[:n_before],
              f"{name}: the first {n_before} rows those of the run without it")
        if law == "Hertzdamp":
            check(off_status == -3, f"{name}: without it Newton fails (status {off_status})")
            continue
        e_on, e_off = start_errors(on, ref), start_errors(off, ref)
        mean_on, mean_off = sum(e_on) / len(e_on), sum(e_off) / len(e_off)
        check(mean_on < mean_off, f"{name}: mean start error {mean_on:.2e} s on, "
              f"{mean_off:.2e} s off ({len(ref)} reference episodes)")
        peak = max(e[2] for e in ref)
        p_on = abs(max(e[2] for e in on) - peak) / peak
        p_off = abs(max(e[2] for e in off) - peak) / peak
        check(p_on < p_off, f"{name}: peak contact force {p_on:.2e} on, {p_off:.2e} off "
              f"(relative to the reference's {peak:.4e} N)")

def numbers(path):
    with open(path) as f:
        lines = f.read().splitlines()[path.endswith(".csv"):]  # a CSV's header
    return [float(x) for line in lines for x in line.replace(",", " ").split()]

for link in ("twoNodeLink", "Series"):
    name = f"linear tuned, {link}"
    on = episodes("linear", "tuned", f"on_{link}")
    recorded = [float(r.split()[0]) for r in rows("linear", "tuned", f"on_{link}")]
    check(status("linear", "tuned", f"on_{link}")[0] == 0 and len(on) > 0 and
          len(episodes("linear", "tuned", f"off_{link}")) > 0,
          f"{name}: completes and logs {len(on)} episodes with it on")
    check(len(recorded) > int(round(4.0 / dt)) + 1,
          f"{name}: {len(recorded)} recorded steps, sub-steps among them")
    check(in_short_substeps([e[0] for e in on] + [e[1] for e in on if e[1] >= 0], recorded),
          f"{name}: the log's starts and ends in sub-steps of <= dt/2^R")
    ref = episodes("linear", "tuned", f"fine_{link}")
    first = abs(on[0][0] - ref[0][0])
    check(first <= finest, f"{name}: first impact {first:.2e} s from its reference's")
link = [numbers(f"{work}/linear_tuned_on{s}.{ext}") for s in ("", "_twoNodeLink")
        for ext in ("out", "csv")]
same = all(len(a) == len(b) and all(abs(x - y) <= 1e-9 * max(1.0, abs(y)) for x, y in zip(a, b))
           for a, b in ((link[0], link[2]), (link[1], link[3])))
check(same, "twoNodeLink on: rows and impact log those of the zeroLength to 1e-9")
sys.exit(1 if failed else 0)
PY
echo "ok"
