# ctest install.consumer: installs the build into a fresh prefix, then, as a
# user would, configures, builds and runs the downstream project of this
# folder against it, runs the installed CLI, and imports the installed Python
# package with Debian's python3.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON=... -DPYTHON_DESTINATION=... -P RunConsumer.cmake
foreach (name BUILD_DIR SOURCE_DIR WORK_DIR)
  if (NOT DEFINED ${name})
    message(FATAL_ERROR "RunConsumer.cmake needs -D${name}=...")
  endif ()
endforeach ()
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "FAILED (${code}): ${ARGN}\n${err}")
  endif ()
endfunction ()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach (installed
    "include/SilhouetteSmoothing/vtkSilhouetteSmoothingFilter.h"
    "bin/silhouette")
  if (NOT EXISTS "${prefix}/${installed}")
    message(FATAL_ERROR "FAILED: ${installed} is not installed")
  endif ()
endforeach ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Testing/Consumer" -B "${WORK_DIR}/consumer"
  "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer")

# The installed program finds the installed module (RPATH), not the build's.
run("${prefix}/bin/silhouette" smooth "${SOURCE_DIR}/Data/sphere_ico80.vtp" --json)

if (PYTHON AND PYTHON_DESTINATION)
  set(ENV{PYTHONPATH} "${prefix}/${PYTHON_DESTINATION}")
  file(WRITE "${WORK_DIR}/import.py" "
import silhouette_smoothing
assert silhouette_smoothing.__file__.startswith('${prefix}/'), silhouette_smoothing.__file__
smoother = silhouette_smoothing.vtkSilhouetteSmoothingFilter()
print('python: imported', smoother.GetClassName(), 'from', silhouette_smoothing.__file__)
")
  run("${PYTHON}" "${WORK_DIR}/import.py")
endif ()
message(STATUS "install.consumer: passed")
