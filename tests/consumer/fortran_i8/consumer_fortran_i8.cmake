# consumer_fortran_i8: the installed module source (share/b2b/fortran) built
# by a legacy host with -fdefault-integer-8 -fdefault-real-8 and used with
# libb2b (run_fortran_i8_test.sh says how). Included by
# tests/consumer/CMakeLists.txt after its own checks (ELF, no sanitizers, sh
# and pkg-config found). The flags are gfortran's, so the test needs
# gfortran; like consumer_install it installs the build tree, so the project
# must be built first.
if(NOT TARGET b2b_fortran)
  message(STATUS "consumer_fortran_i8: b2b is built without Fortran, test not registered")
  return()
endif()
if(NOT CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  message(STATUS "consumer_fortran_i8: needs gfortran (-fdefault-integer-8), test not registered")
  return()
endif()

if(BUILD_SHARED_LIBS)
  set(_b2b_i8_shared ON)
else()
  set(_b2b_i8_shared OFF)
endif()
add_test(NAME consumer_fortran_i8
  COMMAND "${B2B_SH}" "${CMAKE_CURRENT_LIST_DIR}/run_fortran_i8_test.sh"
          "--cmake=${CMAKE_COMMAND}"
          "--build-dir=${PROJECT_BINARY_DIR}"
          "--work-dir=${CMAKE_CURRENT_BINARY_DIR}/work_fortran_i8"
          "--source-dir=${CMAKE_CURRENT_LIST_DIR}"
          "--fortran-compiler=${CMAKE_Fortran_COMPILER}"
          "--pkg-config=${PKG_CONFIG_EXECUTABLE}"
          "--libdir=${CMAKE_INSTALL_LIBDIR}"
          "--datadir=${CMAKE_INSTALL_DATADIR}"
          "--shared=${_b2b_i8_shared}"
          "--built-lib=$<TARGET_FILE:b2b>"
          "--built-lib=$<TARGET_FILE:b2b_fortran>")
set_tests_properties(consumer_fortran_i8 PROPERTIES LABELS "consumer" TIMEOUT 300)
