#!/usr/bin/env bash
# Build and run the libFuzzer targets of poundfe's readers, one per reader:
#   parameters  read_parameters: .prm and .json, every section (fuzz_parameters.cc)
#   at2         read_record: AT2 and column records (fuzz_at2.cc)
#   catalogue   read_catalogue: the earthquake catalogue CSV (fuzz_catalogue.cc)
#   hazard      read_pga_hazard: hazard_curve.csv or site-hazard summary.json (fuzz_hazard.cc)
#   fragility   read_fragility_summary: fragility summary.json (fuzz_fragility.cc)
#   mesh        read_line_mesh: Gmsh .msh, checked by check_gmsh_text (fuzz_mesh.cc)
#
#   tests/fuzz/run.sh [BUILD_DIR] [RUNS] [MAX_SECONDS]
#
# BUILD_DIR is a configured and built poundfe build (default: build): its
# libpoundfe_core.a (gcc) supplies the engine, and the readers' sources are
# compiled again with clang++ -fsanitize=fuzzer-no-link,address so that
# libFuzzer sees their coverage and AddressSanitizer checks them (the
# whole-file clang objects come first on the link line, so the archive's
# copies of them are never pulled in). Needs clang and its libFuzzer runtime
# (Debian: apt-get install clang-14 libclang-rt-14-dev). Not part of the
# default build: configure with -DPOUNDFE_FUZZERS=ON and build the target
# `fuzzers` to build them (FUZZ_BUILD_ONLY=1), or run this script.
# The targets run one after the other, each RUNS executions (default 10^6)
# or MAX_SECONDS (default 3600), whichever comes first, under nice -n 10;
# seeds: input/*.prm, tests/cli/*.json, tests/cli/bad/*.prm for parameters,
# tests/fuzz/seeds-<target>/ for the others. Exit 0 when no target found
# anything. FUZZ_TARGETS="at2 mesh" runs those; FUZZ_FORK=2 runs two worker
# processes per target. Measured: doc/verification.md, "Fuzzing".
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
if grep -q '^POUNDFE_UNITY_BUILD:BOOL=ON' "$build/CMakeCache.txt" &&
   ! grep -q '^POUNDFE_FUZZERS:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "run.sh: $build compiles in unity batches, whose objects would clash with the fuzzers'" \
       "single files: configure it with -DPOUNDFE_FUZZERS=ON (or -DPOUNDFE_UNITY_BUILD=OFF)" >&2
  exit 1
fi
runs=${2:-1000000}
max_time=${3:-3600}
all_targets="parameters at2 catalogue hazard fragility mesh"
targets=${FUZZ_TARGETS:-$all_targets}
work=$build/fuzz
mkdir -p "$work/objects" "$work/seeds-parameters"
for target in $targets; do mkdir -p "$work/corpus-$target"; done
cxx=${CXX_FUZZ:-clang++-14}
command -v "$cxx" > /dev/null || cxx=clang++

flags=$(sed -n 's/^CXX_DEFINES = //p; s/^CXX_INCLUDES = //p' "$build/CMakeFiles/poundfe_core.dir/flags.make" | tr '\n' ' ')
# the readers themselves; the rest (deal.II, the sections' declarations)
# runs from the gcc archive, uninstrumented
instrumented=(source/base/input_text.cc source/base/numbers.cc source/base/input_file.cc
              source/base/exceptions.cc source/input/input_parameters.cc
              source/reliability/reliability_analysis_parameters.cc source/reliability/limit_state.cc
              source/excitation/records.cc source/excitation/ground_motion.cc
              source/hazard/catalogue.cc source/hazard/pounding_hazard.cc
              source/hazard/site_hazard.cc source/mesh/gmsh_check.cc source/mesh/line_mesh.cc)
harnesses=()
for target in $all_targets; do harnesses+=("tests/fuzz/fuzz_$target.cc"); done
objects=()
# The newest header: an object older than it may hold an old layout of a
# struct (an object compiled before a member was added overflowed the
# stack of the InputParameters it built, a false finding), so every object
# is compiled again when any header changed.
newest_header=$(ls -t "$src"/include/poundfe/*/*.h "$src"/tests/fuzz/*.h | head -1)
for file in $(printf '%s\n' "${instrumented[@]}" | sort -u) "${harnesses[@]}"; do
  object=$work/objects/$(echo "$file" | tr / _).o
  if [ ! -e "$object" ] || [ "$src/$file" -nt "$object" ] || [ "$newest_header" -nt "$object" ]; then
    rm -f "$object"
    echo "clang: $file"
    # shellcheck disable=SC2086
    nice -n 10 "$cxx" -std=c++17 -O1 -gline-tables-only -fsanitize=fuzzer-no-link,address $flags \
      -I"$src/tests/fuzz" -c "$src/$file" -o "$object"
  fi
  case $file in tests/fuzz/*) ;; *) objects+=("$object") ;; esac
done
# the engine's link line (libraries of deal.II and its dependencies)
libraries=$(sed -e 's/^[^ ]* //' -e 's#CMakeFiles/poundfe.dir/source/main.cc.o##' -e 's#-o poundfe##' \
                -e "s#libpoundfe_core.a#$build/libpoundfe_core.a#" \
                -e 's#CMakeFiles/poundfe.dir/__/revision.cc.o##; s#CMakeFiles/poundfe.dir/revision.cc.o##' \
                "$build/CMakeFiles/poundfe.dir/link.txt")
for target in $targets; do
  binary=$work/fuzz_$target
  object=$work/objects/tests_fuzz_fuzz_$target.cc.o
  if [ ! -e "$binary" ] || [ "$object" -nt "$binary" ] || [ "$build/libpoundfe_core.a" -nt "$binary" ]; then
    echo "link: fuzz_$target"
    # shellcheck disable=SC2086
    nice -n 10 "$cxx" -fsanitize=fuzzer,address "$object" "${objects[@]}" $libraries -o "$binary" 2>&1 |
      grep -v "Cannot export local symbol '__asan" || true # gold on -rdynamic: harmless
  fi
done
[ "${FUZZ_BUILD_ONLY:-0}" = 1 ] && exit 0

cp "$src"/input/*.prm "$src"/tests/cli/bad/*.prm "$src"/tests/cli/*.json "$work/seeds-parameters/"
# malloc_context_size=0: no stack is recorded per allocation (declaring the
# parameters allocates ~33 000 times per execution; recording cost ~20 % of
# the time). Detection is unchanged; a report then lacks the allocation and
# free stacks: rerun its input (./fuzz_TARGET crash-...) with ASAN_OPTIONS
# set to detect_leaks=0 to see them.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:allocator_may_return_null=1:malloc_context_size=0}
# FUZZ_FORK=N: N worker processes (libFuzzer -fork=N; it stops after RUNS
# executions in all). On a shared machine two niced workers get twice one's
# share of the cores.
fork=${FUZZ_FORK:+-fork=$FUZZ_FORK}
status=0
for target in $targets; do
  seeds=$src/tests/fuzz/seeds-$target
  [ "$target" = parameters ] && seeds=$work/seeds-parameters
  echo "fuzz_$target: $runs executions or $max_time s"
  # shellcheck disable=SC2086
  (cd "$work" && nice -n 10 ./fuzz_$target -runs="$runs" -max_total_time="$max_time" \
     -max_len=40000 -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 $fork \
     "corpus-$target" "$seeds") > "$work/fuzz_$target.log" 2>&1 || status=1
  grep -E "^Done|stat::number_of_executed_units|ERROR|SUMMARY|crash-|timeout-|oom-|INFO: fuzzed for|INFO: exiting" \
    "$work/fuzz_$target.log" || true
  [ -n "$fork" ] && { grep -E "^#[0-9]+: cov" "$work/fuzz_$target.log" | tail -1 || true; }
done
exit $status
