"""The README's Python program runs as written (issue 17): the README's one
```python block, run by this interpreter with the build's package in an
empty folder that has the repository's Data/ beside it, prints a count of
new triangles above 0 and writes smoothed.png with the bunny in it. The
reading of the README and the checks are install.consumer's
(Testing/Consumer/RunReadmePrograms.py), which runs the same program
against the installed tree.

Usage: RunReadmeSnippet.py README.md DATA_DIR
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Consumer"))
from RunReadmePrograms import check_image, check_new_triangles, fail, readme_blocks, the_block  # noqa: E402

readme, data = sys.argv[1], sys.argv[2]
program = the_block(readme_blocks(readme), "python")
with tempfile.TemporaryDirectory() as folder:
    os.symlink(os.path.abspath(data), os.path.join(folder, "Data"))
    script = os.path.join(folder, "smooth.py")
    with open(script, "w", encoding="utf-8") as out:
        out.write(program)
    done = subprocess.run([sys.executable, script], cwd=folder, capture_output=True, text=True,
                          timeout=300, check=False)
    print(done.stdout.strip())
    if done.returncode != 0:
        fail("the README's Python program exits %d: %s" % (done.returncode, done.stderr))
    check_new_triangles(done.stdout, "the README's Python program")
    check_image(os.path.join(folder, "smoothed.png"), None, "smoothed.png")
