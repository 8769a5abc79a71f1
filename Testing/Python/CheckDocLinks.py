"""The documentation's links hold (issue 17): every relative link of the
README, of docs/*.md and of the other Markdown files the repository keeps
names a file of the repository, and its #anchor, if any, a heading of that
file (GitHub's anchors: lower case, punctuation dropped, spaces to hyphens);
no link and no text points outside the repository (../shared, DESIGN.md).

Usage: CheckDocLinks.py SOURCE_DIR [FILE.md ...]
  With files, only those are checked (the test's wrong variant).
"""
import os
import re
import subprocess
import sys

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^(```|~~~)")


def github_anchor(heading):
    text = re.sub(r"`", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def prose_lines(path):
    """The lines of a Markdown file outside its code blocks."""
    inside = False
    with open(path, encoding="utf-8") as text:
        for number, line in enumerate(text, 1):
            if FENCE.match(line.lstrip()):
                inside = not inside
                continue
            if not inside:
                yield number, line


def anchors(path):
    found = set()
    counts = {}
    for _, line in prose_lines(path):
        match = HEADING.match(line)
        if match:
            anchor = github_anchor(match.group(1))
            # GitHub numbers repeated headings: name, name-1, name-2.
            seen = counts.get(anchor, 0)
            counts[anchor] = seen + 1
            found.add(anchor if seen == 0 else "%s-%d" % (anchor, seen))
    return found


def check(source, path):
    problems = []
    folder = os.path.dirname(path)
    for number, line in prose_lines(path):
        where = "%s:%d" % (os.path.relpath(path, source), number)
        if "../shared" in line or "DESIGN.md" in line:
            problems.append("%s points outside the repository: %s" % (where, line.strip()))
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue  # http:, https:, mailto:
            name, _, anchor = target.partition("#")
            linked = os.path.normpath(os.path.join(folder, name)) if name else path
            if not os.path.abspath(linked).startswith(os.path.abspath(source) + os.sep):
                problems.append("%s links outside the repository: %s" % (where, target))
            elif not os.path.exists(linked):
                problems.append("%s links to a missing file: %s" % (where, target))
            elif anchor and linked.endswith(".md") and anchor not in anchors(linked):
                problems.append("%s links to a missing heading: %s" % (where, target))
    return problems


def main():
    source = os.path.abspath(sys.argv[1])
    files = [os.path.abspath(f) for f in sys.argv[2:]]
    if not files:
        tracked = subprocess.run(["git", "-C", source, "ls-files", "*.md"], capture_output=True,
                                 text=True, check=False)
        if tracked.returncode == 0 and tracked.stdout.strip():
            # The wrong variant's page is broken on purpose.
            files = [os.path.join(source, f) for f in tracked.stdout.split()
                     if f != "Testing/Data/BrokenLinks.md"]
        else:  # a source tree without git: the README and docs/
            files = [os.path.join(source, "README.md")] + [
                os.path.join(source, "docs", f) for f in sorted(os.listdir(os.path.join(source, "docs")))
                if f.endswith(".md")]
    problems = []
    for path in files:
        problems += check(source, path)
    for problem in problems:
        print(problem)
    print("%d Markdown files checked, %d problems" % (len(files), len(problems)))
    if problems:
        sys.exit("FAILED: %d broken or outside links" % len(problems))


if __name__ == "__main__":
    main()
