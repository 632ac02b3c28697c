#!/usr/bin/env bash
# Initial conditions and modal damping (issue 25 items 1 and 4) in an
# example: input/three-storey-free-vibration.prm released from u0 = 0.05 m
# against the closed-form damped modal superposition
# (free_vibration_check.py says the reference and the tolerance).
#   free_vibration.sh POUNDFE INPUT_DIR
set -eu
poundfe=$1 input=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$poundfe" run "$input/three-storey-free-vibration.prm" --output "$work/run" > "$work/log" \
  || { cat "$work/log"; exit 1; }
python3 "$here/free_vibration_check.py" "$work/run"
