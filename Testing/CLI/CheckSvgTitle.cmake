# An SVG drawing's <title> is the command line that made it, as given: every
# option that shaped the drawing, the words a shell would need quoted in
# single quotes, XML-escaped. (It said "silhouette render INPUT --style lines"
# whatever else was given.) The output's name holds a space and an '&'.
# -DPROGRAM -DINPUT -DWORK_DIR
set(output "${WORK_DIR}/svg title & drawing.svg")
file(REMOVE "${output}")
execute_process(
  COMMAND "${PROGRAM}" render "${INPUT}" -o "${output}" --style lines --hidden dashed
    --width-by-depth --size 200x150
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
if (NOT status EQUAL 0)
  message(FATAL_ERROR "render failed (${status}): ${errors}")
endif ()
file(READ "${output}" drawing)
string(REGEX MATCH "<title>([^<]*)</title>" title_element "${drawing}")
set(title "${CMAKE_MATCH_1}")
set(expected "silhouette render ${INPUT} -o '${WORK_DIR}/svg title &amp; drawing.svg' --style lines --hidden dashed --width-by-depth --size 200x150")
if (NOT title STREQUAL expected)
  message(FATAL_ERROR "the drawing's title is\n  '${title}'\nexpected\n  '${expected}'")
endif ()
message(STATUS "title: ${title}")
