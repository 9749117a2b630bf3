#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that every measured figure the docs quote equals docs/results.md; Python 3, no dependencies.

    tools/check_figures.py [--list] [FILE.md ...]
    tools/check_figures.py --self-test

docs/results.md, written by ./tools/demo, is the one place a measured figure
is written. Its keys are the `key` | value rows of its tables and the
"key value" pairs of its text (comp_rms_ratio 41.39); a key given two values
there is an error.

Elsewhere (README.md and every other *.md of the repository but
CHANGELOG.md, which keeps history) a figure is quoted as a code span
`key = value`: the key must exist in results.md and the value must equal
its value there (numerically when both are numbers). A span `a_b = 12` whose
key is not in results.md is an error; `index = right` is code, not a quote. And an instruction
count written without its key (a number followed by "instructions", outside
code blocks and code spans) is an error too, unless its line states a budget
or a target ("budget", "target", "holds", "<="): those are the tests' limits,
not measurements.

Prints one line per problem (file:line: what) and exits 1 if there is any;
--list prints the keys of results.md and the quotes found; --self-test checks
the checker on made-up lines against the real results.md (a right quote
passes; a wrong value, an unknown key, a split quote and a bare instruction
count fail; a budget line passes).
"""
import os
import re
import subprocess
import sys

from check_links import lines_outside_fences as text_lines  # (line number, line) outside fences

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join("docs", "results.md")
SKIP = {RESULTS, "CHANGELOG.md"}

TABLE_ROW = re.compile(r"^\|\s*`([a-z][a-z0-9_]*)`\s*\|\s*([^|]*?)\s*\|\s*$")
TEXT_PAIR = re.compile(r"(?<![\w`])([a-z][a-z0-9]*(?:_[a-z0-9]+)+)\**\s+\**(-?\d[\d.]*(?:e[+-]?\d+)?)(?![\w.])")
QUOTE = re.compile(r"`([a-z][a-z0-9_]*) = (-?[\w.+]+(?: \d{3})*)`")
CODE_SPAN = re.compile(r"(`+).*?\1")
UNQUOTED_COUNT = re.compile(r"(?<![\w.])(\d[\d ]*)\s+(?:Cortex-M\S*\s+)?instructions\b")
SPLIT_QUOTE = re.compile(r"`[a-z][a-z0-9_]* =\s*$")
LIMIT_WORDS = re.compile(r"budget|target|holds|<=|≤", re.I)


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as fh:
        return fh.read()


def results_keys(errors):
    """{key: (value, line)} of docs/results.md."""
    keys = {}

    def put(key, value, num):
        if key in keys and not same(keys[key][0], value):
            errors.append(f"{RESULTS}:{num}: {key} is {value} here and {keys[key][0]} "
                          f"on line {keys[key][1]}")
        keys.setdefault(key, (value, num))

    for num, line in text_lines(read(RESULTS)):
        m = TABLE_ROW.match(line)
        if m:
            put(m.group(1), m.group(2), num)
            continue
        for m in TEXT_PAIR.finditer(line):
            put(m.group(1), m.group(2), num)
    return keys


def number(text):
    try:
        return float(text.replace(" ", "").replace(",", ""))
    except ValueError:
        return None


def same(a, b):
    x, y = number(a), number(b)
    if x is not None and y is not None:
        return x == y
    return a.strip() == b.strip()


def docs():
    """The Markdown files to check, relative to the root."""
    try:
        out = subprocess.run(["git", "ls-files", "*.md"], cwd=ROOT, capture_output=True,
                             text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        out = []
        for top, dirs, files in os.walk(ROOT):
            dirs[:] = [d for d in dirs if d not in (".git", "build")]
            out += [os.path.relpath(os.path.join(top, f), ROOT) for f in files if f.endswith(".md")]
    return sorted(f for f in out if f not in SKIP and os.path.exists(os.path.join(ROOT, f)))


def check(rel, keys, errors, quotes):
    for num, line in text_lines(read(rel)):
        for m in QUOTE.finditer(line):
            key, value = m.group(1), m.group(2)
            if key not in keys and ("_" not in key or number(value) is None):
                continue  # code, not a quote: `index = right`
            quotes.append((rel, num, key, value))
            if key not in keys:
                errors.append(f"{rel}:{num}: `{key} = {value}`: no key {key} in {RESULTS}")
            elif not same(value, keys[key][0]):
                errors.append(f"{rel}:{num}: `{key} = {value}`: {RESULTS} says {keys[key][0]} "
                              f"(line {keys[key][1]})")
        if SPLIT_QUOTE.search(line):
            errors.append(f"{rel}:{num}: a `key = value` quote split across lines")
        bare = CODE_SPAN.sub("", line)
        if not LIMIT_WORDS.search(bare):
            for m in UNQUOTED_COUNT.finditer(bare):
                errors.append(f"{rel}:{num}: '{m.group(0)}': an instruction count without its key "
                              f"(quote it as `key = value` from {RESULTS})")


def self_test():
    """The checker on made-up files: each case's count of problems."""
    import tempfile
    keys = results_keys([])
    key = "tcm_typical_insns"
    value = keys[key][0]
    wrong = str(int(float(value)) + 1)
    cases = [("right quote", f"costs `{key} = {value}` instructions", 0),
             ("wrong value", f"costs `{key} = {wrong}` instructions", 1),
             ("unknown key", "costs `no_such_key_insns = 3` instructions", 1),
             ("split quote", f"costs `{key} =\n{value}` instructions", 1),
             ("bare count", "a sample costs 38 instructions", 1),
             ("budget line", "a ctest holds it to 40 instructions (budget)", 0),
             ("code, not a quote", "the paper's `index = right`", 0)]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, text, want in cases:
            path = os.path.join(tmp, "case.md")
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text + "\n")
            errors = []
            check(os.path.relpath(path, ROOT), keys, errors, [])
            ok = len(errors) == want
            failed += not ok
            print(f"self-test {name}: {len(errors)} problem(s), want {want}: {'ok' if ok else 'FAIL'}")
    return 1 if failed else 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    listing = "--list" in argv
    files = [a for a in argv if a != "--list"] or docs()
    errors, quotes = [], []
    keys = results_keys(errors)
    for rel in files:
        check(os.path.relpath(os.path.abspath(rel), ROOT) if os.path.isabs(rel) else rel,
              keys, errors, quotes)
    if listing:
        for key, (value, num) in sorted(keys.items()):
            print(f"key {key} = {value} ({RESULTS}:{num})")
        for rel, num, key, value in quotes:
            print(f"quote {rel}:{num}: {key} = {value}")
    for e in errors:
        print(e)
    print(f"check_figures: {len(keys)} keys in {RESULTS}, {len(quotes)} quoted figure(s) in "
          f"{len(files)} file(s), {len(errors)} problem(s)", file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
