#!/usr/bin/env bash
# Sourced by fuzz.sh, sanitize.sh and tsan.sh: installs clang and its
# sanitizer runtimes when they are missing (the other packages come from
# setup.sh), and exports CC and CXX for the configure that follows. Clang
# builds the instrumented trees: libFuzzer is clang's, and with ASan, UBSan
# or TSan clang compiles our code in about three quarters of GCC's time
# (docs/testing.md).
clang_missing=()
for package in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    clang_missing+=("$package")
done
if [ "${#clang_missing[@]}" -gt 0 ]; then
  clang_sudo=()
  [ "$(id -u)" -ne 0 ] && clang_sudo=(sudo)
  echo "clang: installing ${clang_missing[*]}"
  DEBIAN_FRONTEND=noninteractive "${clang_sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${clang_sudo[@]}" apt-get install -y -qq --no-install-recommends \
    "${clang_missing[@]}" >/dev/null
fi
export CC=clang CXX=clang++
