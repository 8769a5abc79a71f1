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
if [ -n "${SILHOUETTE:-}" ]; then
  silhouette="$SILHOUETTE"
else
  # shellcheck source=setup.sh
  source "$here/scripts/setup.sh"
  silhouette="$build/bin/silhouette"
fi
display=()
if [ -z "${DISPLAY:-}" ]; then
  display=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
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
"${display[@]}" /usr/bin/python3 - "$work" "$here/docs/figures/simplification.png" "$triangles" <<'PY'
import json, sys
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkImageActor, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2
import vtkmodules.vtkRenderingFreeType

work, out, triangles = sys.argv[1], sys.argv[2], sys.argv[3]
w, h = 560, 480
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(2 * w, 2 * h)
keep = []
for col, variant in enumerate(["plain", "aware"]):
    figures = json.load(open(f"{work}/{variant}.json"))
    title = ("plain quadric" if variant == "plain" else
             f"silhouette-aware, f = {figures['near_factor']:g}")
    label = (f"{title}, {figures['output_triangles']} triangles\n"
             f"outline off the original's: {figures['outline_mean_px']:.2f} px mean, "
             f"{figures['outline_max_px']:.2f} px max")
    for row, style in enumerate(["wireframe", "shaded"]):
        reader = vtkPNGReader()
        reader.SetFileName(f"{work}/{variant}_{style}.png")
        reader.Update()
        actor = vtkImageActor()
        actor.GetMapper().SetInputConnection(reader.GetOutputPort())
        renderer = vtkRenderer()
        renderer.SetViewport(col / 2, (1 - row) / 2, (col + 1) / 2, (2 - row) / 2)
        renderer.AddActor(actor)
        camera = renderer.GetActiveCamera()
        camera.ParallelProjectionOn()
        camera.SetFocalPoint((w - 1) / 2, (h - 1) / 2, 0)
        camera.SetPosition((w - 1) / 2, (h - 1) / 2, 1000)
        camera.SetParallelScale(h / 2)
        renderer.ResetCameraClippingRange()
        if row == 0:
            text = vtkTextActor()
            text.SetInput(label)
            text.GetTextProperty().SetFontSize(15)
            text.GetTextProperty().SetColor(0, 0, 0)
            text.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
            text.GetPositionCoordinate().SetValue(0.02, 0.89)
            renderer.AddActor2D(text)
            keep.append(text)
        window.AddRenderer(renderer)
        keep += [reader, actor, renderer]
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(out)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", out)
PY
