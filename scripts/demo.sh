#!/usr/bin/env bash
# The main job on the bundled data: smooth the coarse Stanford bunny for the
# default camera, print the figures, and write before/after images to out/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=setup.sh
source "$here/scripts/setup.sh"

out="$here/out"
mkdir -p "$out"
silhouette="$build/bin/silhouette"
bunny="$here/Data/bunny_coarse.ply"
display=()
if [ -z "${DISPLAY:-}" ]; then
  display=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi

"$silhouette" smooth "$bunny" -o "$out/bunny_smoothed.vtp"
"${display[@]}" "$silhouette" render "$bunny" --no-smoothing -o "$out/bunny_before.png" >/dev/null
"${display[@]}" "$silhouette" render "$bunny" -o "$out/bunny_after.png" >/dev/null
"${display[@]}" "$silhouette" render "$bunny" --style new-geometry -o "$out/bunny_new_geometry.png" >/dev/null
echo "demo: wrote $out/bunny_before.png, $out/bunny_after.png, $out/bunny_new_geometry.png and $out/bunny_smoothed.vtp"
