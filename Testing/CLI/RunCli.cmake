# Runs the silhouette program once and checks what it did; a cmake -P script
# so that exit statuses, stderr and files can all be checked. Variables (-D):
#   PROGRAM          the program
#   ARGS             its arguments separated by '|' (a ';' does not survive add_test)
#   WRAPPER          optional command to run it under (run_with_display.sh)
#   EXPECT_EXIT      expected exit status (default 0)
#   EXPECT_STDERR    for a failure: stderr must be one line "silhouette: ..."
#                    matching this regular expression
#   EXPECT_STDOUT    optional regular expression stdout must match
#   EXPECT_QUIET     if true, a success must print nothing on stderr
#   EXPECT_PNG       optional PNG file the run must write (removed first)
#   EXPECT_PNG_SIZE  its size, WxH
#   EXPECT_PNG_BYTES the least file size in bytes, so a blank image fails
#   KEEP_FILE        optional file that holds a line of ours before the run
#                    and must hold it unchanged after (a failed write must
#                    not leave half a file in place of the user's)
#   MEASURE          optional MeasureRun program: the run is measured, and a
#                    failing run must take under MAX_SECONDS (default 10) and
#                    MAX_MIB of memory (default 1024), its reading process
#                    included
cmake_minimum_required(VERSION 3.16)

if (NOT DEFINED EXPECT_EXIT)
  set(EXPECT_EXIT 0)
endif ()
string(REPLACE "|" ";" arguments "${ARGS}")
if (EXPECT_PNG)
  file(REMOVE "${EXPECT_PNG}")
endif ()

set(kept_text "the user's file, which a failed write must leave as it was\n")
if (KEEP_FILE)
  file(WRITE "${KEEP_FILE}" "${kept_text}")
endif ()

set(measure_command)
if (MEASURE)
  string(MD5 run_key "${PROGRAM}|${ARGS}|${WRAPPER}")
  set(measure_report "${CMAKE_CURRENT_BINARY_DIR}/measure-${run_key}.txt")
  file(REMOVE "${measure_report}")
  set(measure_command "${MEASURE}" "${measure_report}")
endif ()
execute_process(
  COMMAND ${measure_command} ${WRAPPER} "${PROGRAM}" ${arguments}
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 120)

set(report "command: ${PROGRAM} ${arguments}\nexit status: ${exit_status}\nstdout:\n${out}\nstderr:\n${err}")
# Crashes show up here as "Segmentation fault" and the like, never as EXPECT_EXIT.
if (NOT exit_status STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "expected exit status ${EXPECT_EXIT}\n${report}")
endif ()

if (MEASURE AND NOT EXPECT_EXIT EQUAL 0)
  if (NOT DEFINED MAX_SECONDS)
    set(MAX_SECONDS 10)
  endif ()
  if (NOT DEFINED MAX_MIB)
    set(MAX_MIB 1024)
  endif ()
  file(STRINGS "${measure_report}" measured)
  string(REGEX REPLACE ".*seconds=([0-9.]+).*" "\\1" seconds "${measured}")
  string(REGEX REPLACE ".*max_rss_mib=([0-9.]+).*" "\\1" mib "${measured}")
  message(STATUS "measured: ${seconds} s, ${mib} MiB")
  if (seconds GREATER MAX_SECONDS OR mib GREATER MAX_MIB)
    message(FATAL_ERROR "the failure took ${seconds} s and ${mib} MiB; the limits are ${MAX_SECONDS} s and ${MAX_MIB} MiB\n${report}")
  endif ()
endif ()

if (NOT EXPECT_EXIT EQUAL 0)
  string(REGEX REPLACE "\n$" "" error_line "${err}")
  if (error_line MATCHES "\n")
    message(FATAL_ERROR "expected a one-line error\n${report}")
  endif ()
  if (NOT error_line MATCHES "^silhouette: ")
    message(FATAL_ERROR "the error must start with 'silhouette: '\n${report}")
  endif ()
  if (DEFINED EXPECT_STDERR AND NOT error_line MATCHES "${EXPECT_STDERR}")
    message(FATAL_ERROR "the error does not match '${EXPECT_STDERR}'\n${report}")
  endif ()
  if (NOT out STREQUAL "")
    message(FATAL_ERROR "a failure must print nothing on stdout\n${report}")
  endif ()
elseif (EXPECT_QUIET AND NOT err STREQUAL "")
  message(FATAL_ERROR "a success must print nothing on stderr\n${report}")
elseif (DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}'\n${report}")
endif ()

if (KEEP_FILE)
  file(READ "${KEEP_FILE}" kept)
  if (NOT kept STREQUAL kept_text)
    message(FATAL_ERROR "${KEEP_FILE} changed\n${report}")
  endif ()
  get_filename_component(kept_dir "${KEEP_FILE}" DIRECTORY)
  get_filename_component(kept_name "${KEEP_FILE}" NAME)
  file(GLOB leftovers "${kept_dir}/.${kept_name}.*")
  if (leftovers)
    message(FATAL_ERROR "the failed write left ${leftovers}\n${report}")
  endif ()
endif ()

if (DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}'\n${report}")
endif ()

if (EXPECT_PNG)
  if (NOT EXISTS "${EXPECT_PNG}")
    message(FATAL_ERROR "no image ${EXPECT_PNG}\n${report}")
  endif ()
  file(READ "${EXPECT_PNG}" header LIMIT 24 HEX)
  string(SUBSTRING "${header}" 0 16 signature)
  if (NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${EXPECT_PNG} is not a PNG file\n${report}")
  endif ()
  # The IHDR chunk holds the width and height, big-endian, at bytes 16 and 20.
  string(SUBSTRING "${header}" 32 8 width_hex)
  string(SUBSTRING "${header}" 40 8 height_hex)
  math(EXPR width "0x${width_hex}")
  math(EXPR height "0x${height_hex}")
  if (EXPECT_PNG_SIZE AND NOT "${width}x${height}" STREQUAL EXPECT_PNG_SIZE)
    message(FATAL_ERROR "${EXPECT_PNG} is ${width}x${height}, not ${EXPECT_PNG_SIZE}\n${report}")
  endif ()
  file(SIZE "${EXPECT_PNG}" bytes)
  if (EXPECT_PNG_BYTES AND bytes LESS EXPECT_PNG_BYTES)
    message(FATAL_ERROR "${EXPECT_PNG} has ${bytes} bytes, fewer than ${EXPECT_PNG_BYTES}: blank?\n${report}")
  endif ()
endif ()
