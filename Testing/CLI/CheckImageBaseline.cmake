# One image of `silhouette render` against its baseline, and a deliberately
# wrong variant that must not match it. Counted pixel for pixel
# (differing_pixels.py): VTK's image difference forgives lines a pixel wide.
# Variables (-D): PROGRAM, WRAPPER, PYTHON, COUNTER, BASELINE, WORK_DIR, NAME,
# ARGS (the render arguments but -o, a ;-list), RIGHT_ARGS (optional: the
# right variant's own extra arguments), WRONG_ARGS (the wrong variant's extra
# arguments, maybe none), MAXIMUM (differing pixels allowed).
foreach (variant right wrong)
  set(extra ${RIGHT_ARGS})
  if (variant STREQUAL "wrong")
    set(extra ${WRONG_ARGS})
  endif ()
  set(image "${WORK_DIR}/${NAME}_${variant}.png")
  execute_process(
    COMMAND "${WRAPPER}" "${PROGRAM}" render ${ARGS} ${extra} -o "${image}"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors TIMEOUT 120)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "render (${variant}) failed (${status}): ${errors}")
  endif ()
  execute_process(
    COMMAND "${PYTHON}" "${COUNTER}" "${image}" "${BASELINE}"
    RESULT_VARIABLE status OUTPUT_VARIABLE count ERROR_VARIABLE errors
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "comparing the ${variant} image failed: ${errors}")
  endif ()
  message(STATUS "${variant}: ${count} pixels differ from ${BASELINE}")
  set(differing_${variant} ${count})
endforeach ()
if (differing_right GREATER MAXIMUM)
  message(FATAL_ERROR "${differing_right} pixels differ from the baseline (limit ${MAXIMUM}); "
    "the image is ${WORK_DIR}/${NAME}_right.png")
endif ()
if (NOT differing_wrong GREATER MAXIMUM)
  message(FATAL_ERROR "the check cannot fail: the wrong variant (${WRONG_ARGS}) differs in only "
    "${differing_wrong} pixels")
endif ()
