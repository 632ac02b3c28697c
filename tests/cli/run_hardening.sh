#!/usr/bin/env bash
# `run` where it used to fail or mislead (issue 14, items 7, 9, 11, 12):
#  - undamped: the default example with damping 0 runs to the end, its Newton
#    iterations converge, and its energy balance closes to 1e-6;
#  - warnings: an absurd run (the example at 27x its PGA) warns of its drift
#    ratios on the console and in summary.json; the example itself does not;
#  - reused directory: a second run (other model, other outputs) into the
#    first one's directory leaves only its own files (the .pvd lists exactly
#    the VTU frames present) and the user's file there untouched;
#  - SIGTERM: exit status 143, summary "interrupted", complete files, no *.tmp;
#  - a blocked summary.json (a directory in its place): exit status 1, the OS
#    reason on stderr, no summary.json.tmp;
#  - a full disk (a small tmpfs; needs root, skipped otherwise): exit status
#    1, summary.json "failed" with "disk full: ... No space left on device",
#    no *.tmp.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'umount "$work/small" 2> /dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
json_number() { sed -n "s/.*\"$2\": \\([^,}]*\\).*/\\1/p" "$1" | head -n 1; }
no_temporaries() {
  [ -z "$(find "$1" -name '*.tmp')" ] || fail "$1: temporary files left: $(find "$1" -name '*.tmp')"
}
# <file> <end time> [sed script]: the default example, shortened
example() {
  sed "s/^subsection Time integration/subsection Time integration\n  set End time = $2/
       ${3:-}" "$input/two-buildings.prm" > "$1"
  grep -q "End time = $2" "$1" || fail "could not write $1"
}

# --- undamped -----------------------------------------------------------
example "$work/undamped.prm" 2 's/set Damping ratio = .*/set Damping ratio = 0/
  s/set VTU interval *= .*/set VTU interval = 0/; s/^\(subsection Output\)/\1\n  set Plots = false/'
[ "$(grep -c 'Damping ratio = 0$' "$work/undamped.prm")" -eq 2 ] || fail "undamped: damping not set to 0"
status=0
"$poundfe" run "$work/undamped.prm" --output "$work/undamped" > "$work/undamped.log" 2>&1 || status=$?
[ "$status" -eq 0 ] || fail "undamped: exit status $status: $(tail -n 3 "$work/undamped.log")"
s=$work/undamped/summary.json
grep -q '"status": "completed"' "$s" || fail "undamped: not completed"
[ "$(json_number "$s" damping_J)" = 0 ] || fail "undamped: damping energy $(json_number "$s" damping_J)"
error=$(json_number "$s" max_relative_balance_error)
cuts=$(json_number "$s" step_cuts)
# the balance measures how well each step's equations were solved (theory
# §3.9): Newton's tolerances bound it near 1e-8; 1e-6 leaves room, and a
# criterion that accepted unconverged iterates would exceed it
awk -v e="$error" 'BEGIN { exit !(e != "" && e < 1e-6) }' || fail "undamped: energy balance error $error"
echo "ok   undamped default example: 2 s completed, energy balance error $error, $cuts step cuts"

# --- warnings -----------------------------------------------------------
grep -q '"warnings": \[\]' "$s" || fail "undamped: warnings on a sane run: $(grep -A2 warnings "$s")"
example "$work/absurd.prm" 3 's/set Target PGA  = 0.35/set Target PGA  = 9.5/
  s/set VTU interval *= .*/set VTU interval = 0/; s/^\(subsection Output\)/\1\n  set Plots = false/'
status=0
"$poundfe" run "$work/absurd.prm" --output "$work/absurd" > "$work/absurd.log" 2>&1 || status=$?
grep -q "poundfe: warning: .*drift ratio .* exceeds Output/Warnings/Drift ratio = 0.1" "$work/absurd.log" ||
  fail "absurd: no drift warning on the console (exit $status): $(tail -n 3 "$work/absurd.log")"
grep -q '"warnings": \[".*drift ratio' "$work/absurd/summary.json" || fail "absurd: no warnings in summary.json"
echo "ok   warnings: the example at 27x its PGA warns ($(grep -c 'poundfe: warning' "$work/absurd.log") warnings), the example itself none"

# --- reused directory ---------------------------------------------------
# first: two frames with gaps, VTU every 0.05 s, plots; then one frame
# without gaps, VTU every 0.25 s, other recorders, into the same directory
d=$work/reused
example "$work/first.prm" 1 's/set VTU interval *= .*/set VTU interval = 0.05/'
sed 's/^subsection Time integration/subsection Time integration\n  set End time = 1/
     s/set VTU interval *= .*/set VTU interval = 0.25/' "$input/three-storey-frame-hinges.prm" > "$work/second.prm"
"$poundfe" run "$work/first.prm" --output "$d" > /dev/null 2>&1 || fail "reused: the first run failed"
[ -f "$d/contact_force.csv" ] && [ -f "$d/impacts.csv" ] || fail "reused: the first run wrote no contact files"
n_first=$(ls "$d/solution" | wc -l)
echo "the user's notes" > "$d/notes.txt"
mkdir -p "$d/modal" && echo keep > "$d/modal/mine.txt"
"$poundfe" run "$work/second.prm" --output "$d" > /dev/null 2>&1 || fail "reused: the second run failed"
# what the second run lists (summary.json's files), the frames, the manifest and the user's files
listed=$(python3 -c 'import json, sys; print("\n".join(json.load(open(sys.argv[1]))["output"]["files"]))' "$d/summary.json")
expected=$( (echo "$listed" | grep -v '/$'; ls "$d/solution" | sed 's|^|solution/|'
             echo .poundfe-files; echo notes.txt; echo modal/mine.txt) | sort)
present=$(cd "$d" && find . -type f | sed 's|^\./||' | sort)
[ "$present" = "$expected" ] || fail "reused: files differ from the second run's: $(diff <(echo "$expected") <(echo "$present"))"
for f in contact_force.csv impacts.csv; do [ ! -e "$d/$f" ] || fail "reused: $f of the first run left"; done
pvd=$(grep -o 'file="[^"]*"' "$d/solution.pvd" | sed 's/file="//; s/"$//' | sort)
[ "$pvd" = "$(ls "$d/solution" | sed 's|^|solution/|' | sort)" ] || fail "reused: the .pvd does not list exactly the frames present"
[ "$(cat "$d/notes.txt")" = "the user's notes" ] || fail "reused: the user's file changed"
echo "ok   reused directory: $n_first frames and the contact files of the first run gone, $(echo "$pvd" | wc -l) frames = the .pvd, the user's files kept"

# --- SIGTERM ------------------------------------------------------------
d=$work/sigterm
example "$work/long.prm" 2000 's/set VTU interval *= .*/set VTU interval = 0/; s/set Output interval *= .*/set Output interval = 0.1/'
status=0
"$poundfe" run "$work/long.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
for _ in $(seq 1 1500); do [ -d "$d" ] && break; sleep 0.02; done
sleep 1
kill -TERM "$job"
wait "$job" 2> /dev/null || status=$?
[ "$status" -eq 143 ] || fail "sigterm: exit status $status: $(cat "$d.log")"
grep -q '"status": "interrupted"' "$d/summary.json" || fail "sigterm: not interrupted"
no_temporaries "$d"
end=$(json_number "$d/summary.json" end_time_s)
last=$(tail -n 1 "$d/drift.csv" | cut -d, -f1)
awk -v e="$end" -v l="$last" 'BEGIN { exit !(e > 0 && l <= e && e - l < 0.1 + 1e-9) }' ||
  fail "sigterm: drift.csv ends at $last, the summary at $end"
echo "ok   SIGTERM: exit status 143, interrupted at t = $end s, drift.csv complete to $last s, no *.tmp"

# --- summary.json blocked -----------------------------------------------
d=$work/blocked
mkdir -p "$d/summary.json"
example "$work/short.prm" 0.2 's/set VTU interval *= .*/set VTU interval = 0/; s/^\(subsection Output\)/\1\n  set Plots = false/'
status=0
"$poundfe" run "$work/short.prm" --output "$d" > "$d.log" 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "blocked: exit status $status"
grep -q "cannot write .*summary.json: Is a directory" "$d.log" || fail "blocked: no reason on stderr: $(cat "$d.log")"
no_temporaries "$d"
[ -s "$d/drift.csv" ] || fail "blocked: drift.csv not written"
echo "ok   summary.json blocked: exit status 1, '$(grep -o 'cannot write [^(]*' "$d.log" | head -n 1 | sed "s|$work/||")' on stderr, no *.tmp"

# --- full disk ----------------------------------------------------------
mkdir -p "$work/small"
if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=256k tmpfs "$work/small" 2> /dev/null; then
  echo "skip full disk: needs root to mount a small tmpfs"
  exit 0
fi
d=$work/small/run
example "$work/full.prm" 3 's/set VTU interval *= .*/set VTU interval = 0/; s/set Output interval *= .*/set Output interval = 0/
  s/^\(subsection Output\)/\1\n  set Plots = false/'
status=0
"$poundfe" run "$work/full.prm" --output "$d" > "$work/full.log" 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "full disk: exit status $status: $(tail -n 3 "$work/full.log")"
grep -q "disk full: cannot write .*: No space left on device" "$work/full.log" ||
  fail "full disk: no reason on stderr: $(cat "$work/full.log")"
no_temporaries "$d"
if [ -f "$d/summary.json" ]; then
  grep -q '"status": "failed"' "$d/summary.json" || fail "full disk: summary not failed"
  grep -q '"message": "disk full: cannot write .*No space left on device' "$d/summary.json" ||
    fail "full disk: the summary does not say the disk is full"
  said="summary.json 'failed', 'disk full: ...'"
else
  grep -q "cannot write .*summary.json" "$work/full.log" || fail "full disk: no summary.json and no word of it"
  said="no room for summary.json, said on stderr"
fi
echo "ok   full disk (256 kB tmpfs): exit status 1, $said, no *.tmp"
