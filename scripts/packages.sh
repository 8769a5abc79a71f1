#!/usr/bin/env bash
# Sourced by setup.sh, clang.sh and paraview.sh: one way to install Debian
# packages on the host.
#
#   install_missing TAG PACKAGE...
#
# installs those of the packages that are not installed yet (none: nothing
# runs, so it is safe to call again), as root or through sudo, and says what
# it installs on a line starting with TAG. Without root or sudo it stops with
# a one-line error.
install_missing() {
  local tag="$1"
  shift
  local missing=() package
  for package in "$@"; do
    # shellcheck disable=SC2016 # dpkg-query's own format, not the shell's
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ "${#missing[@]}" -eq 0 ] && return 0
  local sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
      echo "$tag: need root (or sudo) to install: ${missing[*]}" >&2
      exit 1
    fi
    sudo_cmd=(sudo)
  fi
  echo "$tag: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}
