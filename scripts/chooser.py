#!/usr/bin/python3
"""The technique chooser: README.md's table, measured by one bench run over
the bundled scenes (every scene with one light, each technique in turn on
that light), written as Markdown.

    /usr/bin/python3 scripts/chooser.py [--tool PATH] [--out DIR] [--width W --height H] [--from results.json]

It prints the bench command it runs, then the table. Rerun it when a
default changes and paste the table into README.md. Each row's figures:

- cost: the frame with the shadows over the same frame unshadowed
  (results.json's frameOverUnshadowed), the median over the scenes the
  row ran on and the worst;
- accuracy: hard lights, the share of receiver pixels misclassified away
  from the 1-pixel edge band (false lit + false shadow), the median over
  the scenes and the worst;
  soft lights (a light with a size), the visibility's RMSE, the worst scene;
- memory: the shadow map's bytes (mapBytes; the median over the scenes);
  0 for techniques without a map.

Runs a technique cannot draw on a scene (cascades on a spot light, shadow
volumes over an alpha-tested caster) are left out (--skip-unsupported) and
counted in the "scenes" column. many-lights.json (a grid of 64 lights) is
not in the run: its technique is the shadow atlas (docs/techniques/atlas.md).
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Each row: (name, the light's shadow block, use it when, avoid it when).
ROWS = [
    ("map (defaults: hardware 2x2 compare)", {"technique": "map"},
     "the default for any light: one depth map (a cube for a point light), sharp edges, cheap",
     "you need soft penumbrae (pcss) or a 400 m view from a sun (cascades)"),
    ("map, filter pcf (64 taps)", {"technique": "map", "map": {"filter": "pcf"}},
     "the lectures' PCF: edges smoothed over a few pixels at any distance",
     "frame time matters more than edge smoothness (64 taps a pixel)"),
    ("map, filter poisson", {"technique": "map", "map": {"filter": "poisson"}},
     "a softer edge from fewer taps (a rotated disk)",
     "you dislike the disk's fine noise on large flat receivers"),
    ("map, representation evsm4", {"technique": "map", "map": {"representation": "evsm4"}},
     "filterable maps: blurred, mipmapped edges for directional and spot lights",
     "casters overlap in depth (light leaks) or the light is a point light"),
    ("map, 4 cascades", {"technique": "map", "map": {"cascades": 4}},
     "a sun over a long view: texels spent near the camera",
     "the view is small (a room, a table): one map is as sharp and cheaper"),
    ("map, filter pcss", {"technique": "map", "map": {"filter": "pcss"}},
     "lights with a size: penumbrae that widen away from the caster",
     "the light has no size (its shadow stays hard, at a search's cost)"),
    ("volume (depth-fail)", {"technique": "volume"},
     "exact hard shadows from closed meshes, at any distance, no map",
     "alpha-tested casters (refused), dense meshes (fill of the volumes), soft shadows"),
    ("planar (stencil)", {"technique": "planar"},
     "shadows only on flat ground: exact, no map",
     "objects shadow each other or curved receivers (not drawn)"),
]


def bench_command(tool, out, width, height, scenes):
    values = ",".join(json.dumps(block, separators=(",", ":")) for _, block, _, _ in ROWS)
    return [tool, "bench", *scenes, "--width", str(width), "--height", str(height), "--frames", "5", "--warmup", "1",
            "--skip-unsupported", "-o", out, "--vary", "lights[0].shadow=" + values]


def shown(command):
    return " ".join(c if all(ch.isalnum() or ch in "/._-=[],:" for ch in c) else "'" + c + "'" for c in command)


def table(results):
    rows = {json.dumps(block, sort_keys=True): [] for _, block, _, _ in ROWS}
    for r in results["results"]:
        combo = next(iter(r["settings"].values())) if r.get("settings") else None
        key = json.dumps(json.loads(combo), sort_keys=True) if combo else None
        if key in rows:
            rows[key].append(r)
    skipped = {}
    for s in results.get("skipped", []):
        value = s["vary"][0].split("=", 1)[1]
        key = json.dumps(json.loads(value), sort_keys=True)
        skipped[key] = skipped.get(key, 0) + 1
    out = ["| technique | use it when | avoid it when | cost: frame over unshadowed, median (worst) | misclassified away from edges, median (worst scene) | map memory | scenes |",
           "|---|---|---|---|---|---|---|"]
    for name, block, use, avoid in ROWS:
        key = json.dumps(block, sort_keys=True)
        runs = rows[key]
        if not runs:
            out.append(f"| {name} | {use} | {avoid} | - | - | - | 0 (all {skipped.get(key, 0)} left out) |")
            continue
        cost = [r["frameOverUnshadowed"] for r in runs]
        hard = [r for r in runs if not r["lights"][0]["soft"]]
        soft = [r for r in runs if r["lights"][0]["soft"]]
        accuracy = []
        if hard:
            miss = lambda r: r["lights"][0]["falseLitAwayFromEdges"] + r["lights"][0]["falseShadowAwayFromEdges"]
            worst = max(hard, key=miss)
            accuracy.append(f"{100 * statistics.median(miss(r) for r in hard):.3f} % ({100 * miss(worst):.3f} % {worst['scene']})")
        if soft:
            worst = max(soft, key=lambda r: r["lights"][0]["rmse"])
            accuracy.append(f"soft: RMSE {worst['lights'][0]['rmse']:.3f} ({worst['scene']})")
        memory = statistics.median(r["lights"][0].get("shadowCounters", {}).get("mapBytes", 0.0) for r in runs)
        mem = f"{memory / 2**20:.1f} MiB" if memory else "none"
        left = f", {skipped[key]} left out" if skipped.get(key) else ""
        out.append(f"| {name} | {use} | {avoid} | {statistics.median(cost):.2f}x ({max(cost):.2f}x) | {'; '.join(accuracy)} | {mem} | {len(runs)}{left} |")
    return "\n".join(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "apps", "shadowlab", "shadowlab"))
    p.add_argument("--out", default="chooser-bench")
    p.add_argument("--width", type=int, default=640)
    p.add_argument("--height", type=int, default=360)
    p.add_argument("--from", dest="source", help="make the table from this results.json instead of running the bench")
    a = p.parse_args()
    if a.source:
        with open(a.source) as f:
            print(table(json.load(f)))
        return 0
    scenes = sorted(os.path.relpath(s, os.getcwd()) for s in glob.glob(os.path.join(ROOT, "scenes", "*.json"))
                    if os.path.basename(s) != "many-lights.json")
    command = bench_command(a.tool, a.out, a.width, a.height, scenes)
    print("Measured by: " + shown([os.path.relpath(command[0]) if command[0].startswith(ROOT) else command[0]] + command[1:]), file=sys.stderr)
    subprocess.run(command, check=True)
    with open(os.path.join(a.out, "results.json")) as f:
        print(table(json.load(f)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
