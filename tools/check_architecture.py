#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks docs/architecture.md against the code; Python 3, no dependencies.

    tools/check_architecture.py

- every path it names under src/, include/hyst/, bench/, tools/, tests/ or
  fuzz/ exists (a name with * or <...> is a pattern, not checked);
- every file of src/ and include/hyst/ is named in it (its path, or its
  name in a code span: the Files table);
- every curve kind's file src/kind_*.h is named, and every kind a firmware
  can name (a binder bind_NAME() in src/kinds.h) is declared for each
  variant, hyst_f32_kind_NAME and hyst_f64_kind_NAME (include/hyst/tcm.h,
  which lists it in its table of kinds) and hyst_code_kind_NAME
  (include/hyst/code.h), and tried by kind_of().

Prints one line per problem and exits 1 if there is any, else 0.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
        return f.read()


def problems():
    doc = read("docs/architecture.md")
    spans = set(re.findall(r"`([^`\n]+)`", doc))
    out = []
    for path in sorted(set(re.findall(r"`((?:src|include/hyst|bench|tools|tests|fuzz)/[^`\s]+)`",
                                      doc))):
        if "*" in path or "<" in path:
            continue
        if not os.path.exists(os.path.join(ROOT, path)):
            out.append("docs/architecture.md names %s, which does not exist" % path)
    for folder in ("src", "include/hyst"):
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if "%s/%s" % (folder, name) not in spans and name not in spans:
                out.append("docs/architecture.md does not name %s/%s" % (folder, name))
    kinds_h = read("src/kinds.h")
    tcm_h, code_h = read("include/hyst/tcm.h"), read("include/hyst/code.h")
    kind_of = kinds_h[kinds_h.find("TCM_NAME(kind_of)"):]
    for name in re.findall(r"static const void \*TCM_NAME\(bind_([a-z_]+)\)", kinds_h):
        for variant, header, text in (("f32", "tcm.h", tcm_h), ("f64", "tcm.h", tcm_h),
                                      ("code", "code.h", code_h)):
            if not re.search(r"\bhyst_%s_kind_%s\(" % (variant, name), text):
                out.append("include/hyst/%s does not declare hyst_%s_kind_%s" %
                           (header, variant, name))
        if "| hyst_*_kind_%s |" % name not in tcm_h:
            out.append("include/hyst/tcm.h's table of kinds does not list hyst_*_kind_%s" % name)
        if "TCM_NAME(bind_%s)" % name not in kind_of:
            out.append("src/kinds.h: kind_of() does not try bind_%s()" % name)
    return out


def main():
    found = problems()
    for line in found:
        print(line)
    print("check_architecture: %d problem(s)" % len(found))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
