#!/usr/bin/env bash
# Fuzzes with libFuzzer (clang), under AddressSanitizer and
# UndefinedBehaviorSanitizer, three targets, two at a time:
#   fuzz_core     the algorithm core alone: random meshes (repeated ids,
#                 non-manifold fans, inconsistent orientation, zero normals,
#                 1e-30 to 1e30) and views (Testing/Fuzz/FuzzSilhouetteSmoother.cpp)
#   fuzz_mesh_io  mesh files (.ply .obj .stl .vtp .vtk) read by the program's
#                 own code (Apps/MeshIO.cxx and its pre-checks), then smoothed
#                 by vtkSilhouetteSmoothingFilter for random cameras
#                 (Testing/Fuzz/FuzzMeshReadingAndFilter.cxx)
#   fuzz_progressive_strokes  random meshes and strokes through the progressive
#                 mesh, the edge classification and the brushes
#                 (Testing/Fuzz/FuzzProgressiveStrokes.cpp)
#
#   bash scripts/fuzz.sh [SECONDS]   fuzz each target SECONDS (default 30; CI: 30, a minute in all)
#
# Builds with CMake in build-fuzz/ (SILHOUETTE_FUZZ=ON; our code instrumented,
# VTK as installed); needs what scripts/setup.sh installs, and installs clang
# and its fuzzer runtime if they are missing. A finding is written to
# build-fuzz/artifacts/ and fails the script; the corpora stay in build-fuzz/
# and grow from run to run.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 0
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-30}"
# SILHOUETTE_FUZZ_SEED fixes libFuzzer's random seed (CI sets it, so that a
# run explores the same inputs in the same order every time); unset, each run
# explores new ones.
seed_option=()
if [ -n "${SILHOUETTE_FUZZ_SEED:-}" ]; then
  seed_option=(-seed="$SILHOUETTE_FUZZ_SEED")
fi
work="${SILHOUETTE_FUZZ_DIR:-$here/build-fuzz}"
jobs="$(nproc 2>/dev/null || echo 2)"

# shellcheck source=clang.sh
source "$here/scripts/clang.sh"

# -O1 -g1 (as in scripts/sanitize.sh): line tables suffice for the stack
# traces, and the build takes about half the time of RelWithDebInfo's -O2 -g.
echo "fuzz: building fuzz_core, fuzz_mesh_io and fuzz_progressive_strokes with clang (libFuzzer, ASan, UBSan) in $work"
mkdir -p "$work"
# A unity build, as in scripts/sanitize.sh.
cmake -S "$here" -B "$work" -DSILHOUETTE_FUZZ=ON -DBUILD_TESTING=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_UNITY_BUILD=ON \
  >"$work/fuzz-configure.log" 2>&1 ||
  { cat "$work/fuzz-configure.log" >&2; exit 1; }
cmake --build "$work" -j "$jobs" --target fuzz_core fuzz_mesh_io fuzz_progressive_strokes >"$work/fuzz-build.log" 2>&1 ||
  { tail -50 "$work/fuzz-build.log" >&2; exit 1; }

# Seeds for fuzz_mesh_io: small meshes, good and bad, each prefixed with its
# format byte (the order of Extensions in the target) and 48 parameter bytes.
seeds="$work/seeds-mesh"
rm -rf "$seeds"
mkdir -p "$seeds" "$work/corpus-core" "$work/corpus-mesh" "$work/corpus-strokes" "$work/artifacts"
for file in "$here"/Data/sphere_ico80.vtp "$here"/Testing/CLI/Meshes/* \
  "$here"/Testing/Data/BadInput/* "$here"/Testing/Fuzz/Seeds/*; do
  case "$file" in
    *.ply) format='\000' ;;
    *.obj) format='\001' ;;
    *.stl) format='\002' ;;
    *.vtp) format='\003' ;;
    *.vtk) format='\004' ;;
    *) continue ;;
  esac
  { printf "$format"; head -c 48 /dev/zero | tr '\0' '\200'; cat "$file"; } \
    >"$seeds/$(basename "$file")"
done

# An input is a hang after 60 s: generous, because a busy machine has been
# seen to stall one for 12 s that runs in 74 ms alone (a VTP header, in CI).
run() { # target corpus max_len [seeds]
  local target="$1" corpus="$2" max_len="$3"
  shift 3
  echo "fuzz: running $target for $seconds s"
  if ! (cd "$work/artifacts" && "$work/bin/$target" "$corpus" "$@" "${seed_option[@]}" -max_total_time="$seconds" \
    -max_len="$max_len" -timeout=60 -rss_limit_mb=1024 -print_final_stats=1 \
    >"$work/$target.log" 2>&1); then
    tail -60 "$work/$target.log" >&2
    echo "fuzz: $target found a problem; the input is in $work/artifacts" >&2
    exit 1
  fi
  # fuzz_mesh_io's reading process inherits libFuzzer's malloc limit: past
  # it, libFuzzer there starts an oom- artifact the child's file-size limit
  # leaves empty. The program turns that child's end into an error, as it
  # must; only artifacts with content are findings (and fail the run above).
  find "$work/artifacts" -maxdepth 1 -type f -empty -delete
  local runs rate
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/$target.log" | grep -o '[0-9]*$')
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$work/$target.log" | grep -o '[0-9]*$')
  echo "fuzz: $target: $runs inputs ($rate a second), no crash, no sanitizer report, no invariant broken"
}
# A fuzzer is one process on one core: fuzz_mesh_io runs on one core while
# the other two run one after the other on the other.
# VTK's readers leak on some error paths; see the suppression file.
LSAN_OPTIONS="suppressions=$here/Testing/Fuzz/lsan-vtk.supp:print_suppressions=0" \
  run fuzz_mesh_io "$work/corpus-mesh" 8192 "$seeds" &
mesh_io=$!
# Inputs it once failed on come first (Testing/Fuzz/Regressions).
run fuzz_core "$work/corpus-core" 2048 "$here/Testing/Fuzz/Regressions/core"
run fuzz_progressive_strokes "$work/corpus-strokes" 4096
wait "$mesh_io"
