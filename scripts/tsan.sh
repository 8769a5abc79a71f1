#!/usr/bin/env bash
# ThreadSanitizer run (our code instrumented, built with clang; VTK as
# installed): the core's unit tests, whose parallel loops run on std::threads
# here (core.SilhouetteSmoother.ThreadsGiveTheSerialResult), and nine module
# tests that do not render, module.TestConcurrentFilters among them (four
# threads, each with its own filters); only those nine are built. VTK's SMP
# back-end is sequential for the run (VTK_SMP_BACKEND_IN_USE): TSan cannot
# see TBB's uninstrumented synchronisation, and would report its hand-offs as
# races. So the threads are ours: TestConcurrentFilters', the core tests',
# and the index builds that a prepared mesh runs on a thread of its own
# (PreparedMesh.h) in every test. TestHostileMeshes (3.5 minutes under TSan)
# is left out. Any report fails the run (halt_on_error).
# Needs the packages scripts/setup.sh installs (and installs clang, as
# fuzz.sh does); builds in build-tsan/.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 0
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SILHOUETTE_TSAN_BUILD_DIR:-$here/build-tsan}"
jobs="$(nproc 2>/dev/null || echo 2)"

started=$SECONDS
echo "tsan: building the core and module tests with -fsanitize=thread in $build"
# shellcheck source=clang.sh
source "$here/scripts/clang.sh"
# shellcheck source=cmake_logged.sh
source "$here/scripts/cmake_logged.sh"
# -O1 -g1 as in scripts/sanitize.sh: line tables suffice for the reports.
# Only the module tests it runs are built (SILHOUETTE_MODULE_TESTS).
module_tests="TestConcurrentFilters;TestTopologyInvariants;TestBadInput;TestVisibilityMethod"
module_tests+=";TestBoundaryCurveSmoothing;TestFaceSilhouetteLines;TestPNTriangleFilter"
module_tests+=";TestProgressiveMeshFilter;TestStylizedStrokes"
# A unity build, as in scripts/sanitize.sh.
configure_logged tsan "$build" -DSILHOUETTE_SANITIZE_THREAD=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSILHOUETTE_MODULE_TESTS="$module_tests" \
  -DCMAKE_UNITY_BUILD=ON
build_logged tsan "$build" -j "$jobs" --target silhouette_core_tests SilhouetteModuleTests
echo "tsan: built in $((SECONDS - started)) s"

cd "$build"
started=$SECONDS
export VTK_SMP_BACKEND_IN_USE=Sequential
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
ctest --output-on-failure -j "$jobs" -E 'benchmark|osmesa' -R '^core\.|^module\.Test'
echo "tsan: core and module tests in $((SECONDS - started)) s"
