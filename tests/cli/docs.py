"""The user's pages are a guide and a reference, not a log, and a clone has
everything they point at:

- no file in the repository names `../shared` (a folder beside the
  checkout that a clone does not have), nor cites a lecture by that
  folder's file numbers ("lecture 002 §8.5": by its author instead);
- README.md and every page under docs/ carry no commit hash (a word of 7 to
  40 hex digits with both letters and digits), no issue number ("issue 25",
  "issues 58-59") and no date of a run (2026-12-06);
- README.md is at most 250 lines, and every lecture scene's command lies
  within its first 120.

    python3 docs.py SOURCE_DIR
"""
import os
import re
import sys

HASH = re.compile(r"\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b")
ISSUE = re.compile(r"\bissues? #?[0-9]+", re.IGNORECASE)
LECTURE_NUMBER = re.compile(r"\blectures? 00[0-9]\b", re.IGNORECASE)
DATE = re.compile(r"\b20[0-9]{2}-[01][0-9]-[0-3][0-9]\b")
SKIP_DIRS = {".git", "build", "build-asan", "build-fuzz", "build-lod", "build-refcheck", "build-web", "node_modules"}


def text_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS and not d.startswith("build-")]
        for name in filenames:
            path = os.path.join(dirpath, name)
            try:
                with open(path, encoding="utf-8") as f:
                    yield path, f.read()
            except (UnicodeDecodeError, OSError):
                continue  # images, meshes


def main():
    root = os.path.abspath(sys.argv[1])
    problems = []
    for path, text in text_files(root):
        rel = os.path.relpath(path, root)
        if rel == os.path.join("tests", "cli", "docs.py"):
            continue  # this file names what it looks for
        if "../shared" in text:
            problems.append(f"{rel}: names ../shared, which a clone does not have")
        m = LECTURE_NUMBER.search(text)
        if m and rel != os.path.join("docs", "history.md"):
            line = text.count("\n", 0, m.start()) + 1
            problems.append(f"{rel}:{line}: cites '{m.group(0)}' by the reference folder's number (name its author)")
    pages = ["README.md"] + [os.path.relpath(os.path.join(d, n), root)
                             for d, _, files in os.walk(os.path.join(root, "docs")) for n in files if n.endswith(".md")]
    for rel in sorted(pages):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                for kind, pattern in (("a commit hash", HASH), ("an issue number", ISSUE), ("a run's date", DATE)):
                    m = pattern.search(line)
                    if m:
                        problems.append(f"{rel}:{number}: {kind} '{m.group(0)}'")
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        readme = f.read().splitlines()
    if len(readme) > 250:
        problems.append(f"README.md: {len(readme)} lines, more than 250")
    lectures = sorted(n[:-5] for n in os.listdir(os.path.join(root, "scenes", "lecture")) if n.endswith(".json"))
    head = "\n".join(readme[:120])
    for name in lectures:
        if f"scenes/lecture/{name}.json" not in head:
            problems.append(f"README.md: no command for scenes/lecture/{name}.json in its first 120 lines")
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s) in {len(pages)} pages and README.md's {len(lectures)} lecture scenes")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
