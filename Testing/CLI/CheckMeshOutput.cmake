# Runs `silhouette smooth INPUT -o OUTPUT --json`, then reads OUTPUT back with
# `silhouette smooth OUTPUT --json`: the file must exist and hold as many
# triangles as the first run said it wrote. Variables (-D): PROGRAM, INPUT, OUTPUT.
cmake_minimum_required(VERSION 3.19) # string(JSON)

file(REMOVE "${OUTPUT}")
execute_process(
  COMMAND "${PROGRAM}" smooth "${INPUT}" -o "${OUTPUT}" --json
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE written
  ERROR_VARIABLE err
  TIMEOUT 120)
if (NOT exit_status EQUAL 0 OR NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "writing ${OUTPUT} failed (${exit_status}):\n${written}\n${err}")
endif ()
string(JSON output GET "${written}" output)
if (NOT output STREQUAL OUTPUT)
  message(FATAL_ERROR "\"output\" is '${output}', not '${OUTPUT}'")
endif ()
string(JSON written_triangles GET "${written}" output_triangles)

execute_process(
  COMMAND "${PROGRAM}" smooth "${OUTPUT}" --json
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE reread
  ERROR_VARIABLE err
  TIMEOUT 120)
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "reading ${OUTPUT} back failed (${exit_status}):\n${reread}\n${err}")
endif ()
string(JSON read_triangles GET "${reread}" input_triangles)
if (NOT read_triangles EQUAL written_triangles)
  message(FATAL_ERROR "${OUTPUT} holds ${read_triangles} triangles, the run wrote ${written_triangles}")
endif ()
