# ThreadSanitizer runs (B2B_TSAN=ON), included by tests/CMakeLists.txt (test
# properties belong to the directory that added the tests). The model's
# threads are OpenMP's, whose synchronisation TSan sees only through LLVM's
# OpenMP runtime and its Archer tool (GCC's libgomp is not instrumented, so
# every parallel region would be reported). The thread suites run with Archer
# loaded, and a canary with a deliberate race in an OpenMP region must be
# reported, so a clean run is evidence and not a blind setup.
set(_tsan_env
  # Reports from the uninstrumented OpenMP runtime itself are not ours;
  # Archer tells TSan what its synchronisation means.
  "TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1"
  # The threads run in the test process itself.
  "CK_FORK=no")

if(B2B_ENABLE_OPENMP)
  find_package(OpenMP COMPONENTS C)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang" OR NOT OpenMP_C_FOUND)
    message(FATAL_ERROR "B2B_TSAN needs clang with LLVM's OpenMP runtime and "
      "its Archer tool (Debian: clang libomp-14-dev libclang-rt-14-dev), e.g. "
      "CC=clang CXX=clang++ cmake -DB2B_TSAN=ON ...; or configure with "
      "-DB2B_ENABLE_OPENMP=OFF (the model's threads are then not tested)")
  endif()
  get_filename_component(_omp_dir "${OpenMP_omp_LIBRARY}" DIRECTORY)
  find_library(B2B_ARCHER_LIBRARY NAMES archer HINTS "${_omp_dir}")
  if(NOT B2B_ARCHER_LIBRARY)
    message(FATAL_ERROR "B2B_TSAN: LLVM's Archer tool (libarcher.so, Debian "
      "package libomp-14-dev) was not found next to ${OpenMP_omp_LIBRARY}")
  endif()
  list(APPEND _tsan_env "OMP_TOOL_LIBRARIES=${B2B_ARCHER_LIBRARY}")

  add_executable(tsan_omp_race_canary tsan/omp_race_canary.c)
  target_link_libraries(tsan_omp_race_canary PRIVATE OpenMP::OpenMP_C)
  add_test(NAME tsan_omp_race_canary
    COMMAND "${CMAKE_COMMAND}" -DPROGRAM=$<TARGET_FILE:tsan_omp_race_canary>
            -DEXPECTED=66 -P "${CMAKE_CURRENT_SOURCE_DIR}/tsan/expect_exit_code.cmake")
  set_tests_properties(tsan_omp_race_canary PROPERTIES
    ENVIRONMENT "${_tsan_env}" LABELS tsan)
endif()

foreach(suite check_pair_threads check_model_threads)
  set_property(TEST ${suite} APPEND PROPERTY ENVIRONMENT ${_tsan_env})
  set_property(TEST ${suite} APPEND PROPERTY LABELS tsan)
endforeach()
