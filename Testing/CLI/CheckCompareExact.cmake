# `silhouette compare` on the analytic models measured against their exact
# surfaces' stand-ins (ExactSurface: the same analytic surface sampled very
# finely, docs/exact-surfaces.md): the ellipsoid, the super-toroid and the
# knot report an exact distance for every variant, and one threshold: the
# smoothed outline comes within 0.75 px of the exact one on average (measured
# at 640x480: 0.56, 0.57, 0.52 px), and the coarse mesh itself (the
# deliberately wrong variant: 2.07, 1.84, 1.72 px) does not. (The filter at a
# 20 px tolerance instead of 0.5 fails it too: 0.97, 0.94, 0.83 px.) The fine
# reference (Loop's limit, which shrinks) must not be the exact surface
# (0.77, 0.50, 0.67 px).
# Variables (-D): PROGRAM, WRAPPER (runs it with a display).
cmake_minimum_required(VERSION 3.19) # string(JSON)
include("${CMAKE_CURRENT_LIST_DIR}/RunCompare.cmake")

set(models ellipsoid supertoroid knot)
run_compare(json ${models})

set(limit 0.75)
set(index 0)
foreach (model IN LISTS models)
  string(JSON name GET "${json}" ${index} model)
  if (NOT name STREQUAL model)
    message(FATAL_ERROR "model ${index} is '${name}', not '${model}'")
  endif ()
  foreach (variant coarse smoothed wang2003 pn fine)
    string(JSON ${variant} ERROR_VARIABLE missing GET "${json}" ${index} ${variant} exact_mean_px)
    if (missing)
      message(FATAL_ERROR "${model}: no exact distance for ${variant} (${missing})")
    endif ()
    message(STATUS "${model}: ${variant} ${${variant}} px from the exact outline")
  endforeach ()
  if (NOT coarse GREATER limit)
    message(FATAL_ERROR
      "${model}: the check cannot fail: the coarse mesh is ${coarse} px from the exact outline")
  endif ()
  if (smoothed GREATER limit)
    message(FATAL_ERROR "${model}: smoothed ${smoothed} px from the exact outline, above ${limit}")
  endif ()
  if (NOT smoothed LESS coarse)
    message(FATAL_ERROR "${model}: smoothing should bring the outline nearer the exact one")
  endif ()
  if (NOT fine GREATER 0.1)
    message(FATAL_ERROR "${model}: the fine reference is ${fine} px from the exact outline: "
      "is the stand-in the fine reference?")
  endif ()
  math(EXPR index "${index} + 1")
endforeach ()
