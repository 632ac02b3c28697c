#!/usr/bin/env bash
# Regenerate every table and figure of the thesis that poundfe can set up
# (input/thesis/, one input per table or figure) and write
# doc/thesis-reproduction.md: each table's printed values beside poundfe's
# with the difference (tests/cli/thesis_tables.py, which cli/thesis-tables
# also runs), each figure beside its regenerated plot (doc/thesis-figures/),
# what the thesis leaves unspecified and what was chosen, and what cannot be
# reproduced yet. About 4–5 minutes.
#   scripts/reproduce-thesis.sh BUILD_DIR [OUTPUT_DIR [--check]]   (OUTPUT_DIR: results/thesis)
# --check (cli/thesis-reproduction): every run but the five bifurcation
# diagrams (4 of the 5 minutes), then each line of the committed
# doc/thesis-reproduction.md that those runs decide is compared with the
# regenerated one; nothing in doc/ is written. Exit 1 on a difference.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [OUTPUT_DIR [--check]]" >&2; exit 1; }
build=$(cd "$1" && pwd)
check=${3:-}
cd "$(dirname "$0")/.."
poundfe=$build/poundfe
[ -x "$poundfe" ] || { echo "reproduce-thesis.sh: no $poundfe (build first)" >&2; exit 1; }
out=${2:-results/thesis}
inputs=input/thesis
figures=doc/thesis-figures
mkdir -p "$out"
[ "$check" = --check ] || mkdir -p "$figures"
timing="$out/timing.txt"
: > "$timing"

# run COMMAND NAME [INPUT]: poundfe COMMAND on input/thesis/NAME.prm into $out/NAME
run() {
  local command=$1 name=$2 file=${3:-$inputs/$2.prm}
  local start=$SECONDS
  "$poundfe" "$command" "$file" --output "$out/$name" > "$out/$name.log"
  echo "$name: poundfe $command ${file#"$out"/}, $((SECONDS - start)) s" >> "$timing"
}

# Tables. Table 2.2 also with the intensity not rounded (the thesis's rule
# for its first row): a copy of the input beside a copy of its catalogue.
run site-hazard table-2.2
sed 's/^\( *set Intensity decimals *=\).*/\1 -1/' "$inputs/table-2.2.prm" > "$out/table-2.2-unrounded.prm"
cp "$inputs/memvele-events.csv" "$out/"
run site-hazard table-2.2-unrounded "$out/table-2.2-unrounded.prm"
run site-hazard table-2.3
run site-hazard table-2.3-catalogue
run run table-3.1
run modal eq-2.36

# Figures
for f in fig-3.1a fig-3.1b fig-3.1c fig-3.9; do run run $f; done
run run fig-3.10c input/three-storey-free-vibration.prm
if [ "$check" != --check ]; then
  for f in fig-3.2a fig-3.2b fig-3.2c fig-3.2d fig-3.2e; do run bifurcation $f; done
fi
for f in fig-3.3a fig-3.3b fig-3.4a fig-3.5a-low fig-3.5a-high fig-3.6; do run stationary-pdf $f; done
run reliability fig-3.12
run switching fig-3.7

if [ "$check" = --check ]; then
  exec python3 scripts/thesis_reproduction.py --check doc/thesis-reproduction.md "$out" "$timing"
fi

copy() { cp "$out/$1" "$figures/$2"; }
for f in fig-3.1a fig-3.1b fig-3.1c; do copy $f/phase_portrait.png $f.png; done
for f in fig-3.2a fig-3.2b fig-3.2c fig-3.2d fig-3.2e; do copy $f/bifurcation.png $f.png; done
for f in fig-3.3a fig-3.3b fig-3.5a-low fig-3.5a-high; do copy $f/pdf.png $f.png; done
copy table-3.1/phase_portrait.png table-3.1-phase.png
copy fig-3.7/phase_portrait.png fig-3.7.png
copy table-3.1/contact_force.png table-3.1-contact-force.png
copy fig-3.9/hysteresis_sdof_S1.png fig-3.9-hysteresis.png
copy fig-3.9/phase_portrait.png fig-3.9-phase.png
copy fig-3.10c/roof_displacement.png fig-3.10c.png
for f in fig-3.4a fig-3.6; do copy $f/p_bifurcation.png $f.png; done

python3 scripts/thesis_reproduction.py "$out" "$timing" > doc/thesis-reproduction.md.tmp
mv doc/thesis-reproduction.md.tmp doc/thesis-reproduction.md
echo "doc/thesis-reproduction.md and $figures/ written; run outputs in $out/"
cat "$timing"
