#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the links of the repository's Markdown files; Python 3, no dependencies.

    tools/check_links.py [FILE.md ...]

Without arguments it checks README.md, CHANGELOG.md and every *.md under docs/.
For each inline link [text](target), image ![alt](target) and reference
definition [name]: target outside code blocks and code spans:

- a relative target must name a file or directory of the repository;
- a #fragment on a Markdown target (or on the page itself) must match one of
  its headings, slugged as GitHub does (lower case, punctuation dropped,
  spaces to hyphens, -1, -2 ... on repeats), or an explicit id/name anchor;
- a target with a scheme (http:, mailto: ...) leaves the repository: an
  error, except the paper's DOI address (https://doi.org/...).

Prints one line per broken link (file:line: target: reason) and exits 1 if
there is any, else 0.
"""
import os
import re
import sys
import unicodedata

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ALLOWED_EXTERNAL = ("https://doi.org/",)

FENCE = re.compile(r"^\s{0,3}(`{3,}|~{3,})")
CODE_SPAN = re.compile(r"(`+)(?:.|\n)*?\1")
INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
REF_DEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ID = re.compile(r"""<[^>]+\s(?:id|name)\s*=\s*["']([^"']+)["']""")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def lines_outside_fences(text):
    """(line number, line) of the lines that are not inside fenced code blocks."""
    fence = None
    for num, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence = m.group(1)[0] * len(m.group(1))
                continue
            yield num, line
        elif m and m.group(1).startswith(fence):
            fence = None


def slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links: their text
    text = text.replace("`", "").lower()
    kept = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in " -" or cat[0] in "LMN" or cat == "Pc":
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


_anchor_cache = {}


def anchors(path):
    """The fragment names a Markdown file defines."""
    if path not in _anchor_cache:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found, seen = set(), {}
        for _, line in lines_outside_fences(text):
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else "%s-%d" % (base, n))
            found.update(HTML_ID.findall(line))
        _anchor_cache[path] = found
    return _anchor_cache[path]


def targets(text):
    """(line number, target) of every link outside code."""
    for num, line in lines_outside_fences(text):
        line = CODE_SPAN.sub("", line)
        for m in INLINE.finditer(line):
            yield num, m.group(1)
        m = REF_DEF.match(line)
        if m:
            yield num, m.group(1)


def check(path):
    """Error messages for the links of one Markdown file."""
    errors = []
    with open(path, encoding="utf-8") as f:
        text = f.read()
    rel = os.path.relpath(path, ROOT)
    for num, target in targets(text):
        where = "%s:%d: %s:" % (rel, num, target)
        if not target:
            errors.append("%s empty target" % where)
            continue
        if SCHEME.match(target):
            if not target.startswith(ALLOWED_EXTERNAL):
                errors.append("%s leaves the repository" % where)
            continue
        file_part, _, fragment = target.partition("#")
        if file_part.startswith("/"):
            dest = os.path.normpath(os.path.join(ROOT, file_part.lstrip("/")))
        elif file_part:
            dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
        else:
            dest = path
        inside = dest == ROOT or dest.startswith(ROOT + os.sep)
        if not inside:
            errors.append("%s points outside the repository" % where)
        elif not os.path.exists(dest):
            errors.append("%s no such file" % where)
        elif fragment and dest.endswith(".md") and os.path.isfile(dest):
            if fragment.lower() not in {a.lower() for a in anchors(dest)}:
                errors.append("%s no heading #%s in %s" % (where, fragment,
                                                         os.path.relpath(dest, ROOT)))
    return errors


def default_files():
    files = [os.path.join(ROOT, n) for n in ("README.md", "CHANGELOG.md")]
    for base, dirs, names in os.walk(os.path.join(ROOT, "docs")):
        dirs.sort()
        files += [os.path.join(base, n) for n in sorted(names) if n.endswith(".md")]
    return [f for f in files if os.path.isfile(f)]


def main(argv):
    files = [os.path.abspath(a) for a in argv[1:]] or default_files()
    errors = []
    for path in files:
        errors += check(path)
    for e in errors:
        print(e)
    print("check_links: %d file(s), %d broken link(s)" % (len(files), len(errors)),
          file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
