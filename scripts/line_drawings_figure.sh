#!/usr/bin/env bash
# Draws the line-drawing figures (issue 16), each with hidden lines removed,
# as `silhouette render` draws them today:
# - docs/figures/line_drawings.png, the README's: the coarse bunny in lines
#   and with the charcoal brush, the bracket with its hidden lines dashed,
#   and assimp's spider (assimp-testmodels), 400x330 each;
# - docs/figures/strokes_STYLE.png, the five line styles of the coarse bunny
#   at 512x420 (docs/other-systems.md);
# - docs/figures/bracket_lines.png, the bracket's SVG drawing with hidden
#   lines dashed and widths by depth, rasterised with rsvg-convert.
# SILHOUETTE=path/to/silhouette uses that program instead of building build/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=figure_setup.sh
source "$here/scripts/figure_setup.sh"
figures="$here/docs/figures"
mkdir -p "$figures"
bunny="$here/Data/bunny_coarse.ply"
bracket="$here/Data/bracket.stl"
spider=/usr/share/assimp/models/OBJ/spider.obj
[ -f "$spider" ] || { echo "line_drawings_figure: $spider is missing (apt-get install assimp-testmodels)" >&2; exit 1; }

draw() { # OUTPUT INPUT OPTION...
  local output="$1" input="$2"
  shift 2
  "${display[@]}" "$silhouette" render "$input" -o "$output" "$@" >/dev/null
}

for style in lines charcoal lazy hand rough; do
  draw "$figures/strokes_$style.png" "$bunny" --style "$style" --size 512x420 --zoom 1.35
done
draw "$work/bracket.svg" "$bracket" --style lines --azimuth 30 --elevation 25 --hidden dashed \
  --width-by-depth --size 800x600
rsvg-convert -b white "$work/bracket.svg" -o "$figures/bracket_lines.png"

draw "$work/bunny_lines.png" "$bunny" --style lines --size 400x330 --zoom 1.1
draw "$work/bunny_charcoal.png" "$bunny" --style charcoal --size 400x330 --zoom 1.1
draw "$work/bracket.png" "$bracket" --style lines --azimuth 30 --elevation 25 --hidden dashed \
  --size 400x330
draw "$work/spider.png" "$spider" --style lines --elevation 30 --size 400x330 --zoom 1.3
"${display[@]}" /usr/bin/python3 "$here/scripts/compose_panels.py" "$figures/line_drawings.png" 4 \
  "$work/bunny_lines.png" "lines: the smoothed silhouette" \
  "$work/bunny_charcoal.png" "the charcoal brush (Kim and Choe)" \
  "$work/bracket.png" "creases and borders, hidden lines dashed" \
  "$work/spider.png" "assimp's spider, 1,368 triangles"
echo "line_drawings_figure: wrote $figures/line_drawings.png, strokes_*.png, bracket_lines.png"
