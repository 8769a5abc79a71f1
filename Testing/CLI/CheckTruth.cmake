# `silhouette compare --truth` on the bunny (issue 13): the protocol's shape
# (a Butterfly reference of 16x the original's triangles, the coarse row, four
# normal estimates, carried normals, the fold guard off, PN triangles and
# Phong tessellation at two levels), one threshold: smoothing with the
# default (area-weighted) normals takes at least 40% off the coarse outline's
# distance to the truth, and the coarse mesh itself (the deliberately wrong
# variant) does not; no fold in any row of ours with the fold guard on; and
# with --coarse-points reference the raw coarse outline is nearer the
# reference than with the points on the original; the reference strays
# little from the bunny; every row says where its largest distance is.
# Variables (-D): PROGRAM, WRAPPER, DATA (the Data/ folder).
cmake_minimum_required(VERSION 3.19) # string(JSON)

execute_process(
  COMMAND "${WRAPPER}" "${PROGRAM}" compare --truth "${DATA}/bunny.ply" --views 4 --size 640x480
    --json
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE json
  ERROR_VARIABLE progress
  TIMEOUT 600)
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "compare --truth failed (${exit_status}):\n${json}\n${progress}")
endif ()
message(STATUS "${json}")

string(JSON original GET "${json}" 0 original_triangles)
string(JSON reference GET "${json}" 0 reference_triangles)
math(EXPR expected "16 * ${original}")
if (NOT reference EQUAL expected)
  message(FATAL_ERROR "the Butterfly reference has ${reference} triangles, not 16 x ${original}")
endif ()
string(JSON rows LENGTH "${json}" 0 methods)
if (NOT rows EQUAL 11)
  message(FATAL_ERROR
    "${rows} methods, not 11 (coarse, 4 normal estimates, carried, no fold guard, 4 peers)")
endif ()
set(names "")
foreach (row RANGE 10)
  string(JSON name GET "${json}" 0 methods ${row} method)
  list(APPEND names "${name}")
endforeach ()
foreach (wanted "coarse" "ours, area-weighted normals" "ours, carried normals"
    "ours, area, no fold guard"
    "PN triangles, level 3" "Phong tessellation, level 3")
  if (NOT wanted IN_LIST names)
    message(FATAL_ERROR "no '${wanted}' row: ${names}")
  endif ()
endforeach ()

foreach (row 0 2)
  string(JSON name GET "${json}" 0 methods ${row} method)
  string(JSON ratio GET "${json}" 0 methods ${row} mean_over_coarse)
  if (row EQUAL 0 AND NOT ratio GREATER 0.6)
    message(FATAL_ERROR "the check cannot fail: '${name}' is ${ratio} of the coarse mean")
  endif ()
  if (row EQUAL 2 AND ratio GREATER 0.6)
    message(FATAL_ERROR "'${name}': ${ratio} of the coarse outline's distance, above 0.6")
  endif ()
  message(STATUS "${name}: ${ratio} of the coarse outline's distance to the truth")
endforeach ()

# The bunny's Butterfly reference stays near the original (measured: 0.0039
# of the diagonal outside, 0.0041 inside); the hand's, at its flat wrist,
# strays 0.044 outside, and would fail. Every row says in which of the 4
# views its largest distance is, and on which side of the reference.
string(JSON outside GET "${json}" 0 reference_outside)
string(JSON inside GET "${json}" 0 reference_inside)
if (outside LESS 0 OR outside GREATER 0.01 OR inside GREATER 0 OR inside LESS -0.01)
  message(FATAL_ERROR "the reference strays ${outside} / ${inside} of the diagonal from the "
    "original, beyond 0.01")
endif ()
foreach (row RANGE 10)
  string(JSON name GET "${json}" 0 methods ${row} method)
  string(JSON view GET "${json}" 0 methods ${row} max_view)
  string(JSON side GET "${json}" 0 methods ${row} max_side)
  if (view LESS 0 OR view GREATER 3 OR NOT side MATCHES "^(inside|outside)$")
    message(FATAL_ERROR "'${name}': largest distance at view '${view}', side '${side}'")
  endif ()
endforeach ()

foreach (row RANGE 1 5)
  string(JSON name GET "${json}" 0 methods ${row} method)
  string(JSON turned GET "${json}" 0 methods ${row} turned_over)
  string(JSON cutting GET "${json}" 0 methods ${row} cutting)
  if (NOT turned EQUAL 0 OR NOT cutting EQUAL 0)
    message(FATAL_ERROR "'${name}' folds: ${turned} turned over, ${cutting} cutting")
  endif ()
endforeach ()

# --coarse-points reference: the coarse points sample the reference itself,
# so the raw coarse outline comes nearer it than with the points on the
# original's facets, which lie inside (measured: 1.19 px against 1.41 px
# here). The same run with the points on the original (equal means) fails.
execute_process(
  COMMAND "${WRAPPER}" "${PROGRAM}" compare --truth "${DATA}/bunny.ply" --views 4 --size 640x480
    --json --coarse-points reference
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE on_reference
  ERROR_VARIABLE progress
  TIMEOUT 600)
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "compare --truth --coarse-points reference failed (${exit_status}):\n"
    "${on_reference}\n${progress}")
endif ()
string(JSON where GET "${json}" 0 coarse_points)
string(JSON where_reference GET "${on_reference}" 0 coarse_points)
if (NOT where STREQUAL "original" OR NOT where_reference STREQUAL "reference")
  message(FATAL_ERROR "coarse_points '${where}' and '${where_reference}', "
    "not 'original' and 'reference'")
endif ()
string(JSON coarse_on_original GET "${json}" 0 methods 0 mean)
string(JSON coarse_on_reference GET "${on_reference}" 0 methods 0 mean)
if (NOT coarse_on_reference LESS coarse_on_original)
  message(FATAL_ERROR "the coarse mesh with its points on the reference is ${coarse_on_reference} px "
    "from it, not nearer than with its points on the original (${coarse_on_original} px)")
endif ()
message(STATUS "coarse outline: ${coarse_on_reference} px with the points on the reference, "
  "${coarse_on_original} px on the original")
