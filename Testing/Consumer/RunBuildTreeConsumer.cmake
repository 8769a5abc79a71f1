# ctest buildtree.consumer: the downstream project of this folder configured,
# built and run against the build tree's package (find_package with
# SilhouetteSmoothing_DIR in the build tree, no install), as a developer
# trying the module before installing it would.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPACKAGE_DIR=... -P RunBuildTreeConsumer.cmake
foreach (name BUILD_DIR SOURCE_DIR WORK_DIR PACKAGE_DIR)
  if (NOT DEFINED ${name})
    message(FATAL_ERROR "RunBuildTreeConsumer.cmake needs -D${name}=...")
  endif ()
endforeach ()
file(REMOVE_RECURSE "${WORK_DIR}")
foreach (step configure build run)
  if (step STREQUAL "configure")
    set(command "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Testing/Consumer" -B "${WORK_DIR}"
      "-DSilhouetteSmoothing_DIR=${PACKAGE_DIR}" -DCMAKE_BUILD_TYPE=Release)
  elseif (step STREQUAL "build")
    set(command "${CMAKE_COMMAND}" --build "${WORK_DIR}")
  else ()
    set(command "${WORK_DIR}/consumer")
  endif ()
  execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "FAILED to ${step} against the build tree (${code}):\n${err}")
  endif ()
endforeach ()
