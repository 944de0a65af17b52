# B2B_FUZZ, included by the top-level CMakeLists.txt before src/ so that the
# library is instrumented as well as the targets: libFuzzer needs coverage
# feedback from libb2b's code, not just from the harnesses. The targets
# themselves are in tests/fuzz/CMakeLists.txt; scripts/fuzz.sh drives them.
if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang" OR NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "B2B_FUZZ needs clang for C and C++ (libFuzzer ships with clang; "
    "Debian: clang libclang-rt-14-dev), e.g. CC=clang CXX=clang++ cmake -DB2B_FUZZ=ON ...; "
    "the C compiler is ${CMAKE_C_COMPILER_ID}, the C++ compiler ${CMAKE_CXX_COMPILER_ID}")
endif()
if(B2B_SANITIZE OR B2B_TSAN)
  message(FATAL_ERROR "B2B_FUZZ brings its own AddressSanitizer and UndefinedBehaviorSanitizer: "
    "do not combine it with B2B_SANITIZE or B2B_TSAN")
endif()

option(B2B_FUZZ_COVERAGE
  "With B2B_FUZZ: instrument for clang's source-based coverage instead of the sanitizers (to measure what a corpus reaches)"
  OFF)

if(B2B_FUZZ_COVERAGE)
  # fuzzer-no-link keeps libFuzzer's own instrumentation, so that the targets
  # read a corpus exactly as in the campaign; only the sanitizers are left
  # out (they would not change which lines run, only slow it down).
  add_compile_options(
    "$<$<COMPILE_LANGUAGE:C,CXX>:-fprofile-instr-generate;-fcoverage-mapping;-fsanitize=fuzzer-no-link>")
  add_link_options("$<$<LINK_LANGUAGE:C,CXX>:-fprofile-instr-generate>")
else()
  # -fno-sanitize-recover: a UBSan finding aborts, so libFuzzer records it as
  # a crash with its input instead of printing and going on.
  add_compile_options(
    "$<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=fuzzer-no-link,address,undefined;-fno-omit-frame-pointer;-fno-sanitize-recover=all>")
  add_link_options("$<$<LINK_LANGUAGE:C,CXX>:-fsanitize=address,undefined>")
endif()
