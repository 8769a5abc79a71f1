#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run of the core's unit tests
# and the module's tests (our code instrumented; VTK and Mesa as installed).
# Leak detection is on for the tests that do not render, off for those that
# load Mesa (its driver's allocations would be reported as ours).
# Needs the packages scripts/setup.sh installs; builds in build-asan/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SILHOUETTE_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="$(nproc 2>/dev/null || echo 2)"

echo "sanitize: building the core and module tests with -fsanitize=address,undefined in $build"
mkdir -p "$build"
cmake -S "$here" -B "$build" -DSILHOUETTE_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  >"$build/sanitize-configure.log" 2>&1 || { cat "$build/sanitize-configure.log" >&2; exit 1; }
cmake --build "$build" -j "$jobs" --target silhouette_core_tests SilhouetteModuleTests \
  >"$build/sanitize-build.log" 2>&1 || { tail -50 "$build/sanitize-build.log" >&2; exit 1; }

cd "$build"
display=()
if [ -z "${DISPLAY:-}" ]; then
  display=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
export UBSAN_OPTIONS=print_stacktrace=1
ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure \
  -R '^core\.|^module\.Test(TopologyInvariants|BadInput)$'
ASAN_OPTIONS=detect_leaks=0 "${display[@]}" ctest --output-on-failure \
  -R '^module\.Test(OpenSubdivRefiner|FilterPipeline|SphereAccuracy|SmoothingImages|OrbitCoherence)$'
