# Renders the same stroke style twice and requires byte-identical PNGs: the
# brushes' noise is seeded, so a stroke image repeats exactly.
# -DPROGRAM -DWRAPPER -DINPUT -DSTYLE -DWORK_DIR
foreach (run IN ITEMS 1 2)
  set(image "${WORK_DIR}/repeat_${STYLE}_${run}.png")
  file(REMOVE "${image}")
  execute_process(
    COMMAND "${WRAPPER}" "${PROGRAM}" render "${INPUT}" -o "${image}" --style "${STYLE}"
      --size 400x300
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "render ${STYLE} failed (${status}): ${errors}")
  endif ()
endforeach ()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK_DIR}/repeat_${STYLE}_1.png"
    "${WORK_DIR}/repeat_${STYLE}_2.png"
  RESULT_VARIABLE different)
if (NOT different EQUAL 0)
  message(FATAL_ERROR "two renders of --style ${STYLE} differ")
endif ()
