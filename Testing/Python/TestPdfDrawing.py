"""`silhouette render --style lines -o DRAWING.pdf` (issue 16: vector output).

Checks, on the bundled torus seen from 60 degrees up and on a cube:
- the file is a PDF a reader takes: its cross-reference table gives each
  object's offset, startxref the table's, the stream its length; pdfinfo
  (poppler-utils) reads one page of the image's size at 96 pixels to the
  inch, and the title, non-ASCII letters and parentheses included;
- its paths are the SVG drawing's, point for point and in the same order,
  hidden ones (grey, dashed) first, then the visible ones (stroked, or
  filled outlines with --width-by-depth);
- rasterised at 96 dpi with pdftoppm, it draws what the SVG of the same view
  draws rasterised with rsvg-convert: of the dark pixels of each, at most
  0.4% lie farther than 2 pixels from the other's. The deliberately wrong
  variants, the PDF with the hidden lines drawn (--hidden dashed) against
  the SVG without them, and the PDF drawn upside down, must exceed that;
- --join-lines joins the cube's 9 edges into 3 paths or fewer;
- --progressive 3 --pdf writes sketch-01.pdf to sketch-03.pdf;
- errors: a .pdf with the shaded style, --pdf without --progressive, --svg
  with --pdf.
Usage: TestPdfDrawing.py SILHOUETTE_PROGRAM DATA_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import cli_checks  # beside this script
import drawing_checks  # beside this script

program, data, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = cli_checks.failures
check = cli_checks.check
SVG = "{http://www.w3.org/2000/svg}"
MAXIMUM_STRAY = 0.004  # as the SVG drawing's test against the PNG
RADIUS = 2


def run(*args):
    return cli_checks.run(program, *args)


def read_pdf(pdf_file):
    """Checks the file's structure; returns its page box, its content
    stream's text and its information dictionary's text."""
    with open(pdf_file, "rb") as f:
        pdf = f.read()
    problems = []
    if not (pdf.startswith(b"%PDF-1.4\n") and pdf.endswith(b"%%EOF\n")):
        problems.append("not a PDF 1.4 file")
    start = int(re.search(rb"startxref\n(\d+)\n%%EOF\n$", pdf).group(1))
    if pdf[start:start + 5] != b"xref\n":
        problems.append("startxref does not give the table's offset")
    count = int(re.match(rb"xref\n0 (\d+)\n", pdf[start:]).group(1))
    table = pdf[start:].split(b"\n", 2)[2]
    entries = [table[20 * i:20 * (i + 1)] for i in range(count)]
    if entries[0] != b"0000000000 65535 f \n" or any(len(e) != 20 for e in entries):
        problems.append("the table's entries are not of 20 bytes")
    for number in range(1, count):
        if not pdf[int(entries[number][:10]):].startswith(b"%d 0 obj\n" % number):
            problems.append("object %d is not at the offset the table gives" % number)
    stream = re.search(rb"<< /Length (\d+) >>\nstream\n", pdf)
    length = int(stream.group(1))
    content = pdf[stream.end():stream.end() + length]
    if not pdf[stream.end() + length:].startswith(b"\nendstream"):
        problems.append("the stream is not as long as /Length says")
    check(not problems, "%s: a PDF whose %d objects are where its table says (%s)"
          % (os.path.basename(pdf_file), count - 1, "; ".join(problems) or "ok"))
    box = [float(v) for v in re.search(rb"/MediaBox \[([^\]]*)\]", pdf).group(1).split()]
    info = pdf[int(entries[count - 1][:10]):start]
    return box, content.decode("ascii"), info


def upside_down(pdf_file):
    """The wrong variant: the same file with y not turned (the transformation
    to points without its minus sign, padded to the same length)."""
    with open(pdf_file, "rb") as f:
        pdf = f.read()
    turned = re.search(rb"0\.75 0 0 -0\.75 0 [\d.]+ cm", pdf).group(0)
    plain = b"0.75 0 0 0.75 0 0 cm"
    pdf = pdf.replace(turned, plain + b" " * (len(turned) - len(plain)), 1)
    target = pdf_file[:-4] + "_upside_down.pdf"
    with open(target, "wb") as f:
        f.write(pdf)
    return target


def pdf_paths(content):
    """The paths of the content stream: (group, points, paint) with group 0
    for the first q ... Q (the hidden lines), 1 for the second."""
    paths, points, group = [], [], -1
    for line in content.splitlines():
        words = line.split()
        if words and words[0] == "q":
            group += 1
        elif len(words) == 3 and words[2] in ("m", "l"):
            points.append((words[0], words[1]))
        elif line in ("S", "h f"):
            paths.append((group, points, line))
            points = []
    return paths


def svg_paths(svg_file):
    """The SVG's paths: (group, points) with group 0 for the hidden lines."""
    root = ElementTree.parse(svg_file).getroot()
    out = []
    for group, g in enumerate(root.iter(SVG + "g")):
        for p in g.iter(SVG + "path"):
            out.append((group, re.findall(r"[ML](-?[\d.]+) (-?[\d.]+)", p.get("d"))))
    return out


def raster_pdf(pdf_file):
    prefix = pdf_file[:-4] + "_pdf"
    subprocess.run([pdftoppm, "-r", "96", "-png", "-singlefile", pdf_file, prefix],
                   check=True, timeout=120)
    return prefix + ".png"


def raster_svg(svg_file):
    target = svg_file[:-4] + "_svg.png"
    subprocess.run([rsvg, "-b", "white", svg_file, "-o", target], check=True, timeout=120)
    return target


def compare_raster(name, pdf_file, hidden_pdf_file, svg_file):
    reference = drawing_checks.ink(raster_svg(svg_file))
    shares = []
    for source in (pdf_file, hidden_pdf_file, upside_down(pdf_file)):
        drawn = drawing_checks.ink(raster_pdf(source))
        shares.append(max(drawing_checks.stray(drawn, reference, RADIUS),
                          drawing_checks.stray(reference, drawn, RADIUS)))
    print("%s: stray dark pixels %.4f for the PDF, %.4f with the hidden lines, %.4f upside "
          "down (limit %.3f)" % (name, shares[0], shares[1], shares[2], MAXIMUM_STRAY))
    check(shares[0] <= MAXIMUM_STRAY, name + ": the rasterised PDF draws what the SVG draws")
    check(min(shares[1:]) > MAXIMUM_STRAY,
          name + ": the check fails with the hidden lines drawn, and upside down")


pdftoppm, pdfinfo, rsvg = (shutil.which(t) for t in ("pdftoppm", "pdfinfo", "rsvg-convert"))
check(pdftoppm is not None and pdfinfo is not None,
      "pdftoppm and pdfinfo are installed (scripts/setup.sh installs poppler-utils)")
check(rsvg is not None, "rsvg-convert is installed (scripts/setup.sh installs librsvg2-bin)")

# --- The torus: structure, the SVG's paths, the raster --------------------------
torus = os.path.join(data, "torus_24x12.vtp")
view = ["--style", "lines", "--size", "500x400", "--elevation", "60"]
for suffix, extra in (("", []), ("_hidden", ["--hidden", "dashed"]),
                      ("_depth", ["--width-by-depth"])):
    for extension in ("pdf", "svg"):
        target = os.path.join(work, "torus%s.%s" % (suffix, extension))
        code, _, err = run("render", torus, *view, *extra, "-o", target)
        check(code == 0, "render -o %s succeeds (%s)" % (os.path.basename(target), err.strip()))
if not failures:
    for suffix in ("", "_hidden", "_depth"):
        pdf_file, svg_file = (os.path.join(work, "torus%s.%s" % (suffix, e)) for e in ("pdf", "svg"))
        box, content, _ = read_pdf(pdf_file)
        check(box == [0, 0, 375, 300], "torus%s: the page is 500x400 pixels at 96 dpi (%s)"
              % (suffix, box))
        drawn = pdf_paths(content)
        paint = "h f" if suffix == "_depth" else "S"
        check(all(p == (paint if g == 1 else "S") for g, _, p in drawn),
              "torus%s: visible paths %s, hidden ones stroked" % (suffix, paint))
        written = [(g, points) for g, points, _ in drawn]
        print("torus%s: %d paths, %d hidden" % (suffix, len(written),
                                                 sum(1 for g, _ in written if g == 0)))
        check(written == svg_paths(svg_file) and len(written) > 2,
              "torus%s: the SVG's paths, point for point, in its order" % suffix)
    hidden_box, hidden_content, _ = read_pdf(os.path.join(work, "torus_hidden.pdf"))
    check("0.6 G" in hidden_content.split("Q")[0] and "] 0 d" in hidden_content.split("Q")[0],
          "the hidden lines are grey and dashed")
    if pdftoppm and rsvg:
        compare_raster("torus", os.path.join(work, "torus.pdf"),
                       os.path.join(work, "torus_hidden.pdf"), os.path.join(work, "torus.svg"))
        compare_raster("torus, width by depth", os.path.join(work, "torus_depth.pdf"),
                       os.path.join(work, "torus_hidden.pdf"),
                       os.path.join(work, "torus_depth.svg"))

# --- A CAD part: creases, borders, hidden lines, joined ------------------------
bracket = os.path.join(data, "bracket.stl")
bracket_view = ["--style", "lines", "--size", "600x450", "--hidden", "dashed", "--join-lines"]
targets = [os.path.join(work, "bracket." + e) for e in ("pdf", "svg")]
if all(run("render", bracket, *bracket_view, "-o", t)[0] == 0 for t in targets):
    written = [(g, points) for g, points, _ in pdf_paths(read_pdf(targets[0])[1])]
    print("bracket: %d paths, %d hidden" % (len(written), sum(1 for g, _ in written if g == 0)))
    check(written == svg_paths(targets[1]) and len(written) > 10,
          "bracket: the SVG's paths, point for point, in its order")
else:
    check(False, "render the bracket to PDF and SVG")

# --- The title: pdfinfo reads it -----------------------------------------------
odd = os.path.join(work, "drawing (\u00fc\u00df).pdf")
code, _, err = run("render", torus, "--style", "lines", "--size", "200x150", "-o", odd)
check(code == 0, "render to a name with parentheses and umlauts (%s)" % err.strip())
if code == 0 and pdfinfo:
    info = subprocess.run([pdfinfo, odd], capture_output=True, text=True, timeout=60).stdout
    print(info.strip())
    check("drawing (\u00fc\u00df).pdf" in info and re.search(r"Pages:\s+1\n", info) is not None,
          "pdfinfo reads one page and the title with its letters")
    check(re.search(r"Page size:\s+150 x 112.5 pts", info) is not None,
          "pdfinfo reads a page of 200x150 pixels at 96 dpi")

# A tab in the name is kept in both titles, as a control character is
# written '?' in both (the PDF's title wrote the tab as '?').
tabbed = os.path.join(work, "tab\tname")
for suffix in (".pdf", ".svg"):
    code, _, err = run("render", torus, "--style", "lines", "--size", "200x150",
                       "-o", tabbed + suffix)
    check(code == 0, "render to a name with a tab (%s)" % err.strip())
if pdfinfo and os.path.exists(tabbed + ".pdf") and os.path.exists(tabbed + ".svg"):
    info = subprocess.run([pdfinfo, tabbed + ".pdf"], capture_output=True, text=True,
                          timeout=60).stdout
    with open(tabbed + ".svg", encoding="utf-8") as svg:
        svg_title = re.search(r"<title>([^<]*)</title>", svg.read()).group(1)
    check("tab\tname.pdf" in info and "tab\tname.svg" in svg_title,
          "the tab kept in the PDF's and the SVG's titles")

# --- The cube: joined lines ----------------------------------------------------
cube_file = drawing_checks.write_cube(work)
cube_view = drawing_checks.CUBE_VIEW
counts = []
for extra in ([], ["--join-lines"]):
    target = os.path.join(work, "cube%s.pdf" % ("_joined" if extra else ""))
    code, _, err = run("render", cube_file, *cube_view, *extra, "-o", target)
    check(code == 0, "render the cube to %s (%s)" % (os.path.basename(target), err.strip()))
    if code == 0:
        counts.append(len(pdf_paths(read_pdf(target)[1])))
print("cube: paths", counts)
check(counts[:1] == [9] and len(counts) == 2 and 1 <= counts[1] <= 3,
      "the cube's 9 edges, joined into 3 paths or fewer")

# --- The progressive sketch ----------------------------------------------------
sketch = os.path.join(work, "sketch")
shutil.rmtree(sketch, ignore_errors=True)
code, _, err = run("render", torus, "--style", "lines", "--size", "200x150", "--progressive", "3",
                   "--pdf", "-o", sketch)
check(code == 0, "--progressive 3 --pdf succeeds (%s)" % err.strip())
if code == 0:
    names = sorted(os.listdir(sketch))
    check(names == ["sketch-01.pdf", "sketch-02.pdf", "sketch-03.pdf"],
          "three PDF drawings (%s)" % names)
    for name in names:
        read_pdf(os.path.join(sketch, name))

# --- Errors --------------------------------------------------------------------
code, _, err = run("render", torus, "-o", os.path.join(work, "shaded.pdf"))
check(code == 2 and "a drawing (.svg or .pdf) needs a line style" in err and err.count("\n") == 1,
      "a .pdf with the shaded style is refused in one line")
code, _, err = run("render", torus, "--style", "lines", "--pdf", "-o", os.path.join(work, "x.pdf"))
check(code == 2 and "'--pdf' goes with '--progressive'; for one drawing write '-o DRAWING.pdf'"
      in err, "--pdf alone is a usage error")
code, _, err = run("render", torus, "--style", "lines", "--progressive", "2", "--svg", "--pdf",
                   "-o", os.path.join(work, "both"))
check(code == 2 and "'--svg' and '--pdf' do not go together" in err,
      "--svg with --pdf is a usage error")

if failures:
    print("FAILED: %d check(s)" % len(failures))
    sys.exit(1)
print("all checks passed")
