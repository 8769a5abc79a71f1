"""The README's Python program runs as written (issue 17): the first
```python block of README.md, run by this interpreter in an empty folder
that has the repository's Data/ beside it, prints the new triangles and
writes smoothed.png with the bunny in it.

Usage: RunReadmeSnippet.py README.md DATA_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader

readme, data = sys.argv[1], sys.argv[2]
with open(readme, encoding="utf-8") as text:
    blocks = re.findall(r"```python\n(.*?)```", text.read(), re.S)
if not blocks:
    sys.exit("FAILED: the README has no ```python block")
with tempfile.TemporaryDirectory() as folder:
    os.symlink(os.path.abspath(data), os.path.join(folder, "Data"))
    script = os.path.join(folder, "smooth.py")
    with open(script, "w", encoding="utf-8") as out:
        out.write(blocks[0])
    done = subprocess.run([sys.executable, script], cwd=folder, capture_output=True, text=True,
                          timeout=300, check=False)
    print(done.stdout.strip())
    if done.returncode != 0:
        sys.exit("FAILED: the README's Python program exits %d: %s" % (done.returncode, done.stderr))
    match = re.search(r"new triangles: (\d+)", done.stdout)
    if not match or int(match.group(1)) == 0:
        sys.exit("FAILED: the program does not print a count of new triangles above 0")
    image = os.path.join(folder, "smoothed.png")
    if not os.path.exists(image):
        sys.exit("FAILED: no smoothed.png")
    reader = vtkPNGReader()
    reader.SetFileName(image)
    reader.Update()
    pixels = reader.GetOutput().GetPointData().GetScalars()
    background = pixels.GetTuple(0)[:3]
    covered = sum(1 for i in range(pixels.GetNumberOfTuples())
                  if pixels.GetTuple(i)[:3] != background)
    fraction = covered / pixels.GetNumberOfTuples()
    print("smoothed.png: %.1f%% of the pixels show the bunny" % (100.0 * fraction))
    if not 0.1 < fraction < 0.8:
        sys.exit("FAILED: the image does not show the bunny")
