# Runs one scene through b2b_demo: passes when the program exits with 0,
# reports the run complete, and the .pvd collection and history CSV exist.
# -DDEMO=program -DSCENE=file.nml -DOUT=directory
get_filename_component(_name "${SCENE}" NAME_WE)
file(REMOVE "${OUT}/${_name}.pvd" "${OUT}/${_name}_history.csv")
execute_process(COMMAND "${DEMO}" "${SCENE}" "${OUT}"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("${_out}${_err}")
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "b2b_demo exited with ${_rc}")
endif()
if(NOT _out MATCHES "${_name}: complete")
  message(FATAL_ERROR "no completion line")
endif()
if(NOT EXISTS "${OUT}/${_name}.pvd" OR NOT EXISTS "${OUT}/${_name}_history.csv")
  message(FATAL_ERROR "missing ${_name}.pvd or ${_name}_history.csv in ${OUT}")
endif()
