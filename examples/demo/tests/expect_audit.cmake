# The demo's audit check on a scene whose contact sits on a convex joint of
# straight segments (issue 16): either the model carries the contact (exit 0,
# "check audit: 0", some step with contacts) or the audit lists the joint's
# pairs as outside on both sides and the scene fails (exit 1). Anything else
# (a clean audit without contact, a crash) fails the test.
# -DDEMO=program -DSCENE=file.nml -DOUT=directory
execute_process(COMMAND "${DEMO}" "${SCENE}" "${OUT}"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("stdout:\n${_out}\nstderr:\n${_err}")
if(_rc EQUAL 0)
  if(NOT _out MATCHES "check audit: 0 pair" OR NOT _out MATCHES "contacts +[1-9]")
    message(FATAL_ERROR "exit 0 but not a carried contact with a clean audit")
  endif()
elseif(_rc EQUAL 1)
  if(NOT _out MATCHES "check audit: [1-9][0-9]* pair" OR NOT _out MATCHES "outside on both sides"
     OR NOT _out MATCHES "CHECK FAILED: the audit found")
    message(FATAL_ERROR "exit 1 but not for the audit's findings at the joint")
  endif()
else()
  message(FATAL_ERROR "unexpected exit code ${_rc}")
endif()
