"""The README's C++ and Python programs against an installed tree, as a user
would run them (install.consumer, issue 17).

The README holds exactly one ```cpp, one ```cmake and one ```python block
(a fence line exactly "```cpp" and so on, up to a line exactly "```"). The
C++ program and its CMakeLists.txt are built against the prefix; both
programs run in a folder whose Data/ is the installed data folder, with X
(when DISPLAY is set) and with no X server through the installed OSMesa
library. Every run must exit 0 with no VTK error or warning on stderr and
write smoothed.png showing the bunny (10% to 80% of the pixels), the Python
program must print a count of new triangles above 0, and every image must
equal the first pixel for pixel: the filter's output drawn by a plain mapper
(C++) and the render-time mapper (Python) give the same image
(module.TestSmoothingMapper), so a program that skipped the smoothing, or
drew something else, differs.

Usage: RunReadmePrograms.py README.md PREFIX PYTHON_PACKAGE_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def fail(message):
    sys.exit("FAILED: " + message)


def readme_blocks(path):
    """The README's fenced blocks by language: {"cpp": [text, ...], ...}."""
    blocks = {}
    language, lines = None, []
    with open(path, encoding="utf-8") as text:
        for line in text:
            stripped = line.rstrip("\n")
            if language is None:
                match = re.fullmatch(r"```(\w*)", stripped)
                if match:
                    language, lines = match.group(1), []
            elif stripped == "```":
                blocks.setdefault(language, []).append("".join(lines))
                language = None
            else:
                lines.append(line)
    if language is not None:
        fail("the README's last ```%s block is not closed" % language)
    return blocks


def the_block(blocks, language):
    found = blocks.get(language, [])
    if len(found) != 1:
        fail("the README has %d ```%s blocks; install.consumer runs exactly one" %
             (len(found), language))
    return found[0]


def run(command, **kwargs):
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, check=False,
                          **kwargs)
    if done.returncode != 0:
        fail("%s exits %d:\n%s%s" % (" ".join(command), done.returncode, done.stdout,
                                     done.stderr))
    return done


def check_new_triangles(output, label):
    """The Python program's printed count of new triangles is above 0."""
    match = re.search(r"new triangles: (\d+)", output)
    if not match or int(match.group(1)) == 0:
        fail("%s prints no count of new triangles above 0: %s" % (label, output))
    print("%s: %s" % (label, match.group(0)))


def pixels_of(path):
    if not os.path.exists(path):
        fail("no " + path)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        fail(path + " is not a PNG image")
    values = [scalars.GetTuple(i)[:3] for i in range(scalars.GetNumberOfTuples())]
    return image.GetDimensions(), values


def check_image(path, reference, label):
    dimensions, values = pixels_of(path)
    background = values[0]
    covered = sum(1 for value in values if value != background) / len(values)
    print("%s: %dx%d, %.1f%% of the pixels show the bunny" %
          (label, dimensions[0], dimensions[1], 100.0 * covered))
    if not 0.1 < covered < 0.8:
        fail("%s: smoothed.png does not show the bunny" % label)
    if reference is None:
        return dimensions, values
    if dimensions != reference[0]:
        fail("%s: smoothed.png is %s, the first run's %s" % (label, dimensions, reference[0]))
    differing = sum(1 for a, b in zip(values, reference[1]) if a != b)
    print("%s: %d pixels differ from the first run's image" % (label, differing))
    if differing:
        fail("%s: the image differs from the first run's in %d pixels" % (label, differing))
    return reference


def main():
    readme, prefix, package, work = sys.argv[1:5]
    blocks = readme_blocks(readme)
    app = os.path.join(work, "readme_app")
    os.makedirs(app, exist_ok=True)
    with open(os.path.join(app, "smooth.cxx"), "w", encoding="utf-8") as out:
        out.write(the_block(blocks, "cpp"))
    with open(os.path.join(app, "CMakeLists.txt"), "w", encoding="utf-8") as out:
        out.write(the_block(blocks, "cmake"))
    folder = os.path.join(work, "readme_run")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "smooth.py"), "w", encoding="utf-8") as out:
        out.write(the_block(blocks, "python"))
    data = os.path.join(folder, "Data")
    if os.path.lexists(data):
        os.remove(data)
    os.symlink(os.path.join(prefix, "share", "SilhouetteSmoothing", "Data"), data)

    run(["cmake", "-S", app, "-B", os.path.join(app, "build"), "-DCMAKE_PREFIX_PATH=" + prefix,
         "-DCMAKE_BUILD_TYPE=Release"])
    run(["cmake", "--build", os.path.join(app, "build")])
    program = os.path.join(app, "build", "smooth")
    if not os.path.exists(program):
        fail("the README's CMakeLists.txt builds no program named smooth")

    no_x = dict(os.environ, LD_PRELOAD=os.path.join(prefix, "lib", "libsilhouette_osmesa.so"))
    no_x.pop("DISPLAY", None)
    with_x = dict(os.environ)
    ways = [("osmesa", no_x)]
    if os.environ.get("DISPLAY"):
        ways.insert(0, ("x", with_x))
    else:
        print("no DISPLAY: the programs run with OSMesa only")
    reference = None
    for way, environment in ways:
        for language, command in (("C++", [program]), ("Python", [sys.executable, "smooth.py"])):
            label = "%s (%s)" % (language, way)
            image = os.path.join(folder, "smoothed.png")
            if os.path.exists(image):
                os.remove(image)
            env = dict(environment, PYTHONPATH=package)
            done = run(command, cwd=folder, env=env)
            if re.search(r"ERROR|Warning", done.stderr):
                fail("%s writes VTK errors or warnings:\n%s" % (label, done.stderr))
            if language == "Python":
                check_new_triangles(done.stdout, label)
            reference = check_image(image, reference, label)
            shutil.copy(image, os.path.join(folder, "smoothed_%s_%s.png" % (language, way)))
    print("the README's programs: passed")


if __name__ == "__main__":
    main()
