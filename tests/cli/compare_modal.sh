#!/usr/bin/env bash
# deal.II-style output comparison: the modal frequencies of the three-storey
# shear building against the closed-form values of doc/theory.md §1
# (4 decimals given, so numdiff's relative tolerance is 1e-5).
set -eu
poundfe=$1 input=$2 expected=$3 numdiff=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$poundfe" modal "$input" --output "$work/out" > "$work/stdout"
python3 - "$work/out/summary.json" > "$work/frequencies.output" <<'PY'
import json, sys
for f in json.load(open(sys.argv[1]))["modes"]["frequencies_hz"]:
    print(f"{f:.6f}")
PY
cat "$work/frequencies.output"
"$numdiff" -q -r 1e-5 "$work/frequencies.output" "$expected" && echo "numdiff: frequencies agree"
