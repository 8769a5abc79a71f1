#!/usr/bin/env bash
# Draws docs/figures/simplification.png (issue 8): the bunny (Data/bunny.ply,
# 3,674 triangles) simplified to the same triangle count by plain quadric
# edge collapse and by the silhouette-aware rule of Mata et al. (f = 0.1 in
# the interval [1, 3] cells of a 128-cell proximity grid), for the framing
# camera zoomed 1.2x at 560x480; wireframes on top, shaded below, each labelled with its
# outline deviation from the original's outline (silhouette simplify
# --measure). Prints the figures of both runs.
# Usage: bash scripts/simplification_figure.sh [TRIANGLES]   (default 600)
# SILHOUETTE=path/to/silhouette uses that program instead of building build/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
triangles="${1:-600}"
# shellcheck source=figure_setup.sh
source "$here/scripts/figure_setup.sh"
size=560x480
input="$here/Data/bunny.ply"

for variant in plain aware; do
  extra=()
  [ "$variant" = plain ] && extra=(--plain)
  "${display[@]}" "$silhouette" simplify "$input" -o "$work/$variant.vtp" --triangles "$triangles" \
    --size "$size" --zoom 1.2 --measure --json "${extra[@]}" >"$work/$variant.json"
  cat "$work/$variant.json"
  # The framing camera of the original, so both panels share it exactly:
  # render frames on the mesh it draws, so pass the original's camera (and
  # the zoom: --view-angle would be lost, vtkRenderer::ResetCamera sets 30).
  camera=($(/usr/bin/python3 -c '
import json, subprocess, sys
out = subprocess.run([sys.argv[1], "smooth", sys.argv[2], "--json", "--size", sys.argv[3]],
                     capture_output=True, text=True, check=True).stdout
c = json.loads(out)["camera"]
print(*(["--camera-position"] + c["position"] + ["--focal-point"] + c["focal_point"] +
        ["--view-up"] + c["view_up"]))' \
    "$silhouette" "$input" "$size"))
  for style in wireframe shaded; do
    "${display[@]}" "$silhouette" render "$work/$variant.vtp" -o "$work/${variant}_$style.png" \
      --style "$style" --no-smoothing --size "$size" "${camera[@]}" --zoom 1.2 >/dev/null
  done
done

mkdir -p "$here/docs/figures"
labels=()
for variant in plain aware; do
  labels+=("$(/usr/bin/python3 -c '
import json, sys
f = json.load(open(sys.argv[1]))
title = "plain quadric" if sys.argv[2] == "plain" else "silhouette-aware, f = %g" % f["near_factor"]
print("%s, %d triangles\\noutline off the original\x27s: %.2f px mean, %.2f px max"
      % (title, f["output_triangles"], f["outline_mean_px"], f["outline_max_px"]))' \
    "$work/$variant.json" "$variant")")
done
"${display[@]}" /usr/bin/python3 "$here/scripts/compose_panels.py" \
  "$here/docs/figures/simplification.png" 2 \
  "$work/plain_wireframe.png" "${labels[0]}" "$work/aware_wireframe.png" "${labels[1]}" \
  "$work/plain_shaded.png" "" "$work/aware_shaded.png" ""
