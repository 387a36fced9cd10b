#!/usr/bin/python3
"""Pastes the options tables, as `shadowlab techniques --markdown` prints
them, into the pages that carry them: docs/scene-format.md (all of it,
between its BEGIN/END generated markers) and each docs/techniques/ page's
`<!-- options:NAME begin -->` ... `end` block (that technique's section).
Run after an option changes; tests/unit/OptionsTest.cpp checks both.

    /usr/bin/python3 scripts/generated-docs.py [--tool PATH]
"""
import argparse
import glob
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "apps", "shadowlab", "shadowlab"))
    tables = subprocess.run([p.parse_args().tool, "techniques", "--markdown"], check=True, capture_output=True, text=True).stdout
    path = os.path.join(ROOT, "docs", "scene-format.md")
    text = open(path).read()
    begin, end = "<!-- BEGIN generated: shadowlab techniques --markdown -->\n", "<!-- END generated -->"
    i, j = text.index(begin) + len(begin), text.index(end)
    open(path, "w").write(text[:i] + tables + text[j:])
    sections = {}
    for m in re.finditer(r"#### `lights\[i\]\.shadow\.([A-Za-z0-9_-]+)`\n.*?(?=\n\n####|\Z)", tables, re.S):
        sections[m.group(1)] = m.group(0).rstrip("\n") + "\n"
    for page in glob.glob(os.path.join(ROOT, "docs", "techniques", "*.md")):
        text = open(page).read()
        for name, section in sections.items():
            b, e = f"<!-- options:{name} begin -->\n", f"<!-- options:{name} end -->"
            if b in text:
                i, j = text.index(b) + len(b), text.index(e)
                text = text[:i] + section + text[j:]
        open(page, "w").write(text)


if __name__ == "__main__":
    main()
