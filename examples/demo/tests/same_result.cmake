# Runs two scenes that must give the same result (e.g. one written with a
# shorthand, one spelt out): both must exit with 0, and their history,
# convergence and (with contact) contacts CSV files must be identical byte
# for byte. The verdict is this script's exit code.
#   -DDEMO=program -DSCENE_A=a.nml -DSCENE_B=b.nml -DOUT=directory
get_filename_component(_a "${SCENE_A}" NAME_WE)
get_filename_component(_b "${SCENE_B}" NAME_WE)
foreach(_s A B)
  file(REMOVE_RECURSE "${OUT}/${_s}")
  execute_process(COMMAND "${DEMO}" "${SCENE_${_s}}" "${OUT}/${_s}"
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message("${_out}${_err}")
    message(FATAL_ERROR "${SCENE_${_s}}: b2b_demo exited with ${_rc}")
  endif()
endforeach()
set(_n 0)
foreach(_f _history.csv _convergence.csv _contacts.csv)
  set(_fa "${OUT}/A/${_a}${_f}")
  set(_fb "${OUT}/B/${_b}${_f}")
  if(NOT EXISTS "${_fa}" AND NOT EXISTS "${_fb}" AND _f STREQUAL "_contacts.csv")
    continue()
  endif()
  if(NOT EXISTS "${_fa}" OR NOT EXISTS "${_fb}")
    message(FATAL_ERROR "missing ${_fa} or ${_fb}")
  endif()
  file(SHA256 "${_fa}" _ha)
  file(SHA256 "${_fb}" _hb)
  if(NOT _ha STREQUAL _hb)
    message(FATAL_ERROR "${_a}${_f} and ${_b}${_f} differ")
  endif()
  math(EXPR _n "${_n} + 1")
endforeach()
message("${_a} and ${_b}: ${_n} result files identical")
