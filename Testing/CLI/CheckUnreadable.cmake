# A file the program may not read must fail with the system's reason. Root
# reads anything, so there the test is skipped. Variables (-D): PROGRAM,
# SOURCE (a readable mesh), WORK_DIR.
cmake_minimum_required(VERSION 3.16)

set(unreadable "${WORK_DIR}/unreadable.ply")
file(REMOVE "${unreadable}")
configure_file("${SOURCE}" "${unreadable}" COPYONLY)
execute_process(COMMAND chmod 000 "${unreadable}")
execute_process(COMMAND sh -c "cat \"$1\" > /dev/null 2>&1" sh "${unreadable}"
  RESULT_VARIABLE still_readable)
if (still_readable EQUAL 0)
  execute_process(COMMAND chmod 644 "${unreadable}")
  message("CLI-TEST-SKIPPED: the file stays readable (running as root?)")
  return()
endif ()

set(ARGS "smooth|${unreadable}")
set(EXPECT_EXIT 1)
set(EXPECT_STDERR "cannot read '.*unreadable.ply': Permission denied")
include("${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake")
execute_process(COMMAND chmod 644 "${unreadable}")
