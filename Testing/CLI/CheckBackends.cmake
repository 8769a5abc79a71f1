# Renders one image through OSMesa and through X and compares the two with
# VTK's image difference, against the regression threshold (issue 5).
# Variables (-D):
#   PROGRAM          the silhouette program
#   COMPARE          silhouette_compare_image
#   ARGS             the render arguments without -o, separated by '|'
#   OSMESA_WRAPPER   runs the OSMesa render (run_without_display.sh: DISPLAY
#                    unset, the back-end picked by itself)
#   OSMESA_OPTIONS   optional extra arguments of that render ('--backend|osmesa')
#   X_WRAPPER        runs the X render (run_with_display.sh), with --backend x
#   WORK_DIR, NAME   the images are WORK_DIR/NAME_osmesa.png and NAME_x.png
#   THRESHOLD        VTK's image difference allowed (default 0.15, VTK's own)
cmake_minimum_required(VERSION 3.16)

if (NOT DEFINED THRESHOLD)
  set(THRESHOLD 0.15)
endif ()
string(REPLACE "|" ";" arguments "${ARGS}")
string(REPLACE "|" ";" osmesa_options "${OSMESA_OPTIONS}")
set(osmesa_png "${WORK_DIR}/${NAME}_osmesa.png")
set(x_png "${WORK_DIR}/${NAME}_x.png")
file(REMOVE "${osmesa_png}" "${x_png}")

execute_process(
  COMMAND "${OSMESA_WRAPPER}" "${PROGRAM}" ${arguments} -o "${osmesa_png}" ${osmesa_options}
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 120)
set(report "OSMesa render: ${PROGRAM} ${arguments} -o ${osmesa_png} ${osmesa_options}\nexit status: ${exit_status}\nstdout:\n${out}\nstderr:\n${err}")
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "the OSMesa render failed\n${report}")
endif ()
# VTK's start-up through GLEW complains about the missing GLX display unless
# the back-end handles it; VTK's logger marks errors "ERR|".
if ("${out}${err}" MATCHES "ERROR|ERR\\|")
  message(FATAL_ERROR "the OSMesa render reported an error\n${report}")
endif ()
if (NOT err STREQUAL "")
  message(FATAL_ERROR "the OSMesa render wrote to stderr\n${report}")
endif ()
if (NOT EXISTS "${osmesa_png}")
  message(FATAL_ERROR "the OSMesa render wrote no image\n${report}")
endif ()

execute_process(
  COMMAND "${X_WRAPPER}" "${PROGRAM}" ${arguments} -o "${x_png}" --backend x
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 120)
if (NOT exit_status EQUAL 0 OR NOT EXISTS "${x_png}")
  message(FATAL_ERROR "the X render failed (${exit_status}):\n${out}\n${err}")
endif ()

execute_process(
  COMMAND "${COMPARE}" "${osmesa_png}" "${x_png}" "${THRESHOLD}" "${WORK_DIR}"
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
string(REGEX MATCH "[^\n]*: difference [^\n]*" verdict "${out}")
message(STATUS "OSMesa against X: ${verdict}")
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "the OSMesa and X images differ beyond ${THRESHOLD}:\n${out}\n${err}")
endif ()
