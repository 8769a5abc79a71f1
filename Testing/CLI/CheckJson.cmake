# Runs `silhouette smooth ... --json` and checks that stdout is one JSON
# object with every documented key, of the right type, and that the counts
# add up. Variables (-D): PROGRAM, ARGS ('|'-separated), INPUT_TRIANGLES
# (expected), VIEWPORT (expected "W,H"), VIEW_ANGLE (expected camera
# view_angle), CAMERA_Z (expected "LOW,HIGH" range of the camera position's
# z).
cmake_minimum_required(VERSION 3.19) # string(JSON)

string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(
  COMMAND "${PROGRAM}" ${arguments}
  RESULT_VARIABLE exit_status
  OUTPUT_VARIABLE json
  ERROR_VARIABLE err
  TIMEOUT 120)
set(report "command: ${PROGRAM} ${arguments}\nexit status: ${exit_status}\nstdout:\n${json}\nstderr:\n${err}")
if (NOT exit_status EQUAL 0)
  message(FATAL_ERROR "the command failed\n${report}")
endif ()
string(REGEX REPLACE "\n$" "" line "${json}")
if (line MATCHES "\n")
  message(FATAL_ERROR "--json must print one line\n${report}")
endif ()

# Each documented key with its JSON type.
foreach (key_type IN ITEMS
    input:STRING output:NULL input_triangles:NUMBER output_triangles:NUMBER
    silhouette_triangles:NUMBER new_triangles:NUMBER new_points:NUMBER fold_fallbacks:OBJECT
    prepare_ms:NUMBER filter_ms:NUMBER
    tolerance:NUMBER viewport:ARRAY camera:OBJECT)
  string(REPLACE ":" ";" key_type "${key_type}")
  list(GET key_type 0 key)
  list(GET key_type 1 expected_type)
  string(JSON type ERROR_VARIABLE json_error TYPE "${json}" ${key})
  if (json_error)
    message(FATAL_ERROR "no key '${key}': ${json_error}\n${report}")
  endif ()
  if (NOT type STREQUAL expected_type)
    message(FATAL_ERROR "'${key}' is ${type}, not ${expected_type}\n${report}")
  endif ()
endforeach ()
foreach (key_type IN ITEMS position:ARRAY focal_point:ARRAY view_up:ARRAY view_angle:NUMBER
    parallel:BOOLEAN)
  string(REPLACE ":" ";" key_type "${key_type}")
  list(GET key_type 0 key)
  list(GET key_type 1 expected_type)
  string(JSON type ERROR_VARIABLE json_error TYPE "${json}" camera ${key})
  if (json_error OR NOT type STREQUAL expected_type)
    message(FATAL_ERROR "camera.${key} is not ${expected_type} (${json_error})\n${report}")
  endif ()
  if (expected_type STREQUAL "ARRAY")
    string(JSON length LENGTH "${json}" camera ${key})
    if (NOT length EQUAL 3)
      message(FATAL_ERROR "camera.${key} has ${length} numbers, not 3\n${report}")
    endif ()
  endif ()
endforeach ()

string(JSON input_triangles GET "${json}" input_triangles)
string(JSON output_triangles GET "${json}" output_triangles)
string(JSON silhouette_triangles GET "${json}" silhouette_triangles)
string(JSON new_triangles GET "${json}" new_triangles)
string(JSON viewport_w GET "${json}" viewport 0)
string(JSON viewport_h GET "${json}" viewport 1)
if (DEFINED INPUT_TRIANGLES AND NOT input_triangles EQUAL INPUT_TRIANGLES)
  message(FATAL_ERROR "input_triangles is ${input_triangles}, not ${INPUT_TRIANGLES}\n${report}")
endif ()
if (DEFINED VIEWPORT AND NOT "${viewport_w},${viewport_h}" STREQUAL VIEWPORT)
  message(FATAL_ERROR "viewport is ${viewport_w},${viewport_h}, not ${VIEWPORT}\n${report}")
endif ()
if (silhouette_triangles LESS_EQUAL 0 OR new_triangles LESS_EQUAL 0)
  message(FATAL_ERROR "a framed mesh must have silhouette and new triangles\n${report}")
endif ()
math(EXPR expected_output "${input_triangles} - ${silhouette_triangles} + ${new_triangles}")
if (NOT output_triangles EQUAL expected_output)
  message(FATAL_ERROR "output_triangles ${output_triangles} is not input - silhouette + new = ${expected_output}\n${report}")
endif ()
if (DEFINED VIEW_ANGLE)
  string(JSON view_angle GET "${json}" camera view_angle)
  if (NOT view_angle EQUAL VIEW_ANGLE)
    message(FATAL_ERROR "camera.view_angle is ${view_angle}, not ${VIEW_ANGLE}\n${report}")
  endif ()
endif ()
if (DEFINED CAMERA_Z)
  string(REPLACE "," ";" range "${CAMERA_Z}")
  list(GET range 0 low)
  list(GET range 1 high)
  string(JSON camera_z GET "${json}" camera position 2)
  if (NOT (camera_z GREATER low AND camera_z LESS high))
    message(FATAL_ERROR "camera.position z is ${camera_z}, not in (${low}, ${high})\n${report}")
  endif ()
endif ()
