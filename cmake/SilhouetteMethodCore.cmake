# silhouette_add_method_core(<target> <source>...): the VTK-free core of one
# method (line drawings, strokes, baselines, simplification, level of
# detail): a static library on the common core (Common/Core), whose
# headers are found from the folder that declares it. Position-independent
# (CMAKE_POSITION_INDEPENDENT_CODE) for the shared VTK modules, and, as the
# smoothing core, built without semantic interposition so that GCC calls
# its own functions directly.
function(silhouette_add_method_core target)
  add_library(${target} STATIC ${ARGN})
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>")
  target_link_libraries(${target} PUBLIC silhouette_common_core)
  if (CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif ()
endfunction()
