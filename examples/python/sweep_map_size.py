#!/usr/bin/env python3
"""Sweep a shadow map's size and filter on one scene; plot error against frame time.

Each point is one run of shadowlab's bench (the same rows `shadowlab bench`
writes to results.json): its frame time (median of the timed frames) and
its error against the exact ray-traced shadows. For hard lights the error
is the share of receiver pixels misclassified away from shadow edges; a
line per filter, a point per map size. The plot is written as a PNG.

    PYTHONPATH=build/python python3 examples/python/sweep_map_size.py -o sweep.png

From a build tree; with an installed module, without PYTHONPATH.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt

import shadowlab

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def misclassified(light):
    """Share of the light's receiver pixels shadowed wrongly away from edges, in percent."""
    return 100.0 * (light["falseShadowAwayFromEdges"] + light["falseLitAwayFromEdges"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(SOURCE, "scenes", "long-view.json"))
    parser.add_argument("--sizes", default="256,512,1024,2048", help="map sizes, texels, comma-separated")
    parser.add_argument("--filters", default="none,hardware,grid,poisson", help="map filters, comma-separated")
    parser.add_argument("--width", type=int, default=800)
    parser.add_argument("--height", type=int, default=450)
    parser.add_argument("--frames", type=int, default=5, help="timed frames per run")
    parser.add_argument("-o", "--output", default="sweep.png")
    args = parser.parse_args()

    sizes = [int(s) for s in args.sizes.split(",")]
    filters = args.filters.split(",")
    rows = shadowlab.bench(args.scene, args.width, args.height, frames=args.frames, warmup=1,
                           vary=[("lights[0].shadow.map.filter", filters), ("lights[0].shadow.map.size", sizes)])

    figure, axes = plt.subplots(figsize=(7.5, 4.5), dpi=100)
    floor = 1e-4  # percent: a run with no misclassified pixel is drawn on this line (log axis)
    for name in filters:
        runs = [r for r in rows if r["settings"]["lights[0].shadow.map.filter"] == '"%s"' % name]
        times = [r["frameMs"]["median"] for r in runs]
        errors = [max(misclassified(r["lights"][0]), floor) for r in runs]
        line, = axes.plot(times, errors, marker="o", label=name)
        for r, t, e in zip(runs, times, errors):
            axes.annotate(r["settings"]["lights[0].shadow.map.size"], (t, e), textcoords="offset points", xytext=(4, 4),
                          fontsize=7, color=line.get_color())
    unshadowed = sorted(r["unshadowedFrameMs"]["median"] for r in rows)[len(rows) // 2]
    axes.axvline(unshadowed, color="grey", linestyle=":", label="unshadowed frame")
    axes.set_yscale("log")
    axes.set_xlabel("frame time, ms (median of %d frames, %dx%d)" % (args.frames, args.width, args.height))
    axes.set_ylabel("misclassified away from edges, % of receivers")
    axes.set_title("%s: map size (labels, texels) and filter" % rows[0]["scene"])
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(title="filter")
    figure.tight_layout()
    figure.savefig(args.output)
    print(args.output)
    for r in rows:
        print("%-40s %7.2f ms  %.4f %%" % (" ".join("%s=%s" % (k.split(".")[-1], v) for k, v in r["settings"].items()),
                                          r["frameMs"]["median"], misclassified(r["lights"][0])))


if __name__ == "__main__":
    main()
