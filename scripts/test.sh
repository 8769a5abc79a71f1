#!/usr/bin/env bash
# Sets up and builds like demo.sh, then runs the whole ctest suite; rendering
# tests get a private X server (xvfb-run) when there is no display.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=setup.sh
source "$here/scripts/setup.sh"

cd "$build"
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j "$jobs" "$@"
fi
exec ctest --output-on-failure -j "$jobs" "$@"
