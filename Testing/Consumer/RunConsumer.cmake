# ctest install.consumer: installs the build into a fresh prefix and moves the
# prefix to another folder; checks that no installed file names the source or
# build folder, and that every installed module library loads by itself (each
# finds the modules it needs); then, as a user would, configures, builds and
# runs the downstream project of this folder against the moved prefix, runs
# the installed CLI (a job on a file, and the viewer's headless orbit of its
# default mesh, which it finds in the prefix), builds and runs the README's
# programs (with X and with OSMesa), and imports the installed
# Python package with Debian's python3.
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

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/installed")
file(RENAME "${WORK_DIR}/installed" "${prefix}") # the tree must not care where it is
foreach (installed
    "include/SilhouetteSmoothing/vtkSilhouetteSmoothingFilter.h"
    "bin/silhouette"
    "libexec/silhouette-read" # the reading process; the runs below use it
    "share/SilhouetteSmoothing/Data/bunny_coarse.ply"
    # The user documentation, which the headers name (docs/using.md).
    "share/doc/SilhouetteSmoothing/README.md"
    "share/doc/SilhouetteSmoothing/docs/using.md"
    "share/doc/SilhouetteSmoothing/docs/figures/bunny.png")
  if (NOT EXISTS "${prefix}/${installed}")
    message(FATAL_ERROR "FAILED: ${installed} is not installed")
  endif ()
endforeach ()

# No installed file names a folder of the build machine's checkout.
file(GLOB_RECURSE installed_files LIST_DIRECTORIES false "${prefix}/*")
foreach (installed_file IN LISTS installed_files)
  foreach (folder "${SOURCE_DIR}" "${BUILD_DIR}")
    file(STRINGS "${installed_file}" naming REGEX "${folder}")
    if (naming)
      list(GET naming 0 first)
      message(FATAL_ERROR "FAILED: ${installed_file} names ${folder}: ${first}")
    endif ()
  endforeach ()
endforeach ()

# Every RUNPATH entry of the installed programs and libraries stays inside
# the prefix (CheckRunpaths.cmake).
set(PREFIX "${prefix}")
include("${CMAKE_CURRENT_LIST_DIR}/CheckRunpaths.cmake")

# Every module library loads on its own: a library that needs another
# module's finds it in the prefix (a program using only the mapper once
# could not start).
if (PYTHON)
  file(GLOB module_libraries "${prefix}/lib/libSilhouetteSmoothing*.so")
  foreach (library IN LISTS module_libraries)
    run("${PYTHON}" -c "import ctypes; ctypes.CDLL('${library}')")
  endforeach ()
endif ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Testing/Consumer" -B "${WORK_DIR}/consumer"
  "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer")

# The installed program finds the installed module (RPATH), not the build's,
# and its default mesh in the prefix.
run("${prefix}/bin/silhouette" smooth "${SOURCE_DIR}/Data/sphere_ico80.vtp" --json)
# The README's examples run from the installed data folder (the bracket's
# line drawing was the one whose mesh was not installed).
set(installed_data "${prefix}/share/SilhouetteSmoothing/Data")
run("${prefix}/bin/silhouette" render "${installed_data}/bracket.stl" -o "${WORK_DIR}/bracket.svg"
  --style lines --hidden dashed)
run("${prefix}/bin/silhouette" view --orbit 10 --frames 1 --record "${WORK_DIR}/orbit")
if (NOT EXISTS "${WORK_DIR}/orbit/frame_0000.png")
  message(FATAL_ERROR "FAILED: the installed viewer's orbit wrote no frame")
endif ()

# The README's C++ program with its CMakeLists.txt, and its Python program,
# as written, against the moved prefix and its installed data, with X and
# with OSMesa: each image shows the smoothed bunny, the same pixel for pixel
# (RunReadmePrograms.py).
if (PYTHON AND PYTHON_DESTINATION)
  run("${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/RunReadmePrograms.py" "${SOURCE_DIR}/README.md"
    "${prefix}" "${prefix}/${PYTHON_DESTINATION}" "${WORK_DIR}")
else ()
  message(FATAL_ERROR "FAILED: install.consumer needs PYTHON and PYTHON_DESTINATION for the README's programs")
endif ()

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
