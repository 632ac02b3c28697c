#!/usr/bin/env bash
# SIGTERM stops a long spectrum within seconds: 10000 periods from 1 ms to
# 1000 s take minutes (the free vibration after the motion alone is ~10^7
# sub-steps for the shortest oscillators), and the oscillators' loops check
# the interruption flag. The command exits 143 with summary.json
# "interrupted". Before the check, a spectrum went on for minutes after
# SIGTERM.
set -u
poundfe=$1
input=$2
limit=${3:-10} # seconds from the signal to the exit (the loops check every ~1e6 sub-steps)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$poundfe" spectrum "$input" --output "$work/out" --set "Spectrum/Minimum period=0.001" \
  --set "Spectrum/Maximum period=1000" --set "Spectrum/Number of periods=10000" \
  --set "Output/Plots=false" > "$work/log" 2>&1 &
pid=$!
# Signal once the process has spent 2 s of CPU: past the start-up (under
# 1 s) and inside the oscillators' loops, whatever the machine's load.
ticks=$(getconf CLK_TCK)
while kill -0 "$pid" 2> /dev/null; do
  cpu=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2> /dev/null || echo 0)
  [ "${cpu:-0}" -ge $((2 * ticks)) ] && break
  sleep 0.2
done
if ! kill -0 "$pid" 2> /dev/null; then
  echo "FAIL: the spectrum ended before the signal: $(cat "$work/log")"
  exit 1
fi
kill -TERM "$pid"
start=$(date +%s%N)
while kill -0 "$pid" 2> /dev/null; do
  if [ $(( ($(date +%s%N) - start) / 1000000000 )) -ge $((limit * 6)) ]; then
    kill -KILL "$pid"
    echo "FAIL: still running $((limit * 6)) s after SIGTERM"
    exit 1
  fi
  sleep 0.1
done
wait "$pid"
status=$?
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
echo "exit $status, ${elapsed_ms} ms after SIGTERM"
failures=0
[ "$status" -eq 143 ] || { echo "FAIL: exit $status, expected 143: $(cat "$work/log")"; failures=1; }
[ "$elapsed_ms" -le $((limit * 1000)) ] || { echo "FAIL: ${elapsed_ms} ms from SIGTERM to the exit, more than ${limit} s"; failures=1; }
grep -q '"status": "interrupted"' "$work/out/summary.json" 2> /dev/null ||
  { echo "FAIL: summary.json does not say interrupted"; failures=1; }
[ -z "$(find "$work/out" -name '*.tmp*' 2> /dev/null)" ] || { echo "FAIL: temporaries left"; failures=1; }
[ "$failures" -eq 0 ] && echo "ok   spectrum stopped by SIGTERM"
exit "$failures"
