#!/usr/bin/env bash
# `spectrum` and a run's floor spectra (issue 13 item 3) on input/floor-spectra.prm:
#   - spectrum: spectrum.csv (PSA = w^2 Sd), the intensity measures in summary.json;
#   - spectrum --realizations: re-run with the S0 it reports, the ensemble's
#     mean PSA at the matching period equals the target (PSA scales as sqrt(S0));
#   - --realizations without a stochastic motion: exit 1, nothing written;
#   - run with Output/Floor spectra: floor_spectra.csv listed in summary.json,
#     each floor's spectrum against RK4 on the run's own floor accelerations.
set -eu
poundfe=$1 input=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() { python3 "$here/spectrum_check.py" "$@"; }

"$poundfe" spectrum "$input" --output "$work/single" > /dev/null
check single "$work/single"

"$poundfe" spectrum "$input" --realizations 6 --output "$work/ensemble" > /dev/null
read -r s0 period < <(check s0 "$work/ensemble")
sed -e "s/^\(\s*subsection Stochastic\)/\1\n    set S0 = $s0/" \
    -e "s/^\(\s*subsection Spectrum\)/\1\n  set Matching period = $period/" "$input" > "$work/matched.prm"
"$poundfe" spectrum "$work/matched.prm" --realizations 6 --output "$work/matched" > /dev/null
check matched "$work/matched"

sed -e 's/set Type = kanai-tajimi/set Type = none/' -e 's/set Time step = 0.005/&\n  set End time = 1/' \
    "$input" > "$work/none.prm"
if "$poundfe" spectrum "$work/none.prm" --realizations 3 --output "$work/none" 2> "$work/err"; then
  echo "FAIL --realizations without a stochastic motion succeeded"; exit 1
fi
grep -q "needs a stochastic ground motion" "$work/err" || { echo "FAIL message: $(cat "$work/err")"; exit 1; }
[ ! -e "$work/none" ] || { echo "FAIL output written despite bad input"; exit 1; }
echo "ok   --realizations without a stochastic motion: $(cat "$work/err")"

"$poundfe" run "$input" --output "$work/run" > /dev/null
check floors "$work/run"
if ls "$work"/*/ | grep -q '\.tmp$'; then echo "FAIL temporary files left"; exit 1; fi
