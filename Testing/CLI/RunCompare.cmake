# Included by the `silhouette compare` checks (CheckCompare.cmake,
# CheckCompareExact.cmake), which measure at one size and one number of
# views and frames. Variables (-D): PROGRAM, WRAPPER (runs it with a display).
cmake_minimum_required(VERSION 3.19) # string(JSON)

# run_compare(<json variable> <model>...): the run's JSON, printed; a failed
# run fails the test.
function (run_compare json_variable)
  execute_process(
    COMMAND "${WRAPPER}" "${PROGRAM}" compare ${ARGN} --views 6 --frames 3 --size 640x480 --json
    RESULT_VARIABLE exit_status
    OUTPUT_VARIABLE json
    ERROR_VARIABLE progress
    TIMEOUT 600)
  if (NOT exit_status EQUAL 0)
    message(FATAL_ERROR "compare failed (${exit_status}):\n${json}\n${progress}")
  endif ()
  message(STATUS "${json}")
  set(${json_variable} "${json}" PARENT_SCOPE)
endfunction ()
