#!/usr/bin/env bash
# Builds b2b and runs one of:
#   demo       the demo host (examples/demo): every scene in
#              examples/demo/scenes/ with its check, then the short trade
#              table (Release build in build/; exits 1 if a scene fails)
#   study      the curve study (the main program for now): accuracy and cost
#              of every curve kind
#   test       the whole test suite through ctest (Release build in build/)
#   sanitize   the whole test suite built with AddressSanitizer and
#              UndefinedBehaviorSanitizer (Debug build in build-sanitize/)
# and the further CI checks (each in its own build directory):
#   abi        the ABI gate: libb2b and libb2b_fortran against their abidw
#              baselines in tests/abi/ (RelWithDebInfo build in build-abi/;
#              abigail-tools)
#   tsan       the thread tests check_pair_threads and check_model_threads
#              built by clang with ThreadSanitizer (build-tsan/)
#   clang      the library built by clang with -Werror (B2B_WERROR), then the
#              whole suite (build-clang/; gfortran stays the Fortran compiler)
#   memcheck   the suite under valgrind memcheck (RelWithDebInfo build in
#              build-memcheck/; valgrind)
# It first installs the Debian packages it needs if any is missing (with sudo
# when not run as root), so it works as is on a fresh Debian 12 machine.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
  demo | study | test | sanitize | abi | tsan | clang | memcheck) ;;
  *)
    echo "usage: $0 demo|study|test|sanitize|abi|tsan|clang|memcheck" >&2
    exit 2
    ;;
esac

packages=(cmake make g++ gfortran pkg-config check liblapack-dev libboost-dev)
case "$mode" in
  abi) packages+=(abigail-tools) ;;
  tsan) packages+=(clang libomp-14-dev libclang-rt-14-dev) ;;
  clang) packages+=(clang) ;;
  memcheck) packages+=(valgrind) ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "quickstart: installing missing Debian packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
case "$mode" in
  demo)
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs" --target b2b_demo
    # Each scene's full output goes to build/demo/<scene>.log; its check
    # summary and verdict are printed here.
    out=build/demo
    mkdir -p "$out"
    failed=()
    for scene in examples/demo/scenes/*.nml; do
      name=$(basename "$scene" .nml)
      if ./build/examples/demo/b2b_demo "$scene" "$out" >"$out/$name.log" 2>&1; then
        verdict=ok
      else
        verdict="FAILED (exit $?, see $out/$name.log)"
        failed+=("$name")
      fi
      grep -E "^$name: check|^  steps checked|^  straight segments|CHECK FAILED|error:" "$out/$name.log" || true
      echo "$name: $verdict"
    done
    ./build/examples/demo/b2b_demo --trade-table short examples/demo/scenes "$out"
    if ((${#failed[@]})); then
      echo "quickstart demo: ${#failed[@]} scene(s) failed: ${failed[*]}" >&2
      exit 1
    fi
    ;;
  study)
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs" --target curve_study
    ./build/examples/curve_study
    ;;
  test)
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs"
    ctest --test-dir build --output-on-failure -j "$jobs"
    ;;
  sanitize)
    cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DB2B_SANITIZE=ON
    cmake --build build-sanitize -j "$jobs"
    # Any finding aborts the test that made it (-fno-sanitize-recover), so a
    # green run means zero findings.
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
    ;;
  abi)
    # Debug info is what abidiff compares types with; the baselines and how
    # to update them: tests/abi/README.md.
    cmake -S . -B build-abi -DCMAKE_BUILD_TYPE=RelWithDebInfo -DB2B_ABI_CHECK=ON \
      -DB2B_BUILD_EXAMPLES=OFF
    cmake --build build-abi -j "$jobs" --target b2b b2b_fortran
    ctest --test-dir build-abi --output-on-failure -L abi
    ;;
  tsan)
    # clang with LLVM's OpenMP runtime and its Archer tool: TSan then sees
    # the synchronisation of OpenMP regions (tests/tsan/CMakeLists.txt sets
    # the run-time environment). Any report fails a thread suite (exit code
    # 66), and the race canary must be reported. setarch -R: without address
    # randomisation, since some TSan runtimes cannot map their shadow memory
    # under the larger mmap randomisation of recent kernels.
    CC=clang CXX=clang++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DB2B_TSAN=ON -DB2B_BUILD_EXAMPLES=OFF
    cmake --build build-tsan -j "$jobs" --target check_pair_threads \
      check_model_threads tsan_omp_race_canary
    setarch "$(uname -m)" -R ctest --test-dir build-tsan --output-on-failure -L tsan
    ;;
  clang)
    CC=clang CXX=clang++ cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=Release -DB2B_WERROR=ON
    cmake --build build-clang -j "$jobs"
    ctest --test-dir build-clang --output-on-failure -j "$jobs"
    ;;
  memcheck)
    # The test programs under valgrind; any error or definitely/possibly
    # lost block makes one exit 1, i.e. fail (tests/memcheck.supp: what is
    # suppressed, and why). CK_FORK=no: Check runs the tests in the process
    # valgrind watches. Not run under valgrind:
    #  - consumer_install and the abi tests: they run cmake, compilers, nm,
    #    readelf and abidiff, not b2b code;
    #  - fortran_stop_without_ierr*: they end in the module's error stop by
    #    design, so the message it was building is reported as lost, and
    #    they pass by a non-zero exit (WILL_FAIL) anyway;
    #  - check_curve_bad_input and check_pair_bad_input: 260 s and 630 s
    #    under valgrind (4 s and 5 s without), since Check writes a record
    #    to its temporary file for every passed assertion and these suites
    #    pass about 9 and 11 million of them in loops (one system call each,
    #    expensive under valgrind). They run under ASan+UBSan in the sanitize
    #    step; include them here once they assert less often;
    #  - demo_trade_table_short (16 solves of the demo host) and
    #    demo_contact_tangent_many_contacts (finite differences of the host's
    #    500-equation assembly, two assemblies per column): 20 to 30 min each
    #    under valgrind; every library path they take is in the scene tests,
    #    which do run here, and they run under ASan+UBSan.
    cmake -S . -B build-memcheck -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DMEMORYCHECK_COMMAND=$(command -v valgrind)" \
      "-DMEMORYCHECK_SUPPRESSIONS_FILE=$PWD/tests/memcheck.supp" \
      "-DMEMORYCHECK_COMMAND_OPTIONS=--error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,possible --show-leak-kinds=definite,possible --num-callers=30"
    cmake --build build-memcheck -j "$jobs"
    CK_FORK=no ctest --test-dir build-memcheck --output-on-failure -j "$jobs" -T memcheck \
      -LE 'consumer|abi' -E 'stop_without_ierr|^check_(curve|pair)_bad_input$|^demo_trade_table_short$|^demo_contact_tangent_many_contacts$'
    ;;
esac
