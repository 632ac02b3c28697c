#!/usr/bin/env bash
# Output/Field format = xdmf on a full disk (a 256 kB tmpfs; needs root,
# skipped otherwise), one process: run (solution.h5 fills the disk) and
# modal (modes.h5 on a disk a filler left 24 kB of): exit status 1, no
# crash (HDF5 had been left a file it could not close, which its exit
# handler touched: SIGSEGV after the run), "disk full" naming the .h5 file,
# summary.json "failed" with the reason and without the .h5, no *.tmp.
#   xdmf_full_disk.sh POUNDFE INPUT-DIRECTORY
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'umount "$work/small" 2> /dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
mkdir -p "$work/small"
if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=256k tmpfs "$work/small" 2> /dev/null; then
  echo "skip full disk: needs root to mount a small tmpfs"
  exit 0
fi
xdmf="s/^subsection Output/subsection Output\n  set Plots = false\n  set Field format = xdmf/"

full_disk() { # label directory h5-name command...
  local label=$1 d=$2 h5=$3
  shift 3
  local status=0
  timeout -k 5 60 "$poundfe" "$@" --output "$d" > "$work/log" 2>&1 || status=$?
  [ "$status" -eq 1 ] || fail "$label: exit status $status (139: SIGSEGV): $(tail -n 3 "$work/log")"
  grep -q "poundfe: error: disk full: cannot write .*$h5: No space left on device" "$work/log" ||
    fail "$label: $h5 not named: $(cat "$work/log")"
  grep -q '"status": "failed"' "$d/summary.json" || fail "$label: summary.json not 'failed'"
  grep -q "\"message\": \"disk full: cannot write .*$h5" "$d/summary.json" ||
    fail "$label: summary.json does not say what failed"
  ! grep -q "\"$h5\"" "$d/summary.json" || fail "$label: summary.json lists $h5"
  [ -z "$(find "$d" -name '*.tmp')" ] || fail "$label: temporary files left: $(find "$d" -name '*.tmp')"
  [ ! -e "$d/$h5" ] || fail "$label: a partial $h5"
  echo "ok   $label: exit status 1, 'disk full' naming $h5, summary.json 'failed', no *.tmp"
}

# a frame every 0.011 s (the cap of 2000 frames) of 20 s: far more than 256 kB
sed -e "s/set VTU interval *= .*/set VTU interval = 0.01/" -e "s/set Output interval *= .*/set Output interval = 1/" \
    -e "$xdmf" "$input/two-buildings.prm" > "$work/run.prm"
full_disk "run, solution.h5 fills the disk" "$work/small/run" solution.h5 run "$work/run.prm"

# six modes of two frames: modes.h5 is 38 kB
rm -rf "$work/small/run"
head -c $((232 * 1024)) /dev/zero > "$work/small/filler"
sed -e "$xdmf" "$input/two-buildings.prm" > "$work/modal.prm"
full_disk "modal, modes.h5 on a disk with 24 kB left" "$work/small/modal" modes.h5 modal "$work/modal.prm"
