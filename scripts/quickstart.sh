#!/usr/bin/env bash
# Builds b2b and runs one of:
#   demo       the demo host (examples/demo): every scene in
#              examples/demo/scenes/ with its check, then the short trade
#              table (Release build in build/; exits 1 if a scene fails)
#   study      the curve study (the main program for now): accuracy and cost
#              of every curve kind
#   test       the whole test suite through ctest (Release build in build/)
#   sanitize   the test suite built with AddressSanitizer and
#              UndefinedBehaviorSanitizer, optimised (build-sanitize/)
# and the further CI checks (.ci/run runs them, two at a time; each step
# builds only the targets it runs, and a step that uses another's build
# directory waits for it):
#   abi        the ABI gate: libb2b and libb2b_fortran against their abidw
#              baselines in tests/abi/ (Debug build in build-abi/;
#              abigail-tools)
#   memcheck   the library's suites (Check and Fortran) under valgrind
#              memcheck, the slowest in their quick mode (the test step's
#              Release build in build/; valgrind)
#   tsan       the thread tests check_pair_threads and check_model_threads
#              built by clang with ThreadSanitizer (build-tsan/)
#   clang      all C and C++ (the library with -Werror, its tests, the
#              examples) built by clang, then the Check suites (build-clang/)
#   conly      the C library alone (build-pkg-conly/): no Fortran compiler,
#              Check or LAPACK as far as CMake knows; builds, installs, and
#              the README's C consumer commands work against the install
#   doc        the API reference by Doxygen, warnings as errors (in conly's
#              build-pkg-conly/; doxygen)
#   static     BUILD_SHARED_LIBS=OFF (build-pkg-static/): a static libb2b
#              installs, and the consumer and README-snippet tests link it
#   fuzz       the libFuzzer targets (tests/fuzz, clang, ASan+UBSan) for a
#              bounded time each (scripts/fuzz.sh short)
#   mpi        the MPI/PETSc example host on 1 and 2 ranks
#              (scripts/mpi_example.sh quick, in build/; petsc-dev, Open MPI)
# and, not in CI:
#   coverage   checks by gcov that the tests memcheck and sanitize leave out,
#              and the quick modes, lose no library line that the tests they
#              run reach (build-coverage/)
# It first installs the Debian packages it needs if any is missing (with sudo
# when not run as root), so it works as is on a fresh Debian 12 machine.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
  demo | study | test | sanitize | abi | tsan | clang | memcheck | conly | static | doc | fuzz | mpi | coverage) ;;
  *)
    echo "usage: $0 demo|study|test|sanitize|abi|memcheck|tsan|clang|conly|doc|static|fuzz|mpi|coverage" >&2
    exit 2
    ;;
esac

packages=(cmake ninja-build make g++ gfortran pkg-config check liblapack-dev libboost-dev)
case "$mode" in
  abi) packages+=(abigail-tools) ;;
  memcheck) packages+=(valgrind) ;;
  tsan) packages+=(clang libomp-14-dev libclang-rt-14-dev) ;;
  clang) packages+=(clang) ;;
  doc) packages+=(doxygen) ;;
esac
scripts/install_packages.sh quickstart "${packages[@]}"

# Parallel jobs of the build and of ctest: one per core, unless B2B_JOBS
# says otherwise (.ci/run, which runs two steps at a time, gives each its
# share of the cores).
jobs=${B2B_JOBS:-$(nproc)}

case "$mode" in
  demo)
    scripts/configure_build.sh build -DCMAKE_BUILD_TYPE=Release
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
    scripts/configure_build.sh build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs" --target curve_study
    ./build/examples/curve_study
    ;;
  test)
    scripts/configure_build.sh build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs"
    # Label large (the MPI example's 10^5-segment network, minutes per run,
    # registered when MPI and PETSc are found): on demand only, as
    # scripts/mpi_example.sh (without "quick") runs it.
    ctest --test-dir build --output-on-failure -j "$jobs" -LE large
    ;;
  sanitize)
    # Optimised, not a -O0 Debug build: AddressSanitizer's and UBSan's checks
    # are inserted all the same (GCC's -fsanitize=object-size even needs
    # optimisation), while the demo host's scenes, most of this step's time,
    # run faster. Their time is in the host's instrumented Fortran, not in
    # the library: build-sanitize/examples/demo/b2b_demo on
    # tunnel_bar_linear.nml took 38 s of CPU at -O1, 28 s at -O2, and 28 s
    # too with the Release libb2b.so in its place (4.7 s all Release); three
    # quarters of it in the host's hyperdual arithmetic, which is therefore
    # not instrumented (examples/demo/CMakeLists.txt says why): 11 s. Debug
    # stays the build type, so no NDEBUG (the library has no assert(); the
    # tests may).
    # The library (C++) at -O2, the C and Fortran around it (the module's
    # wrappers, the tests, the hosts) at -O1, which is still optimised: the
    # tests spend their time in the library, and a build at -O1 for C and
    # Fortran took 40 s less CPU to build and 11 s more to test than one all
    # at -O2 (271 + 201 s against 311 + 190 s, one run each). -g1: line
    # tables, all a finding's stack trace needs (file, line, function). The
    # MPI example is not built: its tests do not run here (below).
    scripts/configure_build.sh build-sanitize -DCMAKE_BUILD_TYPE=Debug -DB2B_SANITIZE=ON \
      "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1" "-DCMAKE_CXX_FLAGS_DEBUG=-O2 -g1" \
      "-DCMAKE_Fortran_FLAGS_DEBUG=-O1 -g1" -DB2B_ENABLE_MPI_EXAMPLE=OFF
    cmake --build build-sanitize -j "$jobs"
    # Any finding aborts the test that made it (-fno-sanitize-recover), so a
    # green run means zero findings. Not run here: the MPI example (labels
    # mpi and large, registered when MPI and PETSc are found), since
    # LeakSanitizer reports Open MPI's own allocations (ompi_op_base_op_select
    # and its plugins) as leaks, so that mpi_slide_np1 fails here without a
    # finding in b2b; the mpi step runs the example.
    # And, since they run in the test step and every library path they take
    # runs here in other tests:
    #  - demo_trade_table_short: 16 solves of the demo host's scenes, which
    #    the scene tests run;
    #  - demo_contact_tangent_many_contacts: finite differences of the host's
    #    500-equation assembly, two assemblies per column (a sixth of this
    #    step's test time); the same assembly runs in demo_scene_many_contacts
    #    and the same program in the three other demo_contact_tangent_* tests,
    #    and it reaches no library line that they and the suites do not
    #    (scripts/quickstart.sh coverage checks it).
    # CK_FORK=no: a Check suite runs all its tests in its own process, not
    # each in a child process (check_model_hostile, whose tests need one
    # each, forks all the same: tst_run_suite_forked). A process under ASan
    # is slow to fork: check_curve_bad_input took 26.5 s in fork mode and
    # 0.15 s without; and a crash is reported by ASan with its stack, which
    # is more than Check's report from a child process says.
    CK_FORK=no ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -LE 'large|mpi' \
      -E '^(demo_trade_table_short|demo_contact_tangent_many_contacts)$'
    ;;
  abi)
    # Debug info is what abidiff compares types with; the baselines and how
    # to update them: tests/abi/README.md. A Debug build (-O0 -g): the
    # exported functions and types do not depend on the optimisation, and
    # the two libraries took 44 s of CPU to build at -O0 against 58 s at
    # RelWithDebInfo's -O2 (the gate passes against the same baselines).
    # Only the two libraries are built, no examples.
    scripts/configure_build.sh build-abi -DCMAKE_BUILD_TYPE=Debug -DB2B_ABI_CHECK=ON \
      -DB2B_BUILD_EXAMPLES=OFF
    cmake --build build-abi -j "$jobs" --target b2b b2b_fortran
    ctest --test-dir build-abi --output-on-failure -j "$jobs" -L abi
    ;;
  tsan)
    # clang with LLVM's OpenMP runtime and its Archer tool: TSan then sees
    # the synchronisation of OpenMP regions (tests/tsan/CMakeLists.txt sets
    # the run-time environment). Any report fails a thread suite (exit code
    # 66), and the race canary must be reported. setarch -R: without address
    # randomisation, since some TSan runtimes cannot map their shadow memory
    # under the larger mmap randomisation of recent kernels.
    CC=clang CXX=clang++ scripts/configure_build.sh build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DB2B_TSAN=ON -DB2B_BUILD_EXAMPLES=OFF
    cmake --build build-tsan -j "$jobs" --target check_pair_threads \
      check_model_threads tsan_omp_race_canary
    setarch "$(uname -m)" -R ctest --test-dir build-tsan --output-on-failure -L tsan
    ;;
  clang)
    # What only clang proves: all C and C++ of the project (the library with
    # -Werror, the tests and the examples) compiles, and the library it
    # compiled passes the Check suites (the demo host, the examples and the
    # packaging tests run in the test and sanitize steps). Fortran off: the
    # Fortran is gfortran's in every step, its module and host are built
    # and run in the others.
    CC=clang CXX=clang++ scripts/configure_build.sh build-clang -DCMAKE_BUILD_TYPE=Release -DB2B_WERROR=ON \
      -DB2B_ENABLE_FORTRAN=OFF
    cmake --build build-clang -j "$jobs"
    # CK_FORK=no as in sanitize: the same verdicts, without a child process
    # for each test (every suite passes so; check_model_hostile forks anyway).
    CK_FORK=no ctest --test-dir build-clang --output-on-failure -j "$jobs" -L check
    ;;
  memcheck)
    # The library's suites under valgrind; any error or definitely/possibly
    # lost block makes one exit 1, i.e. fail (tests/memcheck.supp: what is
    # suppressed, and why). CK_FORK=no: Check runs the tests in the process
    # valgrind watches. In the test step's Release build (build/, configured
    # and built here when the step runs alone; in CI it has run, and the
    # build is up to date): the programs valgrind runs are the ones the test
    # step ran, and no third build of the suites is made for it (a
    # RelWithDebInfo one took about 45 s of CPU). Without debug information
    # a report names functions, not lines; `-DCMAKE_BUILD_TYPE=RelWithDebInfo`
    # in a build directory of one's own gives the lines.
    scripts/configure_build.sh build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs"
    # Only the library's suites (label memcheck: of the labels check and
    # fortran): the demo host's scenes and the examples are the library under
    # a host, which ASan and UBSan cover in the sanitize step (under valgrind
    # they took most of this step's time); the consumer, abi and docs tests
    # run cmake, compilers, nm, readelf, abidiff and shell scripts, not b2b
    # code. Of the check and fortran tests, not run under valgrind:
    #  - ten Check suites that valgrind makes slow (finite differences and
    #    sweeps: thousands of evaluations of the same paths) and that reach
    #    no line of the library that the memcheck suites do not reach as well
    #    (tests/CMakeLists.txt, B2B_MEMCHECK_SKIP; scripts/quickstart.sh
    #    coverage checks it); they run in full in every other step;
    #  - fortran_stop_without_ierr*: they end in the module's error stop by
    #    design, so the message it was building is reported as lost, and
    #    they pass by a non-zero exit (WILL_FAIL) anyway;
    #  - check_model_hostile: it limits the process's address space to test
    #    out-of-memory paths, while valgrind's own allocator runs under the
    #    limits; its 10^5-group and 10^5-contact scenes take minutes here.
    #    It runs under ASan+UBSan (the limits skipped there) and in every
    #    other mode.
    # B2B_TEST_QUICK=1: the suites labelled quick (tests/CMakeLists.txt,
    # B2B_QUICK_SUITES) run the same checks on fewer configurations, which
    # every other step runs in full: check_model_threads' 500 fibres in a
    # cube of 12, not 5 (a ninth of the pairs); check_model_state's networks
    # of 20 fibres, not 40; check_model_line's all-angle sweep in steps of
    # 0.3 degrees, not 0.1; check_model_partition's slide of each kind on 2
    # or on 3 ranks, not both; half of the random finite-difference
    # configurations of check_pair_ends and check_pair_line; every third
    # angle per kind pair in check_pair_line_extremes. Every library line
    # the full suites reach, memcheck still reaches (scripts/quickstart.sh
    # coverage checks it; what two quick runs leave to the other suites is a
    # random network's rare events, such as a pair found parallel, which a
    # smaller network meets elsewhere or not at all). With CK_FORK=no,
    # Check's record of every passed assertion is skipped as well
    # (tests/check/test_support.h): a write(2) each, which was most of the
    # bad-input suites' time under valgrind. The tests of this step, one run
    # each on the same library (doc/verification.md, CI): 507 s of CPU and
    # 345 s of wall time with the tests before the quick modes, 113.5 s and
    # 57.6 s with them.
    # valgrind's options through ctest's --overwrite, not build/'s cache.
    CK_FORK=no B2B_TEST_QUICK=1 ctest --test-dir build --output-on-failure -j "$jobs" \
      -T memcheck -L memcheck \
      --overwrite "MemoryCheckCommand=$(command -v valgrind)" \
      --overwrite "MemoryCheckSuppressionFile=$PWD/tests/memcheck.supp" \
      --overwrite "MemoryCheckCommandOptions=--error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,possible --show-leak-kinds=definite,possible --num-callers=30"
    ;;
  coverage)
    # Not a CI step: it checks what memcheck and sanitize leave out. Each
    # check and fortran test, and the demo tests that stand for
    # demo_contact_tangent_many_contacts, runs alone in a gcc --coverage
    # build (build-coverage/); gcov lists the lines of the library's sources
    # (src/, include/) it reached. The suites with a quick mode (label quick,
    # tests/CMakeLists.txt: B2B_QUICK_SUITES) run a second time as memcheck
    # runs them, with B2B_TEST_QUICK=1. Then, with "the memcheck tests as
    # memcheck runs them" the memcheck-labelled tests, the quick ones' quick
    # runs (but the stop_without_ierr programs and check_model_hostile,
    # which memcheck leaves out for other reasons):
    #  - each line a quick suite's full run reaches, its quick run or another
    #    of the memcheck tests as memcheck runs them must reach, so memcheck
    #    reaches every line it reached before the quick modes (the lines a
    #    quick run leaves to the others are counted and printed: a random
    #    network's rare events, such as a pair found parallel, are reached in
    #    one run by chance and not in a smaller one);
    #  - every test without the memcheck label (but those programs) must
    #    reach no line that the memcheck tests as memcheck runs them do not;
    #  - demo_contact_tangent_many_contacts none that the others do not.
    # Exits 1, naming the lines (the first 20 of each test), if one does not
    # hold.
    dir=build-coverage
    scripts/configure_build.sh "$dir" -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g --coverage" \
      -DCMAKE_SHARED_LINKER_FLAGS=--coverage -DCMAKE_EXE_LINKER_FLAGS=--coverage
    cmake --build "$dir" -j "$jobs"
    names() { ctest --test-dir "$dir" -N "$@" | sed -n 's/^ *Test *#[0-9]*: //p'; }
    lines=$dir/coverage-lines       # a file per test: its full run's lines
    quick=$dir/coverage-lines-quick # a file per quick suite: its quick run's
    rm -rf "$lines" "$quick"
    mkdir -p "$lines" "$quick"
    # reach <test> <file> [VAR=value ...]: runs the test alone (with the
    # variables set) and writes the library lines it reached to <file>.
    reach() {
      local t=$1 out=$2
      shift 2
      find "$dir" -name '*.gcda' -delete
      env "$@" ctest --test-dir "$dir" -R "^$t\$" >/dev/null ||
        { echo "quickstart coverage: $t failed${*:+ ($*)}" >&2; exit 1; }
      # gcov -t: the annotated sources on stdout, each after a line
      # "-: 0:Source:<path>"; an executed line starts with its count.
      # (gcov writes its .gcov files into the directory it runs in.)
      find "$PWD/$dir" -name '*.gcda' | while read -r f; do
        (cd "$lines" && gcov -t -o "$(dirname "$f")" "$f" 2>/dev/null) || true
      done | awk -v root="$PWD/" '
        /^ *-: *0:Source:/ { sub(/^ *-: *0:Source:/, ""); file = $0; next }
        /^ *[0-9]+\*?: *[0-9]+:/ && (index(file, root "src/") == 1 || index(file, root "include/") == 1) {
          split($0, a, ":"); gsub(/ /, "", a[2]); print substr(file, length(root) + 1) ":" a[2] }' |
        sort -u >"$out"
      echo "quickstart coverage: $t${*:+ ($*)} reaches $(wc -l <"$out") lines of src/ and include/"
    }
    demo=(demo_scene_many_contacts demo_contact_tangent_sliding_friction
      demo_contact_tangent_friction_pull demo_contact_tangent_crossed_30_inside
      demo_contact_tangent_many_contacts)
    for t in $(names -L 'check|fortran' -E 'stop_without_ierr|^check_model_hostile$') "${demo[@]}"; do
      reach "$t" "$lines/$t"
    done
    mapfile -t quick_suites < <(names -L quick)
    for t in "${quick_suites[@]}"; do
      reach "$t" "$quick/$t" B2B_TEST_QUICK=1
    done
    # Lines of the tests in the first file list not in the second's union.
    missing() { comm -23 <(cat "${@:1:1}" | sort -u) <(cat "${@:2}" | sort -u); }
    failed=0
    # The memcheck tests' lines as memcheck reaches them.
    kept=()
    while read -r t; do
      if [ -f "$quick/$t" ]; then kept+=("$quick/$t"); else kept+=("$lines/$t"); fi
    done < <(names -L memcheck -E 'stop_without_ierr|^check_model_hostile$')
    for t in "${quick_suites[@]}"; do
      m=$(missing "$lines/$t" "${kept[@]}")
      if [ -n "$m" ]; then
        echo "quickstart coverage: $t in its quick mode (B2B_TEST_QUICK=1) misses lines its full run reaches and no memcheck test reaches as memcheck runs it:"
        echo "$m" | head -20
        failed=1
      else
        echo "quickstart coverage: $t in its quick mode leaves $(missing "$lines/$t" "$quick/$t" | wc -l) of the $(wc -l <"$lines/$t") lines its full run reaches to the other memcheck tests (they reach them)"
      fi
    done
    for t in $(names -L 'check|fortran' -LE memcheck -E 'stop_without_ierr|^check_model_hostile$'); do
      m=$(missing "$lines/$t" "${kept[@]}")
      if [ -n "$m" ]; then
        echo "quickstart coverage: $t (not run by memcheck) reaches lines no memcheck test reaches:"
        echo "$m" | head -20
        failed=1
      fi
    done
    others=()
    for f in "$lines"/*; do [ "$f" = "$lines/demo_contact_tangent_many_contacts" ] || others+=("$f"); done
    m=$(missing "$lines/demo_contact_tangent_many_contacts" "${others[@]}")
    if [ -n "$m" ]; then
      echo "quickstart coverage: demo_contact_tangent_many_contacts (not run by sanitize) reaches lines the others do not:"
      echo "$m" | head -20
      failed=1
    fi
    ((failed == 0)) || exit 1
    echo "quickstart coverage: the memcheck tests as memcheck runs them (quick modes included) reach every line their full runs reach, and the tests memcheck and sanitize leave out reach no library line that the tests they run do not"
    ;;
  conly)
    # The C library as a packager without a Fortran compiler, Check or LAPACK
    # builds it: Fortran is never enabled, the tests (the only users of
    # Check) are off, and LAPACK is disabled, so the examples that need it
    # are left out. The cache shows that CMake looked for none of the three.
    dir=build-pkg-conly
    scripts/configure_build.sh "$dir" -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_FORTRAN=OFF \
      -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_LAPACK=ON
    if grep -E '^(CMAKE_Fortran_COMPILER|pkgcfg_lib_CHECK_|LAPACK_|BLAS_)' "$dir/CMakeCache.txt"; then
      echo "quickstart conly: CMake looked for Fortran, Check or LAPACK (cache entries above)" >&2
      exit 1
    fi
    # Only the library: the consumer test installs and uses nothing else (the
    # examples are built without Fortran in the clang step).
    cmake --build "$dir" -j "$jobs" --target b2b
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
    scripts/configure_build.sh build-pkg-static -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF
    cmake --build build-pkg-static -j "$jobs" --target b2b b2b_fortran
    # cited_paths (label docs) reads the sources only: the test step ran it.
    ctest --test-dir build-pkg-static --output-on-failure -j "$jobs" -L 'consumer|docs' \
      -E '^cited_paths$'
    ;;
  mpi)
    # The MPI/PETSc example host (examples/mpi, doc/distributed.md):
    # scripts/mpi_example.sh installs petsc-dev and Open MPI, switches the
    # example on in the test step's build/ (Release: its libb2b is built
    # already when test ran first, as in CI) and runs ctest -L mpi -LE
    # large: the host's element against finite differences, the slide and
    # the fibre network of 4800 segments on 1 and 2 ranks (block and COO
    # Jacobians), each pair of runs compared (the same contacts, every value
    # within 1e-10 relative). The 10^5-segment network (label large, about
    # five minutes on 1 and 2 ranks) is the bounded run's full form:
    # scripts/mpi_example.sh runs it.
    MPI_BUILD_DIR=build scripts/mpi_example.sh quick
    ;;
  fuzz)
    # The libFuzzer targets of tests/fuzz for a bounded time each, on their
    # seed corpora and the reproducers of every defect found (clang, ASan +
    # UBSan; scripts/fuzz.sh installs what it needs): 15 s per target
    # (FUZZ_SECONDS), one target per job (B2B_JOBS, by default a core;
    # FUZZ_PARALLEL), so 8 targets take four rounds on 2 cores, eight in CI
    # (one job a step): two CPU minutes of mutation, CI's share of a
    # 12-minute budget (issue 20). The seeds and reproducers are all
    # replayed first in any case; the long campaign that grows the corpus
    # and measures coverage is scripts/fuzz.sh long (15 minutes a target).
    scripts/fuzz.sh short
    ;;
  doc)
    # The API reference of the C headers (cmake/B2BDoc.cmake); any Doxygen
    # warning fails the target. Nothing is compiled: a C-only configure
    # (for the generated b2b_version.h) and Doxygen.
    # The conly step's C-only build directory, configured (again, now that
    # Doxygen is there) with the same options.
    dir=build-pkg-conly
    scripts/configure_build.sh "$dir" -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_FORTRAN=OFF \
      -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_LAPACK=ON
    cmake --build "$dir" --target doc
    echo "quickstart doc: $PWD/$dir/doc/api/html/index.html"
    ;;
esac
