#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang, ASan+UBSan, build-fuzz/)
# and runs them one after the other, on the seed corpora of
# tests/fuzz/corpus/<target>/ (which also hold the reproducers of every
# defect found: each is run first, so a regression fails at once):
#   short            each target for 15 s (FUZZ_SECONDS overrides), as many
#                    at a time as there are cores, or B2B_JOBS
#                    (FUZZ_PARALLEL overrides both):
#                    the CI step; exits 1 if any target crashes or breaks the
#                    contract (the input is kept in build-fuzz/artifacts/)
#   long [seconds]   the long campaign, each target for `seconds` (default
#                    900), growing its corpus in build-fuzz/corpus/long/
#                    (kept between campaigns); then replays that corpus in a
#                    build for clang's source-based coverage (build-fuzz-cov/)
#                    and prints per target: executions, time, corpus size and
#                    the line coverage of the library's sources (src/) and of
#                    the contact model's (src/model/)
# FUZZ_TARGETS="fuzz_model_restore fuzz_model_calls" scripts/fuzz.sh ...
# runs only those targets (default: all of them).
# It first installs the Debian packages it needs if any is missing (with sudo
# when not run as root), as scripts/quickstart.sh does.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
  short) seconds=${FUZZ_SECONDS:-15} ;;
  long) seconds=${2:-900} ;;
  *)
    echo "usage: $0 short | long [seconds per target]" >&2
    exit 2
    ;;
esac

# libFuzzer and the sanitizer runtimes come with clang's runtime package;
# llvm-14 has llvm-profdata-14 and llvm-cov-14. gfortran and LAPACK because
# the project's CMake configuration needs them (the targets do not).
packages=(cmake ninja-build make g++ gfortran pkg-config liblapack-dev libboost-dev clang libclang-rt-14-dev)
[ "$mode" = long ] && packages+=(llvm-14)
scripts/install_packages.sh fuzz "${packages[@]}"

# Every target of tests/fuzz/CMakeLists.txt (B2B_FUZZ_TARGETS), read from
# there so that a new target cannot be built and never run; each must have
# its corpus directory.
read -r -a all_targets <<<"$(sed -n '/^set(B2B_FUZZ_TARGETS/,/)/p' tests/fuzz/CMakeLists.txt |
  sed 's/^set(B2B_FUZZ_TARGETS//; s/)//' | tr '\n' ' ')"
for t in "${all_targets[@]}"; do
  [ -d "tests/fuzz/corpus/$t" ] || {
    echo "fuzz: target $t has no corpus directory tests/fuzz/corpus/$t" >&2
    exit 1
  }
done
read -r -a targets <<<"${FUZZ_TARGETS:-${all_targets[*]}}"
jobs=${B2B_JOBS:-$(nproc)}   # as scripts/quickstart.sh: one per core unless B2B_JOBS says
# OpenMP off: the model's threads would only make runs less reproducible (a
# fuzz model stays far below the size at which it starts threads).
configure=(-DB2B_FUZZ=ON -DBUILD_TESTING=OFF -DB2B_BUILD_EXAMPLES=OFF -DB2B_ENABLE_OPENMP=OFF)
CC=clang CXX=clang++ scripts/configure_build.sh build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo "${configure[@]}"
cmake --build build-fuzz -j "$jobs" --target fuzz_targets

# Any sanitizer finding aborts (the build has -fno-sanitize-recover), and so
# does a broken contract (tests/fuzz/fuzz_contract.hpp): libFuzzer then writes
# the input to the artifact directory and exits non-zero.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

logs=build-fuzz/logs/$mode
mkdir -p "$logs"
declare -A execs times
failed=()
# One target's run: its verdict, time and executions into $logs/$t.*, read
# back below (the runs go on in parallel in short mode).
run_target() {
  local t=$1 corpus=build-fuzz/corpus/$mode/$1 artifacts=build-fuzz/artifacts/$1/ start=$SECONDS
  mkdir -p "$corpus" "$artifacts"
  # A short run starts from the seeds alone, so that CI results do not
  # depend on what an earlier run left behind.
  [ "$mode" = short ] && rm -rf "${corpus:?}"/*
  echo "fuzz: $t for $seconds s (log: $logs/$t.log)"
  # -timeout: one input (a handful of calls) may take at most 60 s; the
  # targets bound each call's CPU time far more tightly themselves.
  # -rss_limit_mb: ASan's quarantine alone takes a few hundred MB.
  if ./build-fuzz/tests/fuzz/"$t" -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" "tests/fuzz/corpus/$t" \
    >"$logs/$t.log" 2>&1; then
    echo ok >"$logs/$t.verdict"
  else
    echo "FAILED (see $logs/$t.log and $artifacts)" >"$logs/$t.verdict"
  fi
  echo $((SECONDS - start)) >"$logs/$t.time"
}
# Short runs (CI) go FUZZ_PARALLEL at a time, by default one per job: a
# target is single-threaded, and max_total_time is wall time. The long
# campaign runs them one after the other unless FUZZ_PARALLEL says otherwise.
if [ "$mode" = short ]; then parallel=${FUZZ_PARALLEL:-$jobs}; else parallel=${FUZZ_PARALLEL:-1}; fi
running=0
for t in "${targets[@]}"; do
  rm -f "$logs/$t.verdict" "$logs/$t.time"
  run_target "$t" &
  running=$((running + 1))
  if ((running >= parallel)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true
for t in "${targets[@]}"; do
  verdict=$(cat "$logs/$t.verdict" 2>/dev/null || echo "FAILED (no verdict: the run did not finish)")
  if [ "$verdict" != ok ]; then
    failed+=("$t")
    grep -E "CONTRACT VIOLATED|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error|^  |Test unit written" \
      "$logs/$t.log" | head -20 || true
  fi
  times[$t]=$(cat "$logs/$t.time" 2>/dev/null || echo "?")
  execs[$t]=$(sed -n 's/^stat::number_of_executed_units: *//p' "$logs/$t.log" | tail -1)
  echo "fuzz: $t: ${execs[$t]:-?} executions in ${times[$t]} s: $verdict"
done

if [ "$mode" = long ] && ((${#failed[@]} == 0)); then
  # Line coverage of src/ reached by each target's corpus (seeds and what the
  # campaign added), measured in a build without sanitizers.
  bin=/usr/lib/llvm-14/bin
  profdata=$(command -v llvm-profdata-14 || command -v "$bin/llvm-profdata" || command -v llvm-profdata)
  cov=$(command -v llvm-cov-14 || command -v "$bin/llvm-cov" || command -v llvm-cov)
  CC=clang CXX=clang++ scripts/configure_build.sh build-fuzz-cov -DCMAKE_BUILD_TYPE=Debug "${configure[@]}" \
    -DB2B_FUZZ_COVERAGE=ON
  cmake --build build-fuzz-cov -j "$jobs" --target fuzz_targets
  prof=build-fuzz-cov/profiles
  rm -rf "$prof"
  mkdir -p "$prof"
  declare -A lines model_lines corpus_size
  # llvm-cov's TOTAL row: regions (3 columns), functions (3), lines: count,
  # missed, percentage; then branches (3).
  total='/^TOTAL/ {printf "%d of %d lines (%s); branches %d of %d (%s)", $8 - $9, $8, $10, $11 - $12, $11, $13}'

  for t in "${targets[@]}"; do
    # %m: one raw profile per instrumented module (the target and libb2b.so).
    LLVM_PROFILE_FILE="$prof/$t-%m.profraw" ./build-fuzz-cov/tests/fuzz/"$t" -runs=0 \
      "build-fuzz/corpus/long/$t" "tests/fuzz/corpus/$t" >"$logs/$t.coverage.log" 2>&1
    "$profdata" merge -sparse "$prof/$t"-*.profraw -o "$prof/$t.profdata"
    lines[$t]=$("$cov" report build-fuzz-cov/src/libb2b.so -instr-profile="$prof/$t.profdata" \
      "$PWD/src" | awk "$total")
    model_lines[$t]=$("$cov" report build-fuzz-cov/src/libb2b.so -instr-profile="$prof/$t.profdata" \
      "$PWD/src/model" | awk "$total")
    corpus_size[$t]=$(find "build-fuzz/corpus/long/$t" "tests/fuzz/corpus/$t" -type f | wc -l)
  done
  "$profdata" merge -sparse "$prof"/*.profraw -o "$prof/all.profdata"
  all=$("$cov" report build-fuzz-cov/src/libb2b.so -instr-profile="$prof/all.profdata" "$PWD/src" |
    awk "$total")
  echo
  echo "fuzz: long campaign on $(date -u +%Y-%m-%d), $(nproc) cores ($(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1))"
  printf '| %s | %s | %s | %s | %s | %s |\n' target executions "time [s]" "corpus files" \
    "coverage of src/ by the corpus" "of src/model/"
  printf '|---|---:|---:|---:|---|---|\n'
  for t in "${targets[@]}"; do
    printf '| %s | %s | %s | %s | %s | %s |\n' "$t" "${execs[$t]:-?}" "${times[$t]}" \
      "${corpus_size[$t]}" "${lines[$t]}" "${model_lines[$t]}"
  done
  all_model=$("$cov" report build-fuzz-cov/src/libb2b.so -instr-profile="$prof/all.profdata" \
    "$PWD/src/model" | awk "$total")
  echo "all targets together: $all; src/model/: $all_model"
  echo "(per-file report: $cov report build-fuzz-cov/src/libb2b.so -instr-profile=$prof/all.profdata $PWD/src)"
fi

if ((${#failed[@]})); then
  echo "fuzz $mode: ${#failed[@]} target(s) failed: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz $mode: all targets passed"
