#!/usr/bin/env bash
# Sourced by fuzz.sh, sanitize.sh and tsan.sh: installs clang and its
# sanitizer runtimes when they are missing (the other packages come from
# setup.sh), and exports CC and CXX for the configure that follows. Clang
# builds the instrumented trees: libFuzzer is clang's, and with ASan, UBSan
# or TSan clang compiles our code in about three quarters of GCC's time
# (docs/testing.md).
# shellcheck source=packages.sh disable=SC2154 # `here`: set by the script that sources this one
source "$here/scripts/packages.sh"
install_missing clang clang libclang-rt-14-dev
export CC=clang CXX=clang++
