#!/usr/bin/env bash
# With Output/VTU impact peaks, a run's field series holds a frame at the
# peak of each impact as well as its regular frames (without it, only those) (doc/verification.md, "Entries another entry silences;
# ... figures"): the example pounding pair (10 s, 3 impacts) with a 0.5 s VTU interval and
# contact_force.csv at every step; the steps at which the gaps' total |force|
# peaks (it rose or held to a positive value and falls at the next step) are
# exactly the frames of solution.pvd that are not at a multiple of 0.5 s
# (besides those that fall on one).
#   vtu_impact_peaks.sh POUNDFE INPUT_DIR
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$poundfe" run "$input/shear-pair-pounding.prm" --output "$work/out" \
  --set "Output/VTU interval=0.5" --set "Output/VTU impact peaks=true" \
  --set "Output/Output interval=0" --set "Output/Plots=false" > /dev/null
# Without the entry (its default, false) only the regular frames.
"$poundfe" run "$input/shear-pair-pounding.prm" --output "$work/off" \
  --set "Output/VTU interval=0.5" --set "Output/Output interval=0" --set "Output/Plots=false" > /dev/null
n_off=$(grep -c 'timestep=' "$work/off/solution.pvd")
[ "$n_off" -eq 21 ] || { echo "FAIL VTU impact peaks = false: $n_off frames, not the 21 regular ones"; exit 1; }
python3 - "$work/out" 0.5 <<'PY'
import csv, os, re, sys
out, interval = sys.argv[1], float(sys.argv[2])
rows = list(csv.reader(open(os.path.join(out, "contact_force.csv"))))
header, rows = rows[0], rows[1:]
forces = [i for i, name in enumerate(header) if name.endswith("_force_N")]
time = [float(r[0]) for r in rows]
total = [sum(abs(float(r[i])) for i in forces) for r in rows]
peaks = {time[k] for k in range(1, len(rows) - 1)
         if total[k] > 0 and total[k - 1] <= total[k] and total[k + 1] < total[k]}
frames = [float(t) for t in re.findall(r'timestep="([^"]+)"', open(os.path.join(out, "solution.pvd")).read())]
regular = {t for t in frames if abs(t / interval - round(t / interval)) < 1e-9}
extra = set(frames) - regular
problems = []
if not peaks:
    problems.append("no impact in the run: the check tests nothing")
if sorted(frames) != frames or len(set(frames)) != len(frames):
    problems.append("the frames are not in strictly increasing time")
if peaks - set(frames):
    problems.append(f"impact peaks without a frame: {sorted(peaks - set(frames))[:5]}")
if extra - peaks:
    problems.append(f"frames neither regular nor at a peak: {sorted(extra - peaks)[:5]}")
for p in problems:
    print("FAIL", p)
print(f"{'ok  ' if not problems else 'FAIL'} {len(peaks)} impact peaks, {len(regular)} regular frames, "
      f"{len(extra)} frames at peaks")
sys.exit(1 if problems else 0)
PY
