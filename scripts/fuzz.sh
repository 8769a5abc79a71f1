#!/usr/bin/env bash
# Fuzzes the algorithm core with libFuzzer (clang): random meshes and views
# through the whole smoothing pass (Testing/Fuzz/FuzzSilhouetteSmoother.cpp),
# then random meshes and strokes through the progressive mesh, the edge
# classification and the brushes (Testing/Fuzz/FuzzProgressiveStrokes.cpp),
# each for SECONDS, under AddressSanitizer and UndefinedBehaviorSanitizer.
#   bash scripts/fuzz.sh [SECONDS]     (default 30)
# Installs clang and its fuzzer runtime if they are missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-30}"
work="${SILHOUETTE_FUZZ_DIR:-$here/build-fuzz}"

missing=()
for package in clang libclang-rt-14-dev libglm-dev; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

mkdir -p "$work/corpus"
echo "fuzz: building the core fuzzer with clang (libFuzzer, ASan, UBSan)"
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I "$here/Filters/Core" "$here/Testing/Fuzz/FuzzSilhouetteSmoother.cpp" \
  "$here"/Filters/Core/*.cpp -o "$work/fuzz_core"
echo "fuzz: running for $seconds s"
"$work/fuzz_core" "$work/corpus" -max_total_time="$seconds" -max_len=2048 -timeout=5 \
  -print_final_stats=1 >"$work/fuzz.log" 2>&1 || { tail -40 "$work/fuzz.log" >&2; exit 1; }
runs=$(grep -o 'Done [0-9]* runs' "$work/fuzz.log" | grep -o '[0-9]*' || echo 0)
echo "fuzz: $runs inputs, no crash, no sanitizer report, no invariant broken"

mkdir -p "$work/corpus_strokes"
echo "fuzz: building the progressive-mesh and strokes fuzzer"
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I "$here/Filters/Core" "$here/Testing/Fuzz/FuzzProgressiveStrokes.cpp" \
  "$here"/Filters/Core/*.cpp -o "$work/fuzz_strokes"
echo "fuzz: running for $seconds s"
"$work/fuzz_strokes" "$work/corpus_strokes" -max_total_time="$seconds" -max_len=2048 -timeout=5 \
  -print_final_stats=1 >"$work/fuzz_strokes.log" 2>&1 || { tail -40 "$work/fuzz_strokes.log" >&2; exit 1; }
runs=$(grep -o 'Done [0-9]* runs' "$work/fuzz_strokes.log" | grep -o '[0-9]*' || echo 0)
echo "fuzz: $runs inputs, no crash, no sanitizer report, no invariant broken"
