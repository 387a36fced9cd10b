"""The Python module (python/module.cpp), imported from the build tree.

Run by ctest as `python3 -m pytest tests/python` with PYTHONPATH at the
build's python/ directory and SHADOWLAB_TOOL naming the CLI, whose PNG the
module's array must match pixel for pixel.
"""
import os
import subprocess

import matplotlib.image
import numpy as np
import pytest

import shadowlab

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
SCENE = os.path.join(SOURCE, "scenes", "torus-floating.json")


def test_render_is_the_cli_frame(tmp_path):
    scene = shadowlab.load_scene(SCENE, {"lights[0].shadow.map.size": 512})
    image = shadowlab.render(scene, 160, 90)
    assert image.shape == (90, 160, 4) and image.dtype == np.uint8
    png = tmp_path / "cli.png"
    subprocess.run([os.environ["SHADOWLAB_TOOL"], "render", SCENE, "--width", "160", "--height", "90",
                    "--set", "lights[0].shadow.map.size=512", "-o", str(png)], check=True, capture_output=True)
    cli = np.rint(matplotlib.image.imread(str(png)) * 255.0).astype(np.uint8)  # float 0..1, top row first
    assert np.array_equal(image, cli)


def test_overrides_and_with_overrides():
    scene = shadowlab.load_scene(SCENE)
    assert scene.lights[0]["technique"] == "map"
    unshadowed = scene.with_overrides({"lights[0].shadow.technique": "none"})
    assert unshadowed.lights[0]["technique"] == "none"
    assert scene.lights[0]["technique"] == "map"  # the original is unchanged
    lit = shadowlab.render(unshadowed, 96, 54)
    shadowed = shadowlab.render(scene, 96, 54)
    # Shadows darken some pixels and brighten none.
    assert (lit.astype(int) - shadowed.astype(int)).min() >= 0
    assert (lit.astype(int) - shadowed.astype(int)).max() > 30


def test_arrays_own_their_memory():
    scene = shadowlab.default_scene()
    first = shadowlab.render(scene, 64, 48)
    copy = first.copy()
    shadowlab.render(scene.with_overrides({"lights[0].intensity": 0.1}), 64, 48)
    assert np.array_equal(first, copy)


def test_bad_input_is_a_value_error_naming_the_key():
    with pytest.raises(ValueError, match=r"^overrides\[lights\[0\]\.shadow\.map\.size\]: lights\[0\]\.shadow\.map\.size: expected an integer in 16\.\.16384, got 7$"):
        shadowlab.load_scene(SCENE, {"lights[0].shadow.map.size": 7})
    with pytest.raises(ValueError, match="file not found"):
        shadowlab.load_scene(os.path.join(SOURCE, "scenes", "no-such-scene.json"))
    with pytest.raises(ValueError, match="width and height must be at least 1"):
        shadowlab.render(shadowlab.default_scene(), 0, 10)
    with pytest.raises(ValueError, match=r"render size 100000x10: expected 1\.\.\d+ pixels per side"):
        shadowlab.render(shadowlab.default_scene(), 100000, 10)


def test_techniques_table():
    tables = shadowlab.techniques()
    assert list(tables)[:2] == ["none", "map"]
    size = tables["map"]["options"]["size"]
    assert size["default"] == "1024" and size["unit"] == "texels" and size["range"] == "16..16384"
    assert '"hardware"' in tables["map"]["options"]["filter"]["range"]


def test_compare_is_the_cli_metrics(tmp_path):
    scene = shadowlab.load_scene(SCENE, {"lights[0].shadow.map.size": 256})
    result = shadowlab.compare(scene, 160, 90)
    subprocess.run([os.environ["SHADOWLAB_TOOL"], "compare", SCENE, "--width", "160", "--height", "90",
                    "--set", "lights[0].shadow.map.size=256", "-o", str(tmp_path / "cmp")], check=True, capture_output=True)
    import json
    cli = json.load(open(tmp_path / "cmp" / "metrics.json"))
    # The same fields but the image files (arrays here) and the trace's time.
    for key in ("scene", "width", "height", "softSamples", "time"):
        assert result[key] == cli[key], key
    assert len(result["lights"]) == len(cli["lights"]) == 1
    ours, theirs = result["lights"][0], cli["lights"][0]
    assert set(ours) - {"images"} == set(theirs) - {"errorImage", "visibilityImage", "techniqueVisibilityImage", "reachImage"}
    for key in ours:
        if key != "images":
            assert ours[key] == theirs[key], key
    assert ours["receiverPixels"] > 1000 and ours["referenceShadowedPixels"] > 100  # it measured a shadow
    images = ours["images"]
    assert images["visibility"].shape == (90, 160) and images["visibility"].dtype == np.float32
    assert images["reach"].sum() == ours["receiverPixels"]
    assert result["images"]["reference"].shape == (90, 160, 4)


def test_visibility_and_debug_images():
    scene = shadowlab.load_scene(SCENE, {"lights[0].shadow.map.size": 256})
    v = shadowlab.visibility(scene, 0, 160, 90)
    assert v.shape == (90, 160) and v.dtype == np.float32
    assert v.min() == 0.0 and v.max() == 1.0  # background and shadow at 0, lit receivers at 1
    rgb = shadowlab.visibility(scene, 0, 160, 90, coloured=True)
    assert rgb.shape == (90, 160, 3) and np.allclose(rgb.mean(axis=2), v)
    # compare's technique visibility is the same term, stored in 16 bits.
    technique = shadowlab.compare(scene, 160, 90)["lights"][0]["images"]["techniqueVisibility"]
    assert np.abs(technique - v).max() <= 1.0 / 65535.0 + 1e-6
    images = shadowlab.debug_images(scene, 160, 90)
    assert "light0-depth" in images or any(name.startswith("light0-") for name in images), list(images)
    assert all(a.dtype == np.uint8 and a.ndim == 3 and a.shape[2] == 4 for a in images.values())
    with pytest.raises(ValueError, match="light 3: the scene has 1 light"):
        shadowlab.visibility(scene, 3, 16, 16)


def test_load_scene_json_and_threads():
    text = open(SCENE).read()
    from_text = shadowlab.load_scene_json(text, base_dir=os.path.dirname(SCENE), overrides={"lights[0].shadow.map.size": 256})
    from_file = shadowlab.load_scene(SCENE, {"lights[0].shadow.map.size": 256})
    assert np.array_equal(shadowlab.render(from_text, 96, 54), shadowlab.render(from_file, 96, 54))
    assert from_text.with_overrides({"lights[0].shadow.technique": "none"}).lights[0]["technique"] == "none"
    with pytest.raises(ValueError, match=r"^<json>: "):
        shadowlab.load_scene_json("{\"lights\": 3}")
    # Calls from two threads at once are serialised on the one context: the same frames.
    import threading
    results = {}

    def work(key):
        results[key] = shadowlab.render(from_file, 96, 54)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert np.array_equal(results[0], results[1])
    assert np.array_equal(results[0], shadowlab.render(from_file, 96, 54))
