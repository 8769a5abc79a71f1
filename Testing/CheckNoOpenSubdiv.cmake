# The smoothing module's library does not need OpenSubdiv (issue 17: only the
# reference module, SilhouetteSmoothing::FiltersReference, links it), so a
# user or the ParaView plugin that smooths links no OpenSubdiv. Reads the
# library's dynamic section (objdump -p) for its NEEDED entries; the
# reference module's library is checked to name OpenSubdiv, so the check can
# fail.
#   cmake -DSMOOTHING=lib.so -DREFERENCE=lib.so -DOBJDUMP=objdump -P CheckNoOpenSubdiv.cmake
foreach (library SMOOTHING REFERENCE)
  execute_process(COMMAND "${OBJDUMP}" -p "${${library}}" RESULT_VARIABLE code
    OUTPUT_VARIABLE dump ERROR_VARIABLE err)
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "objdump failed on ${${library}}: ${err}")
  endif ()
  string(REGEX MATCHALL "NEEDED +[^\n]*osd[^\n]*" needed "${dump}")
  message(STATUS "${library}: ${needed}")
  set(needs_${library} "${needed}")
endforeach ()
if (needs_SMOOTHING)
  message(FATAL_ERROR "the smoothing module needs OpenSubdiv: ${needs_SMOOTHING}")
endif ()
if (NOT needs_REFERENCE)
  message(FATAL_ERROR "the check cannot fail: the reference module needs no OpenSubdiv either")
endif ()
