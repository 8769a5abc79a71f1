"""A Python example's image against its baseline, and a deliberately wrong
variant of the example that must not match it (issue 17).

Usage: TestExampleImage.py EXAMPLE.py BASELINE.png WORK_DIR MAXIMUM RIGHT WRONG [ARG...]

The example runs with ARGs, an "{out}" among them standing for its output
image. The wrong variant is the example's text with the line RIGHT replaced
by WRONG (the line must be there: a changed example fails loudly). Pixels
are counted as differing when any channel differs; the example's image may
differ from the baseline in at most MAXIMUM pixels, the wrong variant's in
more. Without a baseline the test fails and says where the image to check
and copy is.
"""
import os
import subprocess
import sys

# The program's image tests count differing pixels the same way.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "CLI"))
import differing_pixels  # noqa: E402


def differing(a_path, b_path):
    try:
        return differing_pixels.differing(a_path, b_path)
    except ValueError as error:
        sys.exit("FAILED: comparing '%s' with '%s': %s" % (a_path, b_path, error))


def run(script, arguments, image, only_the_image=False):
    """Runs the script; the wrong variant (only_the_image) needs to write its
    image only (what the example prints after it may not hold for it)."""
    command = [sys.executable, script] + [a.replace("{out}", image) for a in arguments]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False)
    if (done.returncode != 0 and not only_the_image) or not os.path.exists(image):
        sys.exit("FAILED: %s exits %d without its image: %s"
                 % (os.path.basename(script), done.returncode, done.stderr.strip()))


def main():
    example, baseline, work, maximum, right, wrong = sys.argv[1:7]
    arguments = sys.argv[7:]
    maximum = int(maximum)
    os.makedirs(work, exist_ok=True)
    name = os.path.splitext(os.path.basename(example))[0]
    image = os.path.join(work, name + ".png")
    run(example, arguments, image)
    if not os.path.exists(baseline):
        sys.exit("FAILED: no baseline %s; look at %s and copy it there" % (baseline, image))
    count = differing(image, baseline)
    print("%s: %d pixels differ from %s (limit %d)" % (name, count, baseline, maximum))

    with open(example, encoding="utf-8") as text:
        source = text.read()
    if source.count(right) != 1:
        sys.exit("FAILED: the line %r is not in %s once: the wrong variant needs it" % (right, example))
    wrong_script = os.path.join(work, name + "_wrong.py")
    with open(wrong_script, "w", encoding="utf-8") as out:
        out.write(source.replace(right, wrong))
    wrong_image = os.path.join(work, name + "_wrong.png")
    run(wrong_script, arguments, wrong_image, only_the_image=True)
    wrong_count = differing(wrong_image, baseline)
    print("wrong variant (%r): %d pixels differ" % (wrong, wrong_count))

    if count > maximum:
        sys.exit("FAILED: %d pixels differ from the baseline (limit %d); the image is %s"
                 % (count, maximum, image))
    if wrong_count <= maximum:
        sys.exit("FAILED: the check cannot fail: the wrong variant differs in only %d pixels"
                 % wrong_count)


main()
