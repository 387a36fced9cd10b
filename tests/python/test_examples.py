"""The examples in examples/python run, on a small size, and write their plots.

docs/python.md shows their plots at full size (the commands there make them).
"""
import os
import subprocess
import sys

import matplotlib.image
import numpy as np

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python")


def run(script, *args):
    return subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args], check=True, capture_output=True, text=True).stdout


def test_sweep_map_size(tmp_path):
    out = tmp_path / "sweep.png"
    printed = run("sweep_map_size.py", "--width", "160", "--height", "90", "--frames", "1", "--sizes", "64,512",
                  "--filters", "none,hardware", "-o", str(out))
    plot = matplotlib.image.imread(str(out))
    assert plot.shape[:2] == (450, 750)  # the figure's 7.5 x 4.5 inches at 100 dpi
    rows = printed.splitlines()[1:]
    assert len(rows) == 4  # a row per filter and size
    # The sweep measures: a 64-texel map on long-view's 300 m street misclassifies more than a 512 one.
    errors = {line.split()[1]: float(line.split()[-2]) for line in rows if line.startswith('filter="none"')}
    assert errors["size=64"] > errors["size=512"], errors


def test_side_by_side(tmp_path):
    out = tmp_path / "side.png"
    run("side_by_side.py", "--width", "160", "--height", "90", "--set", "lights[0].shadow.map.size=128", "-o", str(out))
    image = matplotlib.image.imread(str(out))
    assert image.ndim == 3 and image.shape[1] == 1500
    assert np.ptp(image[..., :3]) > 0.5  # the panels were drawn, not a blank figure
