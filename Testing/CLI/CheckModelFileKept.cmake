# `smooth bunny -o FILE` refuses (exit 2) when FILE is the PLY the bunny model
# is read from: the input word is a model name, and the file behind it is
# what must not be overwritten (the program wrote over it). The program runs
# from a copy in a folder of its own, with its own data folder beside it, so
# that a wrong variant would overwrite only that copy of the bunny.
# -DPROGRAM -DBUNNY -DWORK_DIR
set(prefix "${WORK_DIR}/model_file_kept")
file(REMOVE_RECURSE "${prefix}")
set(data "${prefix}/share/SilhouetteSmoothing/Data")
file(MAKE_DIRECTORY "${prefix}/bin" "${data}")
file(COPY "${PROGRAM}" DESTINATION "${prefix}/bin")
file(COPY "${BUNNY}" DESTINATION "${data}")
get_filename_component(program_name "${PROGRAM}" NAME)
get_filename_component(bunny_name "${BUNNY}" NAME)
file(SHA256 "${data}/${bunny_name}" before)
execute_process(
  COMMAND "${prefix}/bin/${program_name}" smooth bunny -o "${data}/./${bunny_name}"
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
file(SHA256 "${data}/${bunny_name}" after)
if (NOT before STREQUAL after)
  message(FATAL_ERROR "the bunny's file was overwritten (exit ${status}): ${errors}")
endif ()
if (NOT status EQUAL 2 OR NOT errors MATCHES "option '-o' names the input file '[^']*bunny.ply', which would be overwritten")
  message(FATAL_ERROR "expected exit 2 and the refusal, got ${status}: ${errors}")
endif ()
message(STATUS "refused: ${errors}")
