"""The documentation's links hold (issue 17): every relative link of the
README, of docs/*.md and of the other Markdown files the repository keeps
(inline links and images, with or without a title or angle brackets, over
line breaks; reference definitions) names a file git keeps (any file, when
the tree is not a git checkout), and its #anchor, if any, a heading of that
file (GitHub's anchors: lower case, punctuation dropped, spaces to
hyphens); a path in the text (a word that starts with ../) names such a
file too, and neither leads outside the repository: a clone has nothing
there. Code blocks and
code spans are not text.

Usage: CheckDocLinks.py SOURCE_DIR [FILE.md ...]
  With files, only those are checked (the test's wrong variant).
"""
import functools
import os
import re
import subprocess
import sys
import urllib.parse

# [text](target) or ![alt](target), the target bare or in <>, an optional
# "title"; the text may run over lines (no blank line in it).
INLINE = re.compile(r"!?\[(?:[^\[\]]|\n(?!\n))*?\]\(\s*(<[^>\n]*>|[^)\s]+)(?:\s+\"[^\"]*\")?\s*\)")
DEFINITION = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>\n]*>|\S+)", re.M)
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^(```|~~~)")
# A path in the text: ../ once or more, then a name.
TEXT_PATH = re.compile(r"(?<![\w/.])((?:\.\./)+[\w.-][\w./-]*)")
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1", re.S)


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


@functools.lru_cache(maxsize=None)
def anchors(path):  # read once per file, however many links name it
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


def prose(path):
    """The file's text outside code blocks and code spans, with its line
    numbers kept (code is blanked, not removed)."""
    kept = []
    for number, line in prose_lines(path):
        while len(kept) < number - 1:
            kept.append("")
        kept.append(line.rstrip("\n"))
    text = "\n".join(kept)
    return CODE_SPAN.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def inside(source, path):
    """Whether `path` lies in the repository at `source`."""
    relative = os.path.relpath(os.path.normpath(path), source)
    return relative != ".." and not relative.startswith(".." + os.sep)


def kept(source, path, tracked):
    """Whether `path` (inside the repository) exists and git keeps it, or
    exists, when the tree is not a git checkout."""
    return os.path.exists(path) and (
        tracked is None or os.path.relpath(path, source) in tracked)


def check(source, path, tracked):
    problems = []
    folder = os.path.dirname(path)
    text = prose(path)
    # The paths of the text itself: links and definitions are checked below.
    blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))
    words = DEFINITION.sub(blank, INLINE.sub(blank, text))
    for number, line in enumerate(words.split("\n"), 1):
        for named in (found.rstrip(".,;:") for found in TEXT_PATH.findall(line)):
            where = "%s:%d" % (os.path.relpath(path, source), number)
            named_path = os.path.normpath(os.path.join(folder, named.split("#")[0]))
            if not inside(source, named_path):
                problems.append("%s points outside the repository: %s" % (where, named))
            elif not kept(source, named_path, tracked):
                problems.append("%s names a missing file: %s" % (where, named))
    targets = [(m.start(), m.group(1)) for m in INLINE.finditer(text)]
    targets += [(m.start(), m.group(1)) for m in DEFINITION.finditer(text)]
    for start, target in sorted(targets):
        where = "%s:%d" % (os.path.relpath(path, source), text.count("\n", 0, start) + 1)
        target = target[1:-1] if target.startswith("<") else target
        if re.match(r"^[a-z][a-z0-9+.-]*:", target):
            continue  # http:, https:, mailto:
        name, _, anchor = target.partition("#")
        name = urllib.parse.unquote(name)
        linked = os.path.normpath(os.path.join(folder, name)) if name else path
        if not inside(source, linked):
            problems.append("%s links outside the repository: %s" % (where, target))
        elif not kept(source, linked, tracked):
            problems.append("%s links to a missing file: %s" % (where, target))
        elif anchor and linked.endswith(".md") and anchor not in anchors(linked):
            problems.append("%s links to a missing heading: %s" % (where, target))
    return problems


def tracked_paths(source):
    """What git keeps below source, files and their folders, or None."""
    listed = subprocess.run(["git", "-C", source, "ls-files"], capture_output=True, text=True,
                            check=False)
    if listed.returncode != 0 or not listed.stdout.strip():
        return None
    paths = {"."}
    for name in listed.stdout.split("\n"):
        while name:
            paths.add(os.path.normpath(name))
            name = os.path.dirname(name)
    return paths


def main():
    source = os.path.abspath(sys.argv[1])
    files = [os.path.abspath(f) for f in sys.argv[2:]]
    tracked = tracked_paths(source)
    if not files:
        if tracked is not None:
            # The wrong variant's page is broken on purpose.
            files = [os.path.join(source, f) for f in sorted(tracked)
                     if f.endswith(".md") and f != "Testing/Data/BrokenLinks.md"
                     and os.path.isfile(os.path.join(source, f))]
        else:  # a source tree without git: the README and docs/
            files = [os.path.join(source, "README.md")] + [
                os.path.join(source, "docs", f) for f in sorted(os.listdir(os.path.join(source, "docs")))
                if f.endswith(".md")]
    problems = []
    for path in files:
        problems += check(source, path, tracked)
    for problem in problems:
        print(problem)
    print("%d Markdown files checked, %d problems" % (len(files), len(problems)))
    if problems:
        sys.exit("FAILED: %d broken or outside links" % len(problems))


if __name__ == "__main__":
    main()
