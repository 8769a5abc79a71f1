#!/usr/bin/env bash
# Installs what the project needs on Debian bookworm (only the packages that
# are missing, so it is safe to run again), then configures and builds in
# build/ (Release). Sourced by demo.sh and test.sh; run alone to just build.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SILHOUETTE_BUILD_DIR:-$here/build}"

packages=(cmake make g++ pkg-config libvtk9-dev python3-dev libglm-dev libosd-dev libosmesa6-dev libx11-dev libgtest-dev assimp-testmodels
  librsvg2-bin xvfb xauth)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
      echo "setup: need root (or sudo) to install: ${missing[*]}" >&2
      exit 1
    fi
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs="$(nproc 2>/dev/null || echo 2)"
echo "setup: configuring and building in $build"
# shellcheck source=cmake_logged.sh
source "$here/scripts/cmake_logged.sh"
configure_logged setup "$build" -DCMAKE_BUILD_TYPE=Release
build_logged setup "$build" -j "$jobs"
echo "setup: built (logs in $build: setup-configure.log, setup-build.log)"
