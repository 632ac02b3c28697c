#!/usr/bin/env bash
# Build and run the libFuzzer targets of poundfe's readers, one per reader:
#   parameters         read_parameters: .prm and .json, every section (fuzz_parameters.cc)
#   random_parameters  Random parameters resolved against built models, their limit
#                      states compiled against the response columns, one short
#                      realization; Reliability's limit states (fuzz_random_parameters.cc)
#   at2                read_record: AT2 and column records (fuzz_at2.cc)
#   suite              read_record_suite: CSV and JSON record suites (fuzz_suite.cc)
#   forces             make_nodal_forces: a Nodal forces/Tabulated force table (fuzz_forces.cc)
#   catalogue          read_catalogue: the earthquake catalogue CSV (fuzz_catalogue.cc)
#   hazard             read_pga_hazard: hazard_curve.csv or site-hazard summary.json (fuzz_hazard.cc)
#   fragility          read_fragility_summary: fragility summary.json (fuzz_fragility.cc)
#   mesh               read_line_mesh(_3d): Gmsh .msh, checked by check_gmsh_text (fuzz_mesh.cc)
#   mesh_building      a 2D and a 3D mesh building built from the .msh (fuzz_mesh_building.cc)
#
#   tests/fuzz/run.sh [TARGET|all] [RUNS] [MAX_SECONDS]
#
# Each target runs RUNS executions (default 10^6) or MAX_SECONDS (default
# 900), whichever comes first, one target after the other, one process
# (FUZZ_FORK=N: N workers), under nice -n 10. It starts from its kept,
# minimised corpus tests/fuzz/corpus/TARGET/ (and the seeds: input/*.prm,
# tests/cli/*.json, tests/cli/bad/*.prm for parameters, tests/fuzz/seeds-TARGET/
# for the others) and writes what it finds new to BUILD/fuzz/corpus-TARGET/;
# FUZZ_MERGE=1 then merges both into a fresh minimal corpus (libFuzzer
# -merge=1: only inputs that add coverage) that replaces tests/fuzz/corpus/TARGET/.
# FUZZ_REPLAY=1 runs each target once over its kept corpus (-runs=0) instead.
# A finding is a crash, an AddressSanitizer or UndefinedBehaviorSanitizer
# report, a 10 s hang, an out-of-memory or an exception other than the
# target's refusals (reader_target.h); libFuzzer saves its input as
# BUILD/fuzz/crash-* (timeout-*, oom-*). Exit 0 when no target found anything.
#
# BUILD (FUZZ_BUILD, default build-fuzz/ at the top of the tree) is a gcc
# Release build, configured and built (target poundfe_core) here when
# needed: its libpoundfe_core.a supplies the engine, and the readers' sources
# are compiled again with clang++ -fsanitize=fuzzer-no-link,address,undefined,
# so that libFuzzer sees their coverage and the sanitizers check them (the
# clang objects come first on the link line). build-fuzz/ is configured in
# unity batches like build/ (FUZZ_UNITY=OFF: file by file), so that ccache
# serves it from the main build's objects: compiled file by file the library
# takes over an hour on two busy cores. A batch also holds the gcc copy of
# an instrumented file; the link takes the clang one (see muldefs below).
# Needs clang 14 and its libFuzzer runtime (Debian: clang-14
# libclang-rt-14-dev). FUZZ_BUILD_ONLY=1 builds and stops (the CMake target
# `fuzzers` of a build configured with -DPOUNDFE_FUZZERS=ON does that with
# FUZZ_BUILD set to it). Measured: doc/verification.md, "Fuzzing".
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${FUZZ_BUILD:-$src/build-fuzz}
all_targets="parameters random_parameters at2 suite forces catalogue hazard fragility mesh mesh_building"
case ${1:-all} in
  all) targets=$all_targets ;;
  *) targets=$1
     for t in $targets; do
       case " $all_targets " in *" $t "*) ;; *) echo "run.sh: no target '$t' ($all_targets)" >&2; exit 1 ;; esac
     done ;;
esac
runs=${2:-1000000}
max_time=${3:-900}

# the gcc library, file by file
if [ ! -e "$build/CMakeCache.txt" ]; then
  mkdir -p "$build"
  launcher=()
  if command -v ccache > /dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$src}" CCACHE_NOHASHDIR=1
    export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
  fi
  echo "run.sh: configuring $build (Release, POUNDFE_UNITY_BUILD=${FUZZ_UNITY:-ON})"
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPOUNDFE_UNITY_BUILD="${FUZZ_UNITY:-ON}" \
    "${launcher[@]}" > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
fi
# A unity batch object holds the gcc copies of the clang objects' functions
# beside other files' functions it is linked for: the first definition (the
# clang object's) is taken. That is sound because the library is compiled
# with -fPIC (deal.II's flags): gcc then neither inlines a global function
# nor calls it other than through its symbol, so every call reaches the
# clang copy; only the batch's unused copies stay behind.
muldefs=()
if grep -q '^POUNDFE_UNITY_BUILD:BOOL=ON' "$build/CMakeCache.txt" &&
   ! grep -q '^POUNDFE_FUZZERS:BOOL=ON' "$build/CMakeCache.txt"; then
  grep -q -- '-fPIC' "$build/CMakeFiles/poundfe_core.dir/flags.make" ||
    { echo "run.sh: $build is a unity build without -fPIC: configure it with -DPOUNDFE_UNITY_BUILD=OFF" >&2; exit 1; }
  muldefs=(-Wl,--allow-multiple-definition)
fi
if [ "${FUZZ_SKIP_LIBRARY:-0}" != 1 ]; then
  echo "run.sh: building poundfe_core in $build (log: $build/library.log)"
  nice -n 10 cmake --build "$build" -j"${FUZZ_JOBS:-2}" --target poundfe_core > "$build/library.log" 2>&1 ||
    { tail -30 "$build/library.log"; exit 1; }
fi
work=$build/fuzz
mkdir -p "$work/objects" "$work/seeds-parameters"
cxx=${CXX_FUZZ:-clang++-14}
command -v "$cxx" > /dev/null || cxx=clang++

flags=$(sed -n 's/^CXX_DEFINES = //p; s/^CXX_INCLUDES = //p' "$build/CMakeFiles/poundfe_core.dir/flags.make" | tr '\n' ' ')
# UndefinedBehaviorSanitizer stops at its first report, so libFuzzer sees it
sanitizers="address,undefined -fno-sanitize-recover=undefined"
# the readers and resolvers themselves; the rest (deal.II, the model
# builder, the engine) runs from the gcc archive, uninstrumented
instrumented=(source/base/input_text.cc source/base/numbers.cc source/base/input_file.cc
              source/base/exceptions.cc source/input/input_parameters.cc
              source/reliability/reliability_analysis_parameters.cc source/reliability/limit_state.cc
              source/reliability/random_parameters.cc source/reliability/distribution.cc
              source/reliability/nataf.cc source/dynamics/model_parameter.cc
              source/dynamics/realization.cc
              source/excitation/records.cc source/excitation/ground_motion.cc
              source/excitation/record_suite.cc
              source/excitation/excitation.cc
              source/hazard/catalogue.cc source/hazard/pounding_hazard.cc
              source/hazard/site_hazard.cc source/mesh/gmsh_check.cc source/mesh/line_mesh.cc
              source/model/mesh_building_3d.cc)
harnesses=()
for target in $all_targets; do harnesses+=("tests/fuzz/fuzz_$target.cc"); done
objects=()
# The newest header: an object older than it may hold an old layout of a
# struct (an object compiled before a member was added overflowed the
# stack of the InputParameters it built, a false finding), so every object
# is compiled again when any header changed.
newest_header=$( (ls -t "$src"/include/poundfe/*/*.h "$src"/tests/fuzz/*.h || true) | head -1)
for file in $(printf '%s\n' "${instrumented[@]}" | sort -u) "${harnesses[@]}"; do
  object=$work/objects/$(echo "$file" | tr / _).o
  if [ ! -e "$object" ] || [ "$src/$file" -nt "$object" ] || [ "$newest_header" -nt "$object" ]; then
    rm -f "$object"
    echo "clang: $file"
    # shellcheck disable=SC2086
    nice -n 10 "$cxx" -std=c++17 -O1 -gline-tables-only -fsanitize=fuzzer-no-link,$sanitizers $flags \
      -I"$src/tests/fuzz" -DPOUNDFE_SOURCE_DIR="\"$src\"" -c "$src/$file" -o "$object"
  fi
  case $file in tests/fuzz/*) ;; *) objects+=("$object") ;; esac
done
# the program module's link line (libraries of deal.II and its dependencies)
libraries=$(sed -e 's/^[^ ]* //' -e 's#CMakeFiles/poundfe_program.dir/source/program.cc.o##' \
                -e 's#-o poundfe-program.so##' -e 's#\(^\| \)-shared\( \|$\)# #' \
                -e "s#\(^\| \)\(libpoundfe_[a-z]*\.a\)#\1$build/\2#g" \
                -e 's#CMakeFiles/poundfe_program.dir/revision.cc.o##' \
                "$build/CMakeFiles/poundfe_program.dir/link.txt")
for target in $targets; do
  binary=$work/fuzz_$target
  object=$work/objects/tests_fuzz_fuzz_$target.cc.o
  if [ ! -e "$binary" ] ||
     [ -n "$( (find "${objects[@]}" "$object" "$build/libpoundfe_core.a" -newer "$binary" || true) | head -1)" ]; then
    echo "link: fuzz_$target"
    # shellcheck disable=SC2086
    nice -n 10 "$cxx" -fsanitize=fuzzer,$sanitizers "${muldefs[@]}" "$object" "${objects[@]}" $libraries -o "$binary" 2>&1 |
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
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
fork=${FUZZ_FORK:+-fork=$FUZZ_FORK}
# The largest input: a bound on an execution's time where the input sets
# the work (a random-parameter line, a force table, a mesh). A mesh's checks
# are of markers, counts, tags and node pairs, which a few dozen nodes
# exercise (4,096 bytes); the large counts are cli/mesh-check's cases. At
# 40,000 bytes the mesh target ran 97 executions/s, at 4,096 about 1,400.
max_length() {
  case $1 in
    random_parameters | forces) echo 2048 ;;
    mesh | mesh_building) echo 4096 ;;
    *) echo 40000 ;;
  esac
}
status=0
for target in $targets; do
  kept=$src/tests/fuzz/corpus/$target
  seeds=$src/tests/fuzz/seeds-$target
  [ "$target" = parameters ] && seeds=$work/seeds-parameters
  mkdir -p "$kept" "$work/corpus-$target"
  inputs=("$kept")
  [ -d "$seeds" ] && inputs+=("$seeds")
  options=(-max_len="$(max_length "$target")" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1)
  dictionary=$src/tests/fuzz/${target%_building}.dict # the mesh targets share one
  [ -e "$dictionary" ] && options+=(-dict="$dictionary")
  if [ "${FUZZ_REPLAY:-0}" = 1 ]; then
    echo "fuzz_$target: its kept corpus once"
    (cd "$work" && ./fuzz_$target -runs=0 "${options[@]}" "$kept") > "$work/fuzz_$target.log" 2>&1 || status=1
  else
    echo "fuzz_$target: $runs executions or $max_time s"
    # shellcheck disable=SC2086
    (cd "$work" && nice -n 10 ./fuzz_$target -runs="$runs" -max_total_time="$max_time" \
       "${options[@]}" $fork "corpus-$target" "${inputs[@]}") > "$work/fuzz_$target.log" 2>&1 || status=1
  fi
  grep -E "^Done|stat::number_of_executed_units|stat::average_exec_per_sec|ERROR|SUMMARY|runtime error|crash-|timeout-|oom-|INFO: fuzzed for|INFO: exiting|not an InputError" \
    "$work/fuzz_$target.log" || true
  [ -n "$fork" ] && { grep -E "^#[0-9]+: cov" "$work/fuzz_$target.log" | tail -1 || true; }
  if [ "${FUZZ_MERGE:-0}" = 1 ] && [ "${FUZZ_REPLAY:-0}" != 1 ]; then
    rm -rf "$work/merged-$target" && mkdir "$work/merged-$target"
    (cd "$work" && ./fuzz_$target -merge=1 "${options[@]}" "merged-$target" "$kept" "corpus-$target") \
      > "$work/merge_$target.log" 2>&1 || { echo "merge of $target failed: $work/merge_$target.log"; status=1; continue; }
    rm -rf "$kept" && mv "$work/merged-$target" "$kept"
    echo "corpus/$target: $(ls "$kept" | wc -l) inputs, $(du -sk "$kept" | cut -f1) KiB"
  fi
done
exit $status
