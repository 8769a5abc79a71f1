"""`silhouette figure --plot` draws its series (the sphere's timings): the
red (coarse + smoothing) and blue (fine) series' colours cover more than a
few pixels outside the legend (the top-left corner, where each colour has a
short sample line). The plot of VTK 9.1's chart read back after one render
had the axes, the legend and no curve: 0 pixels of either outside the
legend. (The grey series shares its colour with the text's anti-aliasing:
1,394 such pixels in the empty plot, so it is counted, not checked.)
Usage: TestFigurePlot.py SILHOUETTE_PROGRAM WORK_DIR
"""
import os
import sys

import cli_checks  # beside this script
from vtkmodules.vtkIOImage import vtkPNGReader

program, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
check = cli_checks.check
plot = os.path.join(work, "plot.png")
code, _, err = cli_checks.run(program, "figure", "sphere", "-o", os.path.join(work, "panels.png"),
                              "--plot", plot, "--size", "200x200", "--frames", "2",
                              "--fine-level", "2")
check(code == 0, "figure --plot runs (%s)" % err.strip())
if code == 0:
    reader = vtkPNGReader()
    reader.SetFileName(plot)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    colours = {"coarse": (110, 110, 110), "coarse + smoothing": (210, 30, 30),
               "fine": (30, 70, 200)}
    counts = dict.fromkeys(colours, 0)
    for y in range(height):
        for x in range(width):
            if x < 220 and y > height - 90:  # the legend (rows count from the bottom)
                continue
            pixel = tuple(int(scalars.GetComponent(y * width + x, c)) for c in range(3))
            for name, colour in colours.items():
                if all(abs(pixel[c] - colour[c]) <= 40 for c in range(3)):
                    counts[name] += 1
    print("pixels of each series outside the legend:", counts)
    for name in ("coarse + smoothing", "fine"):
        check(counts[name] > 50, "the plot draws the %s series" % name)
if cli_checks.failures:
    print("FAILED: %d check(s)" % len(cli_checks.failures))
