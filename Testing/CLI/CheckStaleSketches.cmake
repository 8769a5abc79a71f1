# `render --progressive N --svg -o DIR` into a folder that holds drawings of
# an earlier, longer run: they stay (nothing of the user's is deleted) and a
# warning names them, since they would pass for this run's (a user's
# animation mixed two runs). Files that only look alike (another number
# width, another extension) are not named. The wrong variant: the same run
# into a fresh folder warns of nothing.
# -DPROGRAM -DINPUT -DWORK_DIR
set(folder "${WORK_DIR}/stale_sketches")
file(REMOVE_RECURSE "${folder}" "${folder}_fresh")
file(MAKE_DIRECTORY "${folder}")
foreach (name sketch-05.svg sketch-06.svg sketch-7.svg sketch-08.png sketch-09.svgz)
  file(TOUCH "${folder}/${name}")
endforeach ()
foreach (run stale fresh)
  set(out "${folder}")
  if (run STREQUAL "fresh")
    set(out "${folder}_fresh")
  endif ()
  execute_process(
    COMMAND "${PROGRAM}" render "${INPUT}" --style lines --progressive 2 --svg -o "${out}"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
  if (NOT status EQUAL 0 OR NOT EXISTS "${out}/sketch-02.svg")
    message(FATAL_ERROR "${run}: the sketch failed (exit ${status}): ${errors}")
  endif ()
  set(${run}_errors "${errors}")
endforeach ()
if (NOT stale_errors MATCHES "^silhouette: warning: '[^']*stale_sketches' also holds sketch-05.svg to sketch-06.svg \\(2 drawings\\) of an earlier run, not of this one\n$")
  message(FATAL_ERROR "expected one warning naming sketch-05.svg to sketch-06.svg, got: ${stale_errors}")
endif ()
foreach (name sketch-05.svg sketch-06.svg sketch-7.svg sketch-08.png sketch-09.svgz)
  if (NOT EXISTS "${folder}/${name}")
    message(FATAL_ERROR "${name} was deleted")
  endif ()
endforeach ()
if (NOT fresh_errors STREQUAL "")
  message(FATAL_ERROR "a fresh folder warned: ${fresh_errors}")
endif ()
message(STATUS "warned: ${stale_errors}")
