#!/usr/bin/env bash
# The figures of run and of the assessment commands as the program asks
# gnuplot to draw them (the script, not the pixels): a stand-in `gnuplot` on
# PATH keeps each script the program writes and creates the PNGs it names.
# Checked (tests/cli/figure_scripts.py): every title names the quantity and
# what it is of (the buildings, the pair, the site), the axes their units
# (mm, kN, g), the probability axes hold P = 0 and 1 with a margin, a
# histogram's y range ends above its tallest bar, and each panel resets the
# tics, box width and offsets an earlier one may have set. Commands: run
# (shear-pair-pounding), montecarlo and fragility (montecarlo-small), ida and
# msa (a 4-record suite of ground-motion), subset (subset-drift), separation
# (separation-sdof-pair), mitigation (mitigation-shear-pair), site-hazard.
#   figure_scripts.sh POUNDFE INPUT_DIR CLI_DIR
set -eu
poundfe=$(realpath "$1") input=$(realpath "$2") cli=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$cli/helpers.sh" # fail
mkdir "$work/bin" "$work/scripts"
cat > "$work/bin/gnuplot" <<'SH'
#!/bin/sh
# keeps the script as scripts/<command>.gp; an empty file per PNG
cp "$1" "$FIGURE_SCRIPTS/$COMMAND.gp"
grep -o "^set output '[^']*'" "$1" | cut -d"'" -f2 | while read -r f; do : > "$f"; done
SH
chmod +x "$work/bin/gnuplot"
export PATH="$work/bin:$PATH" FIGURE_SCRIPTS="$work/scripts"
cd "$work"
figures() { # command input [options...]
  local command=$1
  COMMAND=$command "$poundfe" "$@" --output "out-$command" --set "Output/Plots=true" > "$command.log" 2>&1 ||
    { tail -3 "$command.log"; fail "$command: exit $?"; }
}
figures run "$input/shear-pair-pounding.prm"
figures montecarlo "$cli/montecarlo-small.prm"
figures fragility "$cli/montecarlo-small.prm"
figures subset "$input/subset-drift.prm"
figures separation "$cli/separation-sdof-pair.prm"
figures mitigation "$input/mitigation-shear-pair.prm"
figures site-hazard "$input/site-hazard.prm"
"$poundfe" ground-motion "$input/msa-pounding-pair.prm" --realizations 4 --write-at2 --output gen \
  --set "Ground motion/Stochastic/Duration=4" --set "Output/Plots=false" > /dev/null || fail "ground-motion"
suite=(--set "IDA/Suite=$work/gen/records/suite.csv")
figures msa "$cli/msa/linear.prm" "${suite[@]}"
figures ida "$input/ida-pounding-pair.prm" "${suite[@]}" --set "Ground motion/Stochastic/Duration=4" \
  --set "IDA/Runs per record=6" --set "IDA/Tolerance=0.2"
python3 "$cli/figure_scripts.py" "$work/scripts" "$work"
