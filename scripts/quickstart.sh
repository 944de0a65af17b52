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
#   clang      everything built by clang with -Werror (B2B_WERROR), then the
#              Check suites (build-clang/; gfortran stays the Fortran compiler)
#   memcheck   the library's suites (Check and Fortran) under valgrind
#              memcheck (RelWithDebInfo build in build-memcheck/; valgrind)
#   conly      the C library alone (build-pkg-conly/): no Fortran compiler,
#              Check or LAPACK as far as CMake knows; builds, installs, and
#              the README's C consumer commands work against the install
#   static     BUILD_SHARED_LIBS=OFF (build-pkg-static/): a static libb2b
#              installs, and the consumer and README-snippet tests link it
#   doc        the API reference by Doxygen, warnings as errors (in conly's
#              build-pkg-conly/; doxygen)
#   fuzz       the libFuzzer targets (tests/fuzz, clang, ASan+UBSan) for a
#              bounded time each (scripts/fuzz.sh short)
# It first installs the Debian packages it needs if any is missing (with sudo
# when not run as root), so it works as is on a fresh Debian 12 machine.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
  demo | study | test | sanitize | abi | tsan | clang | memcheck | conly | static | doc | fuzz) ;;
  *)
    echo "usage: $0 demo|study|test|sanitize|abi|tsan|clang|memcheck|conly|static|doc|fuzz" >&2
    exit 2
    ;;
esac

packages=(cmake make g++ gfortran pkg-config check liblapack-dev libboost-dev)
case "$mode" in
  abi) packages+=(abigail-tools) ;;
  tsan) packages+=(clang libomp-14-dev libclang-rt-14-dev) ;;
  clang) packages+=(clang) ;;
  memcheck) packages+=(valgrind) ;;
  doc) packages+=(doxygen) ;;
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
    # The trade table (16 solves of the demo host, every path of which the
    # scene tests take) runs in the test step only.
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -E '^demo_trade_table_short$'
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
    # What only clang proves: everything compiles with -Werror, and the
    # library it compiled passes the Check suites (the demo host, the
    # examples and the packaging tests run in the test and sanitize steps).
    CC=clang CXX=clang++ cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=Release -DB2B_WERROR=ON
    cmake --build build-clang -j "$jobs"
    ctest --test-dir build-clang --output-on-failure -j "$jobs" -L check
    ;;
  memcheck)
    # The test programs under valgrind; any error or definitely/possibly
    # lost block makes one exit 1, i.e. fail (tests/memcheck.supp: what is
    # suppressed, and why). CK_FORK=no: Check runs the tests in the process
    # valgrind watches. Not run under valgrind:
    #  - consumer_install, the abi tests and the docs tests (readme_snippets,
    #    cited_paths): they run cmake, compilers, nm, readelf, abidiff and
    #    shell scripts, not b2b code (the snippets' few calls are the suites');
    #  - fortran_stop_without_ierr*: they end in the module's error stop by
    #    design, so the message it was building is reported as lost, and
    #    they pass by a non-zero exit (WILL_FAIL) anyway;
    #  - demo_trade_table_short (16 solves of the demo host) and
    #    demo_contact_tangent_many_contacts (finite differences of the host's
    #    500-equation assembly, two assemblies per column): 20 to 30 min each
    #    under valgrind; every library path they take is in the scene tests,
    #    which do run here, and they run under ASan+UBSan;
    #  - check_model_hostile: it limits the process's address space to test
    #    out-of-memory paths, and under CK_FORK=no (one process for all its
    #    tests) the limits outlive their tests while valgrind's own
    #    allocator runs under them; its 10^5-group and 10^5-contact scenes
    #    take minutes here. It runs under ASan+UBSan (the limits skipped
    #    there) and in every other mode.
    cmake -S . -B build-memcheck -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DMEMORYCHECK_COMMAND=$(command -v valgrind)" \
      "-DMEMORYCHECK_SUPPRESSIONS_FILE=$PWD/tests/memcheck.supp" \
      "-DMEMORYCHECK_COMMAND_OPTIONS=--error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,possible --show-leak-kinds=definite,possible --num-callers=30"
    cmake --build build-memcheck -j "$jobs"
    # Only the library's suites (labels check and fortran): the demo host's
    # scenes and the examples are the library under a host, which ASan and
    # UBSan cover in the sanitize step; under valgrind they took most of
    # this step's time.
    CK_FORK=no ctest --test-dir build-memcheck --output-on-failure -j "$jobs" -T memcheck \
      -L 'check|fortran' -E 'stop_without_ierr|^check_model_hostile$'
    ;;
  conly)
    # The C library as a packager without a Fortran compiler, Check or LAPACK
    # builds it: Fortran is never enabled, the tests (the only users of
    # Check) are off, and LAPACK is disabled, so the examples that need it
    # are left out. The cache shows that CMake looked for none of the three.
    dir=build-pkg-conly
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_FORTRAN=OFF \
      -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_LAPACK=ON
    if grep -E '^(CMAKE_Fortran_COMPILER|pkgcfg_lib_CHECK_|LAPACK_|BLAS_)' "$dir/CMakeCache.txt"; then
      echo "quickstart conly: CMake looked for Fortran, Check or LAPACK (cache entries above)" >&2
      exit 1
    fi
    cmake --build "$dir" -j "$jobs"
    # ctest has no tests here (BUILD_TESTING=OFF), so the consumer test runs
    # directly: the README's install and C consumer commands (its Fortran
    # ones are skipped, and no Fortran file may be installed).
    cache() { sed -n "s/^$1:[A-Z]*=//p" "$dir/CMakeCache.txt"; }
    sh tests/consumer/run_consumer_test.sh "--cmake=$(command -v cmake)" "--build-dir=$dir" \
      --readme=README.md "--work-dir=$PWD/$dir/consumer" --source-dir=tests/consumer \
      "--libdir=$(cache CMAKE_INSTALL_LIBDIR)" "--generator=$(cache CMAKE_GENERATOR)" \
      "--c-compiler=$(cache CMAKE_C_COMPILER)" --fortran-compiler= --shared=ON \
      "--pkg-config=$(command -v pkg-config)"
    ;;
  static)
    # What only a static libb2b proves: it installs, and hosts link it
    # through the CMake package and pkg-config (consumer_install, C and
    # Fortran; consumer_fortran_i8) and the README's snippets build and run
    # against it (readme_snippets). The suites' code is the same as in the
    # test step's shared build; only the libraries are built here.
    cmake -S . -B build-pkg-static -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF
    cmake --build build-pkg-static -j "$jobs" --target b2b b2b_fortran
    ctest --test-dir build-pkg-static --output-on-failure -j "$jobs" -L 'consumer|docs'
    ;;
  fuzz)
    # The libFuzzer targets of tests/fuzz for a bounded time each, on their
    # seed corpora and the reproducers of every defect found (clang, ASan +
    # UBSan; scripts/fuzz.sh installs what it needs; FUZZ_SECONDS per target,
    # default 60). The long campaign: scripts/fuzz.sh long.
    scripts/fuzz.sh short
    ;;
  doc)
    # The API reference of the C headers (cmake/B2BDoc.cmake); any Doxygen
    # warning fails the target. Nothing is compiled: a C-only configure
    # (for the generated b2b_version.h) and Doxygen.
    # The conly step's C-only build directory, configured (again, now that
    # Doxygen is there) with the same options.
    dir=build-pkg-conly
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_FORTRAN=OFF \
      -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_LAPACK=ON
    cmake --build "$dir" --target doc
    echo "quickstart doc: $PWD/$dir/doc/api/html/index.html"
    ;;
esac
