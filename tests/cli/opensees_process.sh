#!/usr/bin/env bash
# `poundfe opensees` as a process (Running OpenSees scripts in
# doc/user-guide.md, "Signals, mpirun and write errors"):
#  1. SIGTERM and SIGINT during an analysis that records (and SIGTERM with
#     --threads 2, which the program's module runs): exit 128 + the signal
#     (143, 130), one message, and no recorder file, complete or temporary
#     (*.out.tmp), left behind;
#  2. under mpirun -np 2 each rank runs the script: getPID and getNP give
#     each its file; an error is printed by every rank that has it, "rank 1: "
#     before rank 1's (an error of rank 1 alone too);
#  3. a recorder's write error (its temporary a link to /dev/full: every
#     write fails with ENOSPC) found by the writer thread after the
#     script's last record names the recorder, its file and the analysis
#     time of the failed lines, exit 1, no file left.
#  4. the same error with two recorders, the failing one first or second:
#     at the script's end and at `wipe`, no recorder file at all (each
#     temporary is written out before any file is put in place); a `wipe`
#     or `remove recorder` whose error the script catches is done all the
#     same (the model wiped, the recorder gone) and its error, with the
#     time of the failed lines, is not reported again at the script's end.
#  5. a signal ends within a second a script that catches the analysis's
#     error in a loop (`catch {analyze 1 0.001}`), a loop of Tcl's own
#     commands (`while 1 {}`, also inside a `catch`) and a Tcl `after`:
#     exit 143 or 130, no recorder file left.
#   opensees_process.sh POUNDFE MPIRUN
set -u
poundfe=$1 mpirun=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }

# A spring and mass driven by a linear ramp, its displacement recorded at
# every step into each of the files named (the scripts below source it).
cat > "$work/spring.tcl" <<'TCL'
proc spring {files} {
  model basic -ndm 1 -ndf 1
  node 1 0.0; node 2 1.0; fix 1 1
  mass 2 1.0
  uniaxialMaterial Elastic 1 4.0
  element zeroLength 1 1 2 -mat 1 -dir 1
  timeSeries Linear 1
  pattern Plain 1 1 { load 2 1.0 }
  foreach file $files { recorder Node -file $file -time -node 2 -dof 1 disp }
  system BandGeneral; numberer Plain; constraints Plain; test NormUnbalance 1e-6 25
  integrator Newmark 0.5 0.25; algorithm Linear; analysis Transient
}
TCL
# long enough (1e8 steps) that only a signal ends it
cat > "$work/long.tcl" <<'TCL'
source [file join [file dirname [info script]] spring.tcl]
spring [lindex $argv 0]
analyze [lindex $argv 1] 0.001
TCL

# interrupted WHAT SIGNAL THREADS PAUSE SCRIPT ARGS...: runs the script,
# sends the signal PAUSE s after the recorder's temporary disp.out.tmp
# appears, and checks exit 128 + the signal, the one message, and no
# disp.out or disp.out.tmp left; sets elapsed_ms (from the signal to the exit).
interrupted() {
  local what=$1 signal=$2 threads=$3 pause=$4
  shift 4
  rm -f "$work"/disp.out*
  # --threads 2: the program's module (source/program.cc) runs the script
  local threads_option=()
  [ "$threads" = 1 ] || threads_option=(--threads "$threads")
  timeout -s KILL 120 "$poundfe" opensees "${threads_option[@]}" "$@" > "$work/signal.log" 2>&1 &
  local pid=$!
  for _ in $(seq 1 1500); do [ -e "$work/disp.out.tmp" ] && break; sleep 0.02; done
  [ -e "$work/disp.out.tmp" ] || fail "$what: the script did not start in 30 s"
  sleep "$pause"
  local start
  start=$(date +%s%N)
  # the timeout's child: poundfe itself
  kill -s "$signal" "$(pgrep -P "$pid" -x poundfe || echo "$pid")"
  wait "$pid"
  local status=$?
  elapsed_ms=$((($(date +%s%N) - start) / 1000000))
  local expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] || { cat "$work/signal.log"; fail "$what: exit $status, not $expected"; }
  grep -q "^poundfe: interrupted by a signal$" "$work/signal.log" ||
    { cat "$work/signal.log"; fail "$what: no message"; }
  local leftover
  leftover=$(ls "$work" | grep '^disp\.out')
  [ -z "$leftover" ] || fail "$what left $leftover"
}

# 1. signals: sent once the recorder's temporary exists (the analysis runs)
for case in "TERM 1" "INT 1" "TERM 2"; do
  read -r signal threads <<< "$case"
  interrupted "SIG$signal" "$signal" "$threads" 0 "$work/long.tcl" "$work/disp.out" 100000000
  echo "ok   SIG$signal during analyze (--threads $threads): exit 128 + the signal, no recorder file left"
done

# 2. mpirun -np 2: a file per rank, then one error message for both ranks
cat > "$work/ranks.tcl" <<'TCL'
set f [open [file join [lindex $argv 0] rank[getPID].txt] w]
puts $f "[getPID] of [getNP]"
close $f
node 1 0.0
TCL
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  "$mpirun" -np 2 "$poundfe" opensees "$work/ranks.tcl" "$work" > "$work/ranks.log" 2>&1 &&
  fail "mpirun: the script's error exited 0"
[ "$(cat "$work/rank0.txt" 2> /dev/null)" = "0 of 2" ] || fail "mpirun: rank 0's file"
[ "$(cat "$work/rank1.txt" 2> /dev/null)" = "1 of 2" ] || fail "mpirun: rank 1's file"
n0=$(grep -c "^poundfe: error: .*node: no model yet" "$work/ranks.log")
n1=$(grep -c "^rank 1: poundfe: error: .*node: no model yet" "$work/ranks.log")
[ "$n0" -eq 1 ] && [ "$n1" -eq 1 ] ||
  { cat "$work/ranks.log"; fail "mpirun: the error printed $n0 times by rank 0, $n1 by rank 1, not once each"; }
"$poundfe" opensees "$work/ranks.tcl" "$work" > /dev/null 2>&1
[ "$(cat "$work/rank0.txt")" = "0 of 1" ] || fail "alone: getPID 0, getNP 1"
# an error of rank 1 alone: printed by rank 1, with its rank
cat > "$work/own.tcl" <<'TCL'
if {[getPID] == 1} { node 1 0.0 }
TCL
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  "$mpirun" -np 2 "$poundfe" opensees "$work/own.tcl" > "$work/own.log" 2>&1 &&
  fail "mpirun: rank 1's error exited 0"
n1=$(grep -c "^rank 1: poundfe: error: .*own.tcl:1: node: no model yet" "$work/own.log")
n=$(grep -c "node: no model yet" "$work/own.log")
[ "$n1" -eq 1 ] && [ "$n" -eq 1 ] || { cat "$work/own.log"; fail "mpirun: rank 1's own error not printed once, by rank 1"; }
echo "ok   mpirun -np 2: one file per rank (getPID, getNP), each rank's error printed by it"

# 3. a write error met by the writer thread (--threads 2) after the last
# record, and inline: 10 steps of 0.001 s, the last line at t = 0.01 s
for threads in 2 1; do
  rm -f "$work"/disp.out*
  ln -s /dev/full "$work/disp.out.tmp" # opened through the link: every write fails (ENOSPC)
  "$poundfe" opensees --threads $threads "$work/long.tcl" "$work/disp.out" 10 > "$work/full.log" 2>&1
  status=$?
  [ "$status" -eq 1 ] || { cat "$work/full.log"; fail "write error (--threads $threads): exit $status"; }
  expected="poundfe: error: recorder 0: disk full: cannot write $work/disp.out: No space left on device (its lines up to time 0.01)"
  grep -qxF "$expected" "$work/full.log" ||
    { cat "$work/full.log"; fail "write error (--threads $threads): not '$expected'"; }
  leftover=$(ls "$work" | grep '^disp\.out')
  [ -z "$leftover" ] || fail "write error (--threads $threads) left $leftover"
  echo "ok   a write error after the last record (--threads $threads): recorder 0, t = 0.01, exit 1"
done

# 4. two recorders, disp.out failing (7 steps of 0.02 s: its lines up to 0.14)
cat > "$work/twin.tcl" <<'TCL'
source [file join [file dirname [info script]] spring.tcl]
lassign $argv dir order mode
proc build {dir names} { spring [lmap name $names { file join $dir $name }] }
build $dir $order
analyze 7 0.02
switch $mode {
  wipe { wipe }
  catchwipe {
    if {![catch {wipe} message]} { error "wipe did not fail" }
    puts "caught: $message"
    puts "time after wipe: [getTime]"
    build $dir again.out
    analyze 2 0.02
  }
  catchremove {
    if {![catch {remove recorder [lsearch $order disp.out]} message]} { error "remove did not fail" }
    puts "caught: $message"
    analyze 5 0.02
  }
}
TCL
for order in "ok.out disp.out" "disp.out ok.out"; do
  [ "${order%% *}" = disp.out ] && tag=0 || tag=1
  error="recorder $tag: disk full: cannot write $work/disp.out: No space left on device (its lines up to time 0.14)"
  for mode in end wipe catchwipe catchremove; do
    rm -f "$work"/*.out "$work"/*.out.tmp
    ln -s /dev/full "$work/disp.out.tmp"
    "$poundfe" opensees "$work/twin.tcl" "$work" "$order" $mode > "$work/twin.log" 2>&1
    status=$?
    files=$(cd "$work" && ls *.out 2> /dev/null | tr '\n' ' ')
    case $mode in
      end | wipe) expected_status=1 expected_files="" ;;
      catchwipe) expected_status=0 expected_files="again.out " ;;
      catchremove) expected_status=0 expected_files="ok.out " ;;
    esac
    what="write error, recorders $order, $mode"
    [ "$status" -eq $expected_status ] || { cat "$work/twin.log"; fail "$what: exit $status"; }
    [ "$files" = "$expected_files" ] || { cat "$work/twin.log"; fail "$what: files '$files', not '$expected_files'"; }
    n=$(grep -cF "$error" "$work/twin.log")
    [ "$n" -eq 1 ] || { cat "$work/twin.log"; fail "$what: '$error' $n times, not once"; }
    case $mode in
      catchwipe) grep -qx "time after wipe: 0.000000" "$work/twin.log" ||
        { cat "$work/twin.log"; fail "$what: the model not wiped"; } ;;
      catchremove) [ "$(wc -l < "$work/ok.out")" -eq 12 ] || fail "$what: ok.out not 7 + 5 lines" ;;
    esac
  done
  echo "ok   a write error with recorders $order: at the end and at wipe no file; caught wipe, remove done, reported once"
done

# 5. signals in loops that catch, and in Tcl's own loops
cat > "$work/loops.tcl" <<'TCL'
source [file join [file dirname [info script]] spring.tcl]
spring [lindex $argv 0]
analyze 1 0.001
switch [lindex $argv 1] {
  catch { while 1 { if {[catch {analyze 1 0.001} message]} { puts "caught: $message" } } }
  while { while 1 {} }
  catchwhile { while 1 { catch { while 1 {} } } }
  after { after 100000 }
}
TCL
for case in "catch TERM" "catch INT" "while TERM" "catchwhile INT" "after TERM" "catch TERM 2" "while INT 2"; do
  read -r loop signal threads <<< "$case"
  what="SIG$signal in '$loop' (--threads ${threads:-1})"
  interrupted "$what" "$signal" "${threads:-1}" 0.3 "$work/loops.tcl" "$work/disp.out" "$loop"
  [ "$elapsed_ms" -lt 1000 ] || fail "$what: ended $elapsed_ms ms after the signal"
  grep -q "^caught" "$work/signal.log" && { cat "$work/signal.log"; fail "$what: the script caught the interruption"; }
  echo "ok   $what: exit 128 + the signal after $elapsed_ms ms, no recorder file left"
done
