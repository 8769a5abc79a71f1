#[=======================================================================[.rst:
FindOpenSubdiv
--------------

Finds OpenSubdiv's CPU library (``osdCPU``) and headers.

Debian bookworm's ``OpenSubdivConfig.cmake`` names a static ``libosdCPU.a``
that the package does not ship, so ``find_package(OpenSubdiv CONFIG)`` fails
there; this module looks for the files themselves.

Imported target: ``OpenSubdiv::osdCPU``.
Result variables: ``OpenSubdiv_FOUND``, ``OpenSubdiv_INCLUDE_DIR``,
``OpenSubdiv_LIBRARY``.
#]=======================================================================]

find_path(OpenSubdiv_INCLUDE_DIR
  NAMES opensubdiv/far/topologyRefiner.h
  DOC "Folder that holds opensubdiv/far/topologyRefiner.h")
find_library(OpenSubdiv_LIBRARY
  NAMES osdCPU
  DOC "OpenSubdiv's CPU library")
mark_as_advanced(OpenSubdiv_INCLUDE_DIR OpenSubdiv_LIBRARY)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenSubdiv
  REQUIRED_VARS OpenSubdiv_LIBRARY OpenSubdiv_INCLUDE_DIR)

if (OpenSubdiv_FOUND AND NOT TARGET OpenSubdiv::osdCPU)
  add_library(OpenSubdiv::osdCPU UNKNOWN IMPORTED)
  set_target_properties(OpenSubdiv::osdCPU PROPERTIES
    IMPORTED_LOCATION "${OpenSubdiv_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OpenSubdiv_INCLUDE_DIR}")
endif ()
