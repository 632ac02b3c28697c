#!/usr/bin/env bash
# The demands of a 3D model along y and in plan, in ida, msa and the pelicun
# demand tables (ida, montecarlo, run): a symmetric 3D shear building
# (tests/cli/3d-symmetric-shear.prm: equal storeys along x and y, mass
# centres at the plan's centre) shaken along y (Ground motion/Incidence
# angle = 90) gives along y what it gives along x when shaken along x:
#  - msa.csv: each run's peak and residual drift ratios and floor
#    accelerations along y at 90 degrees equal those along x at 0 degrees
#    (1e-9 relative to the column's largest: cos 90 degrees is 6e-17, not 0, and the integrator's
#    round-off), and the floors' rotations are nil (1e-12 rad: nothing
#    couples translation and twist);
#  - ida's demand tables (IDA/Demand intensities), msa's (a stripe's),
#    montecarlo's and run's: pelicun's schema, PID-s-2, RID-s-2, PFA-f-2
#    (PFA-0-2: the PGA along y) at 90 degrees equal to PID-s-1, RID-s-1,
#    PFA-f-1 at 0 degrees (1e-9 relative), PFR-f-0 present and nil.
#   assessment_3d.sh POUNDFE CLI_DIR
set -eu
poundfe=$(realpath "$1") here=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL $*"; exit 1; }
prm=$here/3d-symmetric-shear.prm
short=(--set "Ground motion/Stochastic/Duration=3" --set "Output/Plots=false")
"$poundfe" ground-motion "$prm" --realizations 2 --write-at2 --output gen "${short[@]}" > /dev/null ||
  fail "ground-motion --write-at2"
suite=(--set "IDA/Suite=$work/gen/records/suite.csv" --set "IDA/Intensity measure=PGA"
       --set "IDA/Free vibration=0.5")
for angle in 0 90; do
  along=(--set "Ground motion/Incidence angle=$angle")
  "$poundfe" msa "$prm" --output "msa$angle" "${short[@]}" "${suite[@]}" "${along[@]}" \
    --set "MSA/Intensities=0.2, 0.6" --set "Output/Demand tables=true" > "msa$angle.log" ||
    fail "msa at $angle: $(cat "msa$angle.log")"
  "$poundfe" ida "$prm" --output "ida$angle" "${short[@]}" "${suite[@]}" "${along[@]}" \
    --set "IDA/Runs per record=4" --set "IDA/Tolerance=0.3" --set "IDA/Upper intensity=1" \
    --set "IDA/Demand intensities=0.3" > "ida$angle.log" || fail "ida at $angle: $(cat "ida$angle.log")"
  "$poundfe" montecarlo "$prm" --output "mc$angle" "${short[@]}" "${along[@]}" \
    --set "Monte Carlo/Realizations=2" --set "Output/Demand tables=true" > /dev/null ||
    fail "montecarlo at $angle"
  "$poundfe" run "$prm" --output "run$angle" "${short[@]}" "${along[@]}" \
    --set "Output/Demand tables=true" > /dev/null || fail "run at $angle"
done
HERE=$here python3 - <<'PY' || fail "the directions of a symmetric 3D building"
import csv, os, sys
sys.path.insert(0, os.environ["HERE"])
from pelicun_schema import check_schema

def close(a, b, scale, what):
    if abs(a - b) > 1e-9 * scale:
        sys.exit(f"{what}: {a} against {b}")

# msa.csv: y at 90 degrees = x at 0 degrees, no twist
x0 = list(csv.DictReader(open("msa0/msa.csv")))
y90 = list(csv.DictReader(open("msa90/msa.csv")))
assert len(x0) == len(y90) == 4, (len(x0), len(y90))
pairs = [(f"S_storey{s}_peak_drift_ratio", f"S_storey{s}_peak_drift_ratio_y") for s in (1, 2, 3)]
pairs += [(f"S_floor{f}_peak_acc_m_s2", f"S_floor{f}_peak_acc_y_m_s2") for f in (1, 2, 3)]
pairs += [(f"S_storey{s}_residual_drift_ratio", f"S_storey{s}_residual_drift_ratio_y")
          for s in (1, 2, 3)]
for cx, cy in pairs:
    scale = max(abs(float(r[cx])) for r in x0)
    assert scale > 0, cx
    for a, b in zip(x0, y90):
        close(float(b[cy]), float(a[cx]), scale, f"msa {cy} at 90 against {cx} at 0")
        close(float(a[cy]), 0, scale, f"msa {cy} at 0")
for rows in (x0, y90):
    for r in rows:
        for f in (1, 2, 3):
            assert abs(float(r[f"S_floor{f}_peak_rotation_rad"])) < 1e-12, r
print(f"msa: {len(pairs)} demands (peak and residual drifts, accelerations) along y at 90 "
      "degrees = along x at 0, no twist")

# the demand tables
def table(path):
    head, data = check_schema(path)
    return [dict(zip(head, map(float, row[1:]))) for row in data]
for name in ("ida0/demands_S_im1.csv", "msa0/demands_S_stripe2.csv", "mc0/demands_S.csv",
             "run0/demands_S.csv"):
    t0, t90 = table(name), table(name.replace("0/", "90/", 1))
    assert t0 and len(t0) == len(t90), name
    for k in ([f"1-PID-{s}-1" for s in (1, 2, 3)] + [f"1-RID-{s}-1" for s in (1, 2, 3)] +
              [f"1-PFA-{f}-1" for f in (0, 1, 2, 3)]):
        k2 = k[:-1] + "2"
        scale = max(abs(r[k]) for r in t0)
        assert scale > 0, (name, k)
        for a, b in zip(t0, t90):
            close(b[k2], a[k], scale, f"{name}: {k2} at 90 against {k} at 0")
    for r in t0 + t90:
        for f in (1, 2, 3):
            assert abs(r[f"1-PFR-{f}-0"]) < 1e-12, (name, r)
    print(f"{name}: PID, RID, PFA along y at 90 degrees = along x at 0, PFR nil")
PY
echo "ok   a symmetric 3D building: along y at 90 degrees what along x at 0 (msa, ida, montecarlo, run)"
