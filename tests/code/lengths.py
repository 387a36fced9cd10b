"""No file over 400 lines and no function over 80 in src/, apps/, python/
and shaders/: C++ functions' spans from Universal Ctags (its `end` field),
GLSL functions' by counting braces from a line that opens a function
definition at the top level.

    python3 lengths.py SOURCE_DIR
"""
import os
import re
import shutil
import subprocess
import sys

DIRS = ["src", "apps", "python", "shaders"]
MAX_FILE_LINES = 400
MAX_FUNCTION_LINES = 80
CPP = (".cpp", ".h")
GLSL = (".glsl", ".vert", ".frag", ".geom", ".comp")
GLSL_FUNCTION = re.compile(r"^[A-Za-z_][\w\s\[\]]*\s+(\w+)\s*\([^;]*$")


def files(root):
    for top in DIRS:
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if name.endswith(CPP + GLSL):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def cpp_functions(root, paths):
    """(file, line, name, lines) of every C++ function definition, from ctags."""
    out = subprocess.run(["ctags", "-x", "--_xformat=%F\t%n\t%e\t%N", "--fields=+ne", "--kinds-C++=f", "--languages=C++", "--language-force=C++"] + paths,
                         cwd=root, capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        path, start, end, name = line.split("\t")
        if end and end != "-":
            yield path, int(start), name, int(end) - int(start) + 1


def glsl_functions(text):
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = GLSL_FUNCTION.match(lines[i])
        if m and not lines[i].startswith(("#", "layout", "uniform", "in ", "out ", "struct")):
            depth, j, opened = 0, i, False
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                opened = opened or "{" in lines[j]
                if lines[j].rstrip().endswith(";") and not opened:
                    break  # a declaration
                if opened and depth == 0:
                    yield i + 1, m.group(1), j - i + 1
                    break
                j += 1
            i = j + 1
        else:
            i += 1


def main():
    root = os.path.abspath(sys.argv[1])
    have_ctags = shutil.which("ctags") is not None
    problems = []
    paths = list(files(root))
    for rel in paths:
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        count = text.count("\n")
        if count > MAX_FILE_LINES:
            problems.append(f"{rel}: {count} lines (at most {MAX_FILE_LINES})")
        if rel.endswith(GLSL):
            for line, name, length in glsl_functions(text):
                if length > MAX_FUNCTION_LINES:
                    problems.append(f"{rel}:{line}: {name} is {length} lines (at most {MAX_FUNCTION_LINES})")
    if have_ctags:
        for path, line, name, length in cpp_functions(root, [p for p in paths if p.endswith(CPP)]):
            if length > MAX_FUNCTION_LINES:
                problems.append(f"{path}:{line}: {name} is {length} lines (at most {MAX_FUNCTION_LINES})")
    for p in sorted(problems):
        print(p)
    print(f"{len(problems)} problem(s) in {len(paths)} files")
    if problems:
        return 1
    if not have_ctags:
        print("lengths: skipped the C++ functions' lengths: Universal Ctags (package universal-ctags) is not installed; scripts/install-deps.sh installs it")
        return 77  # ctest: skipped
    return 0


if __name__ == "__main__":
    sys.exit(main())
