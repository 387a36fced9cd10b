"""The code's shape, checked (docs/architecture.md):

- every file in src/techniques/map/ is named in docs/architecture.md's
  index of the map technique's module ("The map technique's module"), and
  every file named there exists;
- every .cpp there has a header of its own (the same path, .h);
- no two units there depend on each other (a unit: a .h and its .cpp;
  it depends on another when either file includes the other's header),
  directly or through others.

    python3 structure.py SOURCE_DIR
"""
import os
import re
import sys

from floors import cycles as graph_cycles

MODULE = os.path.join("src", "techniques", "map")
INCLUDE = re.compile(r'^\s*#\s*include\s+"techniques/map/([^"]+)"', re.MULTILINE)


def module_files(root):
    base = os.path.join(root, MODULE)
    for dirpath, _, names in os.walk(base):
        for name in names:
            if name.endswith((".h", ".cpp")):
                yield os.path.relpath(os.path.join(dirpath, name), base).replace(os.sep, "/")


def index_names(root):
    """The files docs/architecture.md's module index names: `a/B.h`, `.cpp` after it means a/B.cpp."""
    with open(os.path.join(root, "docs", "architecture.md"), encoding="utf-8") as f:
        text = f.read()
    start = text.find("## The map technique's module")
    end = text.find("\n## ", start + 1)
    names = set()
    for line in text[start:end].splitlines():
        if not line.startswith("|"):
            continue
        cells = line.split("|")
        if len(cells) < 3:
            continue
        last = None
        for token in re.findall(r"`([^`]+)`", cells[2]):
            if token == ".cpp" and last:
                names.add(last[:-2] + ".cpp")
            elif re.fullmatch(r"[A-Za-z0-9_/]+\.(h|cpp)", token):
                names.add(token)
                last = token
    return names


def cycles(root, files):
    unit = lambda f: f.rsplit(".", 1)[0]
    edges = {}
    for f in files:
        with open(os.path.join(root, MODULE, f), encoding="utf-8") as src:
            for target in INCLUDE.findall(src.read()):
                if unit(target) != unit(f):
                    edges.setdefault(unit(f), set()).add(unit(target))
    return graph_cycles(edges)


def main():
    root = os.path.abspath(sys.argv[1])
    problems = []
    files = sorted(module_files(root))
    named = index_names(root)
    for f in files:
        if f not in named:
            problems.append(f"{MODULE}/{f}: not in docs/architecture.md's index of the map technique's module")
    for f in sorted(named - set(files)):
        problems.append(f"docs/architecture.md: its module index names {f}, which {MODULE}/ does not have")
    for f in files:
        if f.endswith(".cpp") and f[:-4] + ".h" not in files:
            problems.append(f"{MODULE}/{f}: no header of its own ({f[:-4]}.h)")
    for cycle in cycles(root, files):
        problems.append(f"{MODULE}: units that depend on each other: {' -> '.join(cycle)}")
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s) in {len(files)} files of {MODULE}/ ({len(named)} named in its index)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
