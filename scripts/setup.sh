#!/usr/bin/env bash
# Installs what the project needs on Debian bookworm (only the packages that
# are missing, so it is safe to run again), then configures and builds in
# build/ (Release). Sourced by demo.sh and test.sh; run alone to just build.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SILHOUETTE_BUILD_DIR:-$here/build}"

packages=(cmake make g++ pkg-config libvtk9-dev python3-dev libglm-dev libosd-dev libosmesa6-dev libx11-dev libgtest-dev assimp-testmodels
  librsvg2-bin poppler-utils xvfb xauth)

# shellcheck source=packages.sh
source "$here/scripts/packages.sh"
install_missing setup "${packages[@]}"

jobs="$(nproc 2>/dev/null || echo 2)"
echo "setup: configuring and building in $build"
# shellcheck source=cmake_logged.sh
source "$here/scripts/cmake_logged.sh"
configure_logged setup "$build" -DCMAKE_BUILD_TYPE=Release
build_logged setup "$build" -j "$jobs"
echo "setup: built (logs in $build: setup-configure.log, setup-build.log)"
