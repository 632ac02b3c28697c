#!/usr/bin/env bash
# Outputs to a path that is a FIFO (or a device such as /dev/null or
# /dev/stdout) already: written in place, never replaced by the renamed
# temporary that makes a regular file's output atomic (as root, renaming over
# /dev/null would replace the device with a regular file). A FIFO stands for
# the devices, so that the test can fail without harming the machine: the
# recorder's lines must reach the FIFO's reader and the FIFO must stay one.
#   stream_outputs.sh POUNDFE
set -u
poundfe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }

cat > "$work/spring.tcl" <<'TCL'
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 1.0; fix 1 1
mass 2 1.0
uniaxialMaterial Elastic 1 4.0
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }
recorder Node -file [lindex $argv 0] -time -node 2 -dof 1 disp
system BandGeneral; numberer Plain; constraints Plain; test NormUnbalance 1e-6 25
integrator Newmark 0.5 0.25; algorithm Linear; analysis Transient
analyze 10 0.01
TCL

mkfifo "$work/fifo" || fail "mkfifo"
timeout 60 cat "$work/fifo" > "$work/read.txt" &
reader=$!
timeout 60 "$poundfe" opensees "$work/spring.tcl" "$work/fifo" > "$work/out.txt" 2>&1
status=$?
# a reader whose writer never came: end it (the old code renamed a regular
# file over the FIFO and never opened it)
[ -p "$work/fifo" ] || { kill $reader 2>/dev/null; fail "the FIFO was replaced: $(ls -l "$work")"; }
wait $reader
[ $status -eq 0 ] || fail "exit $status: $(cat "$work/out.txt")"
[ "$(wc -l < "$work/read.txt")" -eq 10 ] || fail "the reader got $(wc -l < "$work/read.txt") lines, not 10"
[ ! -e "$work/fifo.tmp" ] || fail "a temporary was left"
echo "stream outputs: 10 lines through a FIFO, which stays a FIFO"
