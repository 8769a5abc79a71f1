# A copy of the program with no silhouette-read beside it or in ../libexec
# (a program copied out of its tree): reading a mesh fails with one line that
# names the missing program and where it was looked for, exit status 1.
# Args: -DPROGRAM= -DSOURCE= (a mesh) -DWORK_DIR=
set(dir "${WORK_DIR}/reading-program-missing/bin")
file(REMOVE_RECURSE "${WORK_DIR}/reading-program-missing")
file(MAKE_DIRECTORY "${dir}")
file(COPY "${PROGRAM}" DESTINATION "${dir}")
get_filename_component(name "${PROGRAM}" NAME)
execute_process(COMMAND "${dir}/${name}" smooth "${SOURCE}" -o "${dir}/out.vtp"
  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_VARIABLE out)
file(REMOVE_RECURSE "${WORK_DIR}/reading-program-missing")
set(expected "^silhouette: cannot read '[^']*': the reading program silhouette-read is not installed \\(looked for [^ ]*/reading-program-missing/bin/silhouette-read and [^ ]*/reading-program-missing/libexec/silhouette-read\\)\n$")
if (NOT status EQUAL 1 OR NOT err MATCHES "${expected}")
  message(FATAL_ERROR "expected exit 1 and the missing reading program named, got ${status}:\n${err}")
endif ()
message(STATUS "exit 1: ${err}")
