# Runs PROGRAM and passes only if it exits with EXPECTED (ctest's WILL_FAIL
# would also pass on a crash or a missing runtime, which proves nothing).
execute_process(COMMAND "${PROGRAM}" RESULT_VARIABLE rc)
if(NOT rc STREQUAL "${EXPECTED}")
  message(FATAL_ERROR "${PROGRAM} exited with ${rc}, expected ${EXPECTED}")
endif()
