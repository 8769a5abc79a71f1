# `silhouette render --style lines` draws the visible lines only (issue 16):
# the 24 x 12 torus from 60 degrees up, where the inner contour ends in
# cusps whose tails the near side of the tube hides, matches its baseline
# (Testing/Data/Baseline/RenderTorusLines.png) within MAXIMUM pixels; the
# same render with --hidden dashed (the hidden tails drawn in grey, the
# deliberately wrong variant) must not (measured: 0 and 68 pixels). Counted
# pixel for pixel: VTK's image difference forgives lines a pixel wide.
# Variables (-D): PROGRAM, WRAPPER, PYTHON, DATA (Data/), BASELINE,
# COUNTER (differing_pixels.py), WORK_DIR.
set(MAXIMUM 20)
set(common "${DATA}/torus_24x12.vtp" --style lines --size 500x400 --elevation 60)
foreach (variant visible hidden)
  set(extra "")
  if (variant STREQUAL "hidden")
    set(extra --hidden dashed)
  endif ()
  execute_process(
    COMMAND "${WRAPPER}" "${PROGRAM}" render ${common} ${extra}
      -o "${WORK_DIR}/torus_lines_${variant}.png"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors TIMEOUT 120)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "render (${variant}) failed (${status}): ${errors}")
  endif ()
  execute_process(
    COMMAND "${PYTHON}" "${COUNTER}" "${WORK_DIR}/torus_lines_${variant}.png" "${BASELINE}"
    RESULT_VARIABLE status OUTPUT_VARIABLE count ERROR_VARIABLE errors
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "comparing the ${variant} image failed: ${errors}")
  endif ()
  message(STATUS "${variant} lines: ${count} pixels differ from the baseline")
  set(differing_${variant} ${count})
endforeach ()
if (differing_visible GREATER MAXIMUM)
  message(FATAL_ERROR "the lines differ from the baseline in ${differing_visible} pixels "
    "(limit ${MAXIMUM}); the image is ${WORK_DIR}/torus_lines_visible.png")
endif ()
if (NOT differing_hidden GREATER MAXIMUM)
  message(FATAL_ERROR "the check cannot fail: with the hidden lines drawn only "
    "${differing_hidden} pixels differ")
endif ()
