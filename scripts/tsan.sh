#!/usr/bin/env bash
# ThreadSanitizer run (our code instrumented; VTK as installed): the core's
# unit tests, whose parallel loops run on std::threads here
# (core.SilhouetteSmoother.ThreadsGiveTheSerialResult), and the module's
# tests that do not render, module.TestConcurrentFilters among them (four
# threads, each with its own filters). VTK's SMP back-end is sequential for
# the run (VTK_SMP_BACKEND_IN_USE): TSan cannot see TBB's uninstrumented
# synchronisation, and would report its hand-offs as races. So the threads
# are ours: TestConcurrentFilters' and the core tests'; the other module
# tests run single-threaded here and look for nothing but are cheap, except
# TestHostileMeshes (3.5 minutes under TSan), which is left out. Any report
# fails the run (halt_on_error).
# Needs the packages scripts/setup.sh installs; builds in build-tsan/.
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
# shellcheck source=cmake_logged.sh
source "$here/scripts/cmake_logged.sh"
# -O1 -g1 as in scripts/sanitize.sh: line tables suffice for the reports.
configure_logged tsan "$build" -DSILHOUETTE_SANITIZE_THREAD=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
build_logged tsan "$build" -j "$jobs" --target silhouette_core_tests SilhouetteModuleTests
echo "tsan: built in $((SECONDS - started)) s"

cd "$build"
started=$SECONDS
export VTK_SMP_BACKEND_IN_USE=Sequential
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
ctest --output-on-failure -j "$jobs" \
  -E 'benchmark' -R '^core\.|^module\.Test(ConcurrentFilters|TopologyInvariants|BadInput|VisibilityMethod|BoundaryCurveSmoothing|FaceSilhouetteLines|PNTriangleFilter|ProgressiveMeshFilter|StylizedStrokes)$'
echo "tsan: core and module tests in $((SECONDS - started)) s"
