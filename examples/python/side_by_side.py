#!/usr/bin/env python3
"""A technique, the exact shadows and their difference, side by side.

Renders one scene with its techniques and with ray-traced visibility
(shadowlab.compare) and shows, for one light: the frame, the reference
frame, and the error image (false lit red, false shadow blue, paler in the
1-pixel edge band), with the misclassified shares in the title.

    PYTHONPATH=build/python python3 examples/python/side_by_side.py \\
        --set lights[0].shadow.map.size=256 -o side-by-side.png
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import shadowlab

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(SOURCE, "scenes", "long-view.json"))
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="an override as shadowlab's --set takes it (the value as JSON, a bare word a string)")
    parser.add_argument("--light", type=int, default=0)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("-o", "--output", default="side-by-side.png")
    args = parser.parse_args()

    overrides = {}
    for item in args.set:
        key, _, value = item.partition("=")
        try:
            overrides[key] = json.loads(value)
        except json.JSONDecodeError:
            overrides[key] = value  # a bare word, as --set takes it
    scene = shadowlab.load_scene(args.scene, overrides)
    result = shadowlab.compare(scene, args.width, args.height)
    light = result["lights"][args.light]

    figure, axes = plt.subplots(1, 3, figsize=(15, 15 * args.height / args.width / 3 + 0.8), dpi=100)
    panels = [(result["images"]["technique"], "technique: %s" % light["technique"]),
              (result["images"]["reference"], "reference (ray traced)"),
              (light["images"]["error"], "error: false lit red, false shadow blue")]
    for axis, (image, title) in zip(axes, panels):
        axis.imshow(image)
        axis.set_title(title)
        axis.axis("off")
    figure.suptitle("%s, light %d '%s': %.3f %% misclassified away from edges (%.3f %% with them), RMSE %.3f" % (
        result["scene"], args.light, light["name"], 100 * (light["falseShadowAwayFromEdges"] + light["falseLitAwayFromEdges"]),
        100 * (light["falseShadow"] + light["falseLit"]), light["rmse"]))
    figure.tight_layout()
    figure.savefig(args.output)
    print(args.output)


if __name__ == "__main__":
    main()
