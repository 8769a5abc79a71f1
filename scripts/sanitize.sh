#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run of the test suite (our
# code instrumented, built with clang; VTK and Mesa as installed): the core's
# unit tests, the module's tests, and the `silhouette` program's tests that
# do not render (help, smooth, read, generate and bad input: every file
# reader and pre-check). Leak detection is on for the tests that do not
# render, off for those that load Mesa (its driver's allocations would be
# reported as ours); for the program, leaks whose allocation runs through
# VTK are suppressed (VTK's readers leak on some error paths;
# Testing/Fuzz/lsan-vtk.supp). The program's tests that render (render,
# view, figure, compare, OSMesa) are left to scripts/test.sh.
# Needs the packages scripts/setup.sh installs (and installs clang, as
# fuzz.sh does); builds in build-asan/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SILHOUETTE_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="$(nproc 2>/dev/null || echo 2)"

started=$SECONDS
echo "sanitize: building the tests and the program with -fsanitize=address,undefined in $build"
meshes="${SILHOUETTE_BUILD_DIR:-$here/build}/real-meshes"
bash "$here/scripts/real-meshes.sh" "$meshes"
# -O1 -g1: the optimisation AddressSanitizer recommends, and line tables
# (enough for its stack traces) instead of full debug information: the build
# takes half the time of -O2 -g, and the tests about as long. Clang rather
# than GCC: three quarters of the build time, and the tests took 302 s
# against GCC's 353 s.
# shellcheck source=clang.sh
source "$here/scripts/clang.sh"
# shellcheck source=cmake_logged.sh
source "$here/scripts/cmake_logged.sh"
# A unity build (CMake joins each target's files in batches, so VTK's
# headers are parsed once per batch, not once per file): 239 s against 306 s
# for this build on 2 cores. The module tests are left out of it (their
# files share helper names), and the release build keeps one file per
# object, so that a file missing an include still fails there.
configure_logged sanitize "$build" -DSILHOUETTE_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
  -DSILHOUETTE_REAL_MESHES_DIR="$meshes"
build_logged sanitize "$build" -j "$jobs" --target silhouette_core_tests visibility_benchmark fold_guard_benchmark SilhouetteModuleTests silhouette MeasureRun
echo "sanitize: built in $((SECONDS - started)) s"

cd "$build"
display=()
if [ -z "${DISPLAY:-}" ]; then
  display=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
fi
export UBSAN_OPTIONS=print_stacktrace=1
started=$SECONDS
ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j "$jobs" \
  -R '^core\.|^module\.Test(TopologyInvariants|NoFolds|BadInput|HostileMeshes|VisibilityMethod|BoundaryCurveSmoothing|FaceSilhouetteLines|PNTriangleFilter|ProgressiveMeshFilter|StylizedStrokes|LineVisibilityFilter|OutlineDeviation|CreaseAndBorderLines|AbortAtHalf)$'
ASAN_OPTIONS=detect_leaks=0 "${display[@]}" ctest --output-on-failure -j "$jobs" \
  -R '^module\.Test(OpenSubdivRefiner|OpenSubdivRefinerInput|FilterPipeline|SphereAccuracy|SmoothingImages|OrbitCoherence|FeatureCurves|AssetMeshes|AssetImages|LineDrawingAccuracy)$'
echo "sanitize: core and module tests in $((SECONDS - started)) s"
started=$SECONDS
# The program reads files in a child process (Apps/IO/SandboxedReading.h),
# which under ASan has no address-space limit (ASan reserves terabytes):
# allocations past 1 GiB fail instead, and a failed allocation throws
# std::bad_alloc there as it does in the normal build; a reader's
# segmentation fault ends the child by its signal, not by ASan's report.
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:max_allocation_size_mb=1024:handle_segv=0 \
  LSAN_OPTIONS="suppressions=$here/Testing/Fuzz/lsan-vtk.supp:print_suppressions=0" \
  ctest --output-on-failure -j "$jobs" \
  -R '^cli\.(help|smooth\.|read\.|generate\.|bad\.)' \
  -E 'render|view|image|figure|compare|backend|osmesa'
echo "sanitize: program tests (no rendering) in $((SECONDS - started)) s"
