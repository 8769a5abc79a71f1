#!/usr/bin/env bash
# Sets up and builds like demo.sh, then runs the whole ctest suite; rendering
# tests get a private X server (xvfb-run) when there is no display. -noreset:
# an X server resets when its last client leaves, and a test connecting
# during the reset is refused (python.package was, twice in a row, in CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=setup.sh
source "$here/scripts/setup.sh"

# The real meshes of module.TestNoFolds and the evaluation (downloaded once).
bash "$here/scripts/real-meshes.sh" "$build/real-meshes"

cd "$build"
# A failed test runs once more: a busy Xvfb has been seen to refuse an X
# connection for a moment, and VTK aborts when that happens inside a test
# that renders. A test that fails twice fails the run; the first failure's
# output stays in the log.
retry=(--repeat until-pass:2)
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j "$jobs" "${retry[@]}" "$@"
fi
exec ctest --output-on-failure -j "$jobs" "${retry[@]}" "$@"
