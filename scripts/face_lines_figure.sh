#!/usr/bin/env bash
# Draws docs/figures/face_lines.png (issue 8, Xing's Fig. 6): the face-based
# silhouette (vtkFaceSilhouetteLines: `render --style lines --no-smoothing`)
# next to the smoothed one (the smoothing filter's second port: `render
# --style lines`), for the coarse bunny and the 80-triangle icosphere, with
# the framing camera at 480x400.
# SILHOUETTE=path/to/silhouette uses that program instead of building build/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=figure_setup.sh
source "$here/scripts/figure_setup.sh"

panels=()
for mesh in bunny_coarse sphere_ico80; do
  input="$here/Data/$mesh.ply"
  [ -f "$input" ] || input="$here/Data/$mesh.vtp"
  triangles="$("$silhouette" smooth "$input" --json | /usr/bin/python3 -c \
    'import json, sys; print(json.load(sys.stdin)["input_triangles"])')"
  "${display[@]}" "$silhouette" render "$input" -o "$work/${mesh}_face.png" --style lines \
    --no-smoothing --size 480x400 --elevation 20 >/dev/null
  "${display[@]}" "$silhouette" render "$input" -o "$work/${mesh}_smooth.png" --style lines \
    --size 480x400 --elevation 20 >/dev/null
  panels+=("$work/${mesh}_face.png" "face-based silhouette, $triangles triangles\\n(vtkFaceSilhouetteLines)")
  panels+=("$work/${mesh}_smooth.png" "smoothed silhouette, 0.5 px\\n(vtkSilhouetteSmoothingFilter, port 1)")
done
mkdir -p "$here/docs/figures"
"${display[@]}" /usr/bin/python3 "$here/scripts/compose_panels.py" \
  "$here/docs/figures/face_lines.png" 2 "${panels[@]}"
