# An output file the user may not write must be refused with the system's
# reason, not replaced (the program writes a temporary file and renames it,
# which a directory the user may write allows: a user's trial replaced
# another user's read-only drawing, 2026-12-06). Root may write anything, so
# there the program runs as nobody (setpriv), in a directory anyone may
# write; without setpriv the test is skipped. Variables (-D): PROGRAM,
# SOURCE (a readable mesh), WORK_DIR.
cmake_minimum_required(VERSION 3.16)

set(dir "${WORK_DIR}/read_only_output")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")
execute_process(COMMAND chmod 777 "${dir}")
set(target "${dir}/kept.vtp")
file(WRITE "${target}" "the user's own file\n")
execute_process(COMMAND chmod 444 "${target}")

set(runner "")
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if (uid STREQUAL "0")
  find_program(setpriv setpriv)
  if (NOT setpriv)
    message("CLI-TEST-SKIPPED: root may write the file, and there is no setpriv to run as nobody")
    return()
  endif ()
  set(runner "${setpriv}" --reuid=65534 --regid=65534 --clear-groups)
  # nobody must reach the program, the mesh and the directory (a build
  # under /root is not reachable): else there is nothing to test.
  execute_process(COMMAND ${runner} sh -c "test -x \"$1\" && test -r \"$2\" && test -w \"$3\""
    sh "${PROGRAM}" "${SOURCE}" "${dir}" RESULT_VARIABLE reachable)
  if (NOT reachable EQUAL 0)
    message("CLI-TEST-SKIPPED: user nobody cannot reach the program, the mesh or ${dir}")
    return()
  endif ()
endif ()
execute_process(COMMAND ${runner} "${PROGRAM}" smooth "${SOURCE}" -o "${target}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${target}" kept)
file(GLOB leftovers "${dir}/.kept.vtp.*")
execute_process(COMMAND chmod 644 "${target}")
if (NOT code EQUAL 1)
  message(FATAL_ERROR "exit ${code}, expected 1 (stderr: ${err})")
endif ()
if (NOT err MATCHES "^silhouette: cannot write '[^']*kept.vtp': Permission denied\n$")
  message(FATAL_ERROR "unexpected stderr: ${err}")
endif ()
if (NOT kept STREQUAL "the user's own file\n")
  message(FATAL_ERROR "the read-only file was replaced")
endif ()
if (leftovers)
  message(FATAL_ERROR "temporary files left: ${leftovers}")
endif ()
message("read-only output refused: ${err}")
