# Plays Testing/Data/viewer_interaction.log in 'silhouette view' (issue 4):
# two rotations, every key, a drag of the tolerance slider. Checks the figures
# printed after each step against what the step must do, and compares four of
# the screenshots with baselines. Variables (-D): PROGRAM, COMPARE (the image
# comparison program), WRAPPER (runs with a display), LOG, BASELINE_DIR,
# WORK_DIR.
cmake_minimum_required(VERSION 3.19) # string(JSON)

set(shots "${WORK_DIR}/viewer_play")
file(REMOVE_RECURSE "${shots}")
# The log's positions (the slider's) are for this window size.
execute_process(
  COMMAND "${WRAPPER}" "${PROGRAM}" view --play "${LOG}" --screenshot-dir "${shots}"
    --size 640x400 --no-times --json
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 240)
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "view --play failed (${exit_status}):\n${out}\n${err}")
endif ()
if (NOT err STREQUAL "")
  message(FATAL_ERROR "view --play wrote to stderr:\n${err}")
endif ()
message(STATUS "${out}")

# One JSON object per step; the 'wrote ...' line of the c key is not one.
string(REPLACE "\n" ";" lines "${out}")
set(steps "")
foreach (line IN LISTS lines)
  if (line MATCHES "^{")
    list(APPEND steps "${line}")
  elseif (NOT line MATCHES "^wrote .*silhouette_view_0001.png$" AND NOT line STREQUAL "")
    message(FATAL_ERROR "unexpected output line: ${line}")
  endif ()
endforeach ()

set(expected_actions start smoothing-off smoothing-on new-geometry wireframe lines shaded
  tolerance-up tolerance-down tolerance-down slider parallel perspective fine-reference-on
  help-on reset-camera screenshot help-off fine-reference-off)
list(LENGTH steps count)
list(LENGTH expected_actions expected_count)
if (NOT count EQUAL expected_count)
  message(FATAL_ERROR "${count} steps reported, expected ${expected_count}")
endif ()

# get(<step> <key> <out>): a value of step N.
function (get step key out)
  list(GET steps ${step} json)
  string(JSON value GET "${json}" ${key})
  set(${out} "${value}" PARENT_SCOPE)
endfunction ()

# expect(<what> "<condition>"): the condition is if() arguments separated by spaces.
function (expect what condition)
  string(REPLACE " " ";" arguments "${condition}")
  if (NOT (${arguments}))
    message(FATAL_ERROR "${what}: expected ${condition}")
  endif ()
  message(STATUS "ok: ${what}")
endfunction ()

math(EXPR last "${count} - 1")
foreach (i RANGE ${last})
  list(GET expected_actions ${i} action)
  get(${i} action got)
  if (NOT got STREQUAL action)
    message(FATAL_ERROR "step ${i} is '${got}', expected '${action}'")
  endif ()
  get(${i} screenshot shot)
  if (NOT EXISTS "${shot}")
    message(FATAL_ERROR "step ${i}: no screenshot ${shot}")
  endif ()
  get(${i} input_triangles input)
  expect("step ${i}: the coarse bunny's 1000 triangles go in" "input EQUAL 1000")
  # With smoothing on the output grows by the re-meshed silhouette; off, it is the input.
  get(${i} smoothing smoothing)
  get(${i} new_triangles new)
  get(${i} output_triangles output)
  get(${i} silhouette_triangles silhouette)
  if (smoothing)
    expect("step ${i} (${action}): new triangles while smoothing is on" "new GREATER 0")
    expect("step ${i} (${action}): silhouette triangles while smoothing is on"
      "silhouette GREATER 0")
    expect("step ${i} (${action}): output has more triangles" "output GREATER input")
  else ()
    expect("step ${i} (${action}): no new triangles while smoothing is off" "new EQUAL 0")
    expect("step ${i} (${action}): output is the input" "output EQUAL input")
  endif ()
endforeach ()

# The rotation between step 0 and step 1 moved the camera.
get(0 camera_position start_camera)
get(1 camera_position turned_camera)
expect("the first drag rotates the camera" "NOT start_camera STREQUAL turned_camera")
get(0 smoothing on0)
get(1 smoothing on1)
get(2 smoothing on2)
expect("s turns smoothing off" "on0 AND NOT on1")
expect("s turns it on again" "on2")

foreach (pair IN ITEMS "3;new-geometry" "4;wireframe" "5;lines" "6;shaded")
  list(GET pair 0 i)
  list(GET pair 1 style)
  get(${i} style got)
  expect("step ${i} style ${style}" "got STREQUAL style")
endforeach ()

# Tolerance: 0.5 -> 1 -> 0.5 -> 0.25, and the finer, the more triangles.
get(6 tolerance t6)
get(7 tolerance t7)
get(8 tolerance t8)
get(9 tolerance t9)
expect("+ doubles the tolerance" "t6 EQUAL 0.5 AND t7 EQUAL 1")
expect("- halves it" "t8 EQUAL 0.5 AND t9 STREQUAL 0.25")
get(7 output_triangles out_1)
get(8 output_triangles out_05)
get(9 output_triangles out_025)
expect("finer tolerance, more triangles" "out_025 GREATER out_05 AND out_05 GREATER out_1")
# The slider drag jumps to about 1.5 px.
get(10 tolerance slider_tolerance)
get(10 output_triangles slider_output)
expect("the slider changes the tolerance"
  "slider_tolerance GREATER 1.0 AND slider_tolerance LESS 2.5")
expect("a coarser tolerance from the slider, fewer triangles" "slider_output LESS out_025")
get(11 parallel p11)
get(12 parallel p12)
expect("p switches to parallel and back" "p11 AND NOT p12")
get(13 fine_reference f13)
get(13 fine_triangles fine)
expect("f shows the fine reference, Loop level 3 of 1000 triangles" "f13 AND fine EQUAL 64000")
get(14 help h14)
get(17 help h17)
expect("h shows the help and hides it" "h14 AND NOT h17")
get(18 fine_reference f18)
expect("f hides the fine reference" "NOT f18")
# r: back on the framing camera's axis (further away: the view is half as wide).
get(15 camera_position reset_camera)
string(JSON x0 GET "${start_camera}" 0)
string(JSON y0 GET "${start_camera}" 1)
string(JSON x1 GET "${reset_camera}" 0)
string(JSON y1 GET "${reset_camera}" 1)
if (NOT x0 STREQUAL x1 OR NOT y0 STREQUAL y1)
  message(FATAL_ERROR "r should bring the camera back on its axis: ${start_camera} -> ${reset_camera}")
endif ()
if (NOT EXISTS "${shots}/silhouette_view_0001.png")
  message(FATAL_ERROR "c wrote no ${shots}/silhouette_view_0001.png")
endif ()

# The images: smoothing off, new geometry in red, the pen-and-ink lines, and
# the side-by-side fine reference with the help overlay.
set(failed "")
foreach (name IN ITEMS step_01_smoothing-off step_03_new-geometry step_05_lines step_14_help-on)
  string(REGEX REPLACE "^step_[0-9]+_" "viewer_" baseline "${name}")
  execute_process(
    COMMAND "${COMPARE}" "${shots}/${name}.png" "${BASELINE_DIR}/${baseline}.png" 0.15
      "${shots}"
    RESULT_VARIABLE compared
    OUTPUT_VARIABLE report)
  message(STATUS "${report}")
  if (NOT compared EQUAL 0)
    list(APPEND failed "${name}")
  endif ()
endforeach ()
if (failed)
  message(FATAL_ERROR "images differ from their baselines: ${failed} (see ${shots})")
endif ()
