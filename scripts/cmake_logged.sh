#!/usr/bin/env bash
# Sourced by setup.sh, sanitize.sh and tsan.sh, with `here` set to the source
# folder: configure and build quietly, the output in a log that is shown only
# when the step fails (the script then exits with status 1).

# configure_logged NAME BUILD_DIR CMAKE_OPTIONS...: configures the source
# folder in BUILD_DIR (made if missing); the log is BUILD_DIR/NAME-configure.log,
# shown whole on failure.
# shellcheck disable=SC2154 # here: set by the sourcing script
configure_logged() {
  local name="$1" dir="$2"
  shift 2
  mkdir -p "$dir"
  cmake -S "$here" -B "$dir" "$@" >"$dir/$name-configure.log" 2>&1 ||
    { cat "$dir/$name-configure.log" >&2; exit 1; }
}

# build_logged NAME BUILD_DIR BUILD_OPTIONS...: cmake --build BUILD_DIR; the
# log is BUILD_DIR/NAME-build.log, its last 50 lines shown on failure.
build_logged() {
  local name="$1" dir="$2"
  shift 2
  cmake --build "$dir" "$@" >"$dir/$name-build.log" 2>&1 ||
    { tail -50 "$dir/$name-build.log" >&2; exit 1; }
}
