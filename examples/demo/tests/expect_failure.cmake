# A bad scene must make b2b_demo exit with 2, print a message matching
# REGEX on standard error, and leave no .pvd collection or history CSV (a
# failed run never writes a result that looks complete). A stale result of
# the same name is planted first, to check that a failed run removes it.
# -DDEMO=program -DSCENE=file.nml -DOUT=directory -DREGEX=expected message
get_filename_component(_name "${SCENE}" NAME_WE)
file(WRITE "${OUT}/${_name}.pvd" "stale")
file(WRITE "${OUT}/${_name}_history.csv" "stale")
execute_process(COMMAND "${DEMO}" "${SCENE}" "${OUT}"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("stdout:\n${_out}\nstderr:\n${_err}")
if(NOT _rc EQUAL 2)
  message(FATAL_ERROR "expected exit code 2, got ${_rc}")
endif()
if(NOT _err MATCHES "${REGEX}")
  message(FATAL_ERROR "the message does not match: ${REGEX}")
endif()
if(EXISTS "${OUT}/${_name}_history.csv" OR EXISTS "${OUT}/${_name}.pvd")
  message(FATAL_ERROR "a complete-looking result (.pvd or history CSV) is left after a failed run")
endif()
