"""The library's floors, checked (docs/architecture.md, "Floors"):

Every file in src/ and include/shadowlab/ sits on one floor and includes
only headers of its own floor or of the floors it stands on:

  floor       files                                          stands on
  base        src/core/, the public headers in BASE          -
  scene       the public headers in SCENE                    base
  geometry    src/geometry/                                  base, scene
  catalog     src/techniques/Catalog.*, Kinds.h,             base, scene, geometry
              techniques/*Options.cpp, techniques/*/options/
  loader      src/scene/                                     base, scene, geometry, catalog
  gl          src/gl/, the public headers in GL              base
  techniques  the rest of src/techniques/                    all of the above
  render      src/render/, Renderer.h (TOP)                  all of the above
  reference   src/reference/, Compare.h                      all of the above
  bench       src/bench/, Bench.h                            all of the above

The floors from base to loader are what src/SceneSources.cmake compiles
into shadowlab_scene, which links no GL library (tests/scene_only/).
A header from shaders/ (one shared between C++ and GLSL) may be included
from the catalog floor up: it is constants, no code. Also checked: no
include cycle among the headers of src/ and include/shadowlab/ (a header
that includes itself through others). The map technique's module is held
to more, no two units depending on each other (tests/code/structure.py).

    python3 floors.py SOURCE_DIR
"""
import os
import re
import sys

BASE = ["Export", "Error", "Text", "Options", "Image", "FileWrite"]
SCENE = ["Scene", "SceneFile", "GltfExport", "Shapes", "Techniques", "MapOptions", "VolumeOptions", "PlanarOptions", "DiscOptions"]
GL = ["Context", "ImageTexture", "DebugImage", "Limits"]
TOP = {"Renderer": "render", "Compare": "reference", "Bench": "bench"}

ORDER = ["base", "scene", "geometry", "catalog", "loader", "gl", "techniques", "render", "reference", "bench"]
STANDS_ON = {
    "base": [],
    "scene": ["base"],
    "geometry": ["base", "scene"],
    "catalog": ["base", "scene", "geometry"],
    "loader": ["base", "scene", "geometry", "catalog"],
    "gl": ["base"],
    "techniques": ["base", "scene", "geometry", "catalog", "gl"],
    "render": ["base", "scene", "geometry", "catalog", "gl", "techniques"],
    "reference": ["base", "scene", "geometry", "catalog", "loader", "gl", "techniques", "render"],
    "bench": ["base", "scene", "geometry", "catalog", "loader", "gl", "techniques", "render", "reference"],
}
SHADER_HEADERS_FROM = "catalog"
INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]([^>"]+)[>"]', re.MULTILINE)


def floor_of(path):
    """The floor of a file, by its path from the source root ('src/...' or 'include/shadowlab/...'), or None."""
    parts = path.split("/")
    if parts[0] == "include":
        stem = parts[-1].rsplit(".", 1)[0]
        for floor, names in (("base", BASE), ("scene", SCENE), ("gl", GL)):
            if stem in names:
                return floor
        return TOP.get(stem)
    if parts[0] != "src" or len(parts) < 3:
        return None
    top = parts[1]
    if top == "core":
        return "base"
    if top == "geometry":
        return "geometry"
    if top == "scene":
        return "loader"
    if top == "techniques":
        name = parts[-1]
        if len(parts) == 3 and (name.split(".")[0] in ("Catalog", "Kinds") or name.endswith("Options.cpp")):
            return "catalog"
        if "options" in parts[3:-1]:
            return "catalog"
        return "techniques"
    return top if top in STANDS_ON else None


def target_path(root, target):
    """Where an include resolves: 'src/...', 'include/shadowlab/...', 'shaders/...' or None (system, glm, ...)."""
    if target.startswith("shadowlab/"):
        return "include/" + target
    if os.path.exists(os.path.join(root, "src", target)):
        return "src/" + target
    if os.path.exists(os.path.join(root, "shaders", target)):
        return "shaders/" + target
    return None


def files(root):
    for base in ("src", os.path.join("include", "shadowlab")):
        for dirpath, _, names in os.walk(os.path.join(root, base)):
            for name in names:
                if name.endswith((".h", ".cpp")):
                    yield os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")


def cycles(edges):
    found, state = [], {}

    def visit(u, path):
        state[u] = 1
        for v in sorted(edges.get(u, ())):
            if state.get(v) == 1:
                found.append(path[path.index(v):] + [v] if v in path else [u, v])
            elif v not in state:
                visit(v, path + [v])
        state[u] = 2

    for u in sorted(edges):
        if u not in state:
            visit(u, [u])
    return found


def main():
    root = os.path.abspath(sys.argv[1])
    problems, edges, count = [], {}, 0
    for f in sorted(files(root)):
        count += 1
        floor = floor_of(f)
        if floor is None:
            problems.append(f"{f}: on no floor (tests/code/floors.py places every file; add its folder there and to docs/architecture.md)")
            continue
        with open(os.path.join(root, f), encoding="utf-8") as src:
            text = src.read()
        for target in INCLUDE.findall(text):
            t = target_path(root, target)
            if t is None:
                continue
            if t.startswith("shaders/"):
                if ORDER.index(floor) < ORDER.index(SHADER_HEADERS_FROM) or floor == "gl":
                    problems.append(f"{f} (floor {floor}) includes the shader header {target}")
                continue
            tf = floor_of(t)
            if tf is None:
                problems.append(f"{f}: includes {target}, which is on no floor")
            elif tf != floor and tf not in STANDS_ON[floor]:
                problems.append(f"{f} (floor {floor}) includes {target} (floor {tf}): {floor} stands on {', '.join(STANDS_ON[floor]) or 'nothing'}")
            if f.endswith(".h") and t.endswith(".h"):
                edges.setdefault(f, set()).add(t)
    for cycle in cycles(edges):
        problems.append(f"an include cycle: {' -> '.join(cycle)}")
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s) in {count} files of src/ and include/shadowlab/")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
