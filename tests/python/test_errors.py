"""Bad input to the Python module: shadowlab.InputError (a ValueError) whose
one-line message names the argument or override key, before anything is
written; never a crash, a hang or another exception. The cases come from a hostile run over
the module (issue 24's battery), one per cause it found."""
import math
import os
import pathlib

import pytest

import shadowlab as sl

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
SCENE = os.path.join(SOURCE, "scenes", "torus-floating.json")
MANY = os.path.join(SOURCE, "scenes", "many-lights.json")


def D(overrides=None):
    return sl.default_scene(overrides or {})


CASES = [
    # Sizes: at least a pixel, within the GPU's limits and the host's memory; a finite time.
    ("render-size-0", lambda: sl.render(D(), 0, 10), r"^width and height must be at least 1 pixel, got 0x10$"),
    ("render-past-gpu", lambda: sl.render(D(), 100000, 24), r"^width 100000: exceeds this GPU's limit of \d+ pixels$"),
    ("render-past-memory", lambda: sl.render(D(), 1 << 20, 1 << 20), r"^width 1048576 height 1048576: the frame needs about .* more than the budget"),
    ("visibility-past-gpu", lambda: sl.visibility(D(), 0, 24, 100000), r"^height 100000: exceeds this GPU's limit"),
    ("render-time-nan", lambda: sl.render(D(), 32, 24, time=math.nan), r"^time nan: expected a finite number of seconds$"),
    ("compare-time-inf", lambda: sl.compare(D(), 32, 24, time=math.inf), r"^time inf: expected a finite number of seconds$"),
    ("debug-time-minus-inf", lambda: sl.debug_images(D(), 32, 24, time=-math.inf), r"^time -inf: expected a finite"),
    # soft_samples: the CLI's range, and the reference's rays within 2^31.
    ("reference-samples-huge", lambda: sl.reference(sl.load_scene(SCENE), 0, 1, 1, soft_samples=2**31 - 1), r"^soft_samples 2147483647: expected 1\.\.65536$"),
    ("compare-rays-past-limit", lambda: sl.compare(D(), 320, 180, soft_samples=65536),
     r"^soft_samples 65536 at 320x180: .* rays for each soft light's reference, more than the limit of 2\^31 \(lower soft_samples, width or height\)$"),
    ("compare-scene-rays-past-limit", lambda: sl.compare(sl.default_scene({"lights": [{"type": "point", "position": [0, 3, 0], "size": 0.2}] * 5}), 256, 256, soft_samples=16384),
     r"^soft_samples 16384 at 256x256: 5\.37e\+09 rays for the reference of 5 soft lights, more than the limit of 2\^32 for a scene"),
    ("bench-samples-huge", lambda: sl.bench(SCENE, 32, 24, soft_samples=10**6), r"^soft_samples 1000000: expected 1\.\.65536$"),
    ("bench-past-gpu", lambda: sl.bench(None, 100000, 24, frames=1, warmup=0), r"^width 100000: exceeds this GPU's limit"),
    # frames and warmup: the CLI's ranges (issue 59: 10**6 frames ran for ever).
    ("bench-frames-huge", lambda: sl.bench(SCENE, 32, 24, frames=10**6), r"^frames 1000000: expected 1\.\.100000$"),
    ("bench-warmup-huge", lambda: sl.bench(SCENE, 32, 24, warmup=10**7), r"^warmup 10000000: expected 0\.\.1000$"),
    # Found while drawing, not in reading the scene: still bad input, named by the override that set the value.
    ("atlas-too-small", lambda: sl.render(sl.load_scene(MANY, {"shadowAtlas.size": 512, "shadowAtlas.minTile": 256}), 64, 36),
     r"^overrides\[shadowAtlas\.size\]: shadowAtlas\.size: 224 tiles of at least 256\^2 texels \(shadowAtlas\.minTile\) do not fit in 512\^2"),
    ("atlas-too-small-with-overrides", lambda: sl.render(sl.load_scene(MANY).with_overrides({"shadowAtlas.size": 512, "shadowAtlas.minTile": 256}), 64, 36),
     r"^overrides\[shadowAtlas\.size\]: shadowAtlas\.size: 224 tiles"),
    ("planar-receiver-missing", lambda: sl.render(D({"lights[0].shadow.technique": "planar", "lights[0].shadow.planar.receivers": "nosuch"}), 64, 36),
     r"^overrides\[lights\[0\]\.shadow\.planar\.receivers\]: lights\[0\]\.shadow\.planar\.receivers: no node named 'nosuch'$"),
    ("cascade-split-before-near", lambda: sl.visibility(D({"lights[0].shadow.map.cascades": 3, "lights[0].shadow.map.cascadeSplits": "0.001,1"}), 0, 64, 36),
     r"^overrides\[lights\[0\]\.shadow\.map\.cascadeSplits\]: .*the first split must lie beyond the camera's near plane"),
    ("maps-past-budget", lambda: sl.render(D({"lights[0].shadow.map.size": 16384, "lights[0].shadow.map.cascades": 4}), 64, 36),
     r"^overrides\[lights\[0\]\.shadow\.map\.cascades\]: lights\[0\]\.shadow\.map: the shadow maps of 1 light\(s\) need 4\.00 GiB, more than the budget of 1 GiB"),
    ("bench-run-atlas-too-small", lambda: sl.bench(MANY, 64, 36, frames=1, warmup=0, overrides={"shadowAtlas.minTile": 256}, vary={"shadowAtlas.size": [512]}),
     r"^bench run 1/1 \(.*many-lights\.json, vary\[shadowAtlas\.size\]=512\): vary\[shadowAtlas\.size\]=512: shadowAtlas\.size: 224 tiles"),
    # Overrides: keys are paths without '=' or NUL, values JSON; messages name the key, not a JSON value's colons.
    ("override-object-value", lambda: D({"lights[0].shadow.map": {"size": 7}}),
     r"^overrides\[lights\[0\]\.shadow\.map\]: lights\[0\]\.shadow\.map\.size: map: size: expected 0 \(follow the frame\) or 16\.\.16384 texels, got 7$"),
    ("override-list-value", lambda: D({"lights[0].color": [1, {"a": 2}, 3]}), r"^overrides\[lights\[0\]\.color\]: lights\[0\]\.color\[1\]: expected a number"),
    ("override-key-with-equals", lambda: D({"lights[0].intensity=5": 1}), r"^overrides\[lights\[0\]\.intensity=5\]: a key may not contain '=' or NUL$"),
    ("override-key-not-str", lambda: D({3: 1}), r"^overrides: keys are scene paths as strings"),
    ("override-key-surrogate", lambda: D({"lights[0].\udc80": 1}), r"^overrides key: not valid UTF-8 text$"),
    ("override-nan", lambda: D({"lights[0].intensity": math.nan}), r"^overrides\[lights\[0\]\.intensity\]: not a JSON value"),
    ("override-bytes", lambda: D({"lights[0].intensity": b"x"}), r"^overrides\[lights\[0\]\.intensity\]: not a JSON value \(TypeError"),
    ("override-deep", lambda: D({"lights[0].intensity": __import__("functools").reduce(lambda a, _: [a], range(100000), 1)}),
     r"^overrides\[lights\[0\]\.intensity\]: not a JSON value"),
    # Paths: str or os.PathLike, not empty, no NUL; messages stay one line.
    ("load-nul", lambda: sl.load_scene(SCENE + "\x00junk"), r"^path .*torus-floating\.json\\x00junk: a path may not contain NUL$"),
    ("load-newline", lambda: sl.load_scene("no\nsuch\nscene.json"), r"^no\\nsuch\\nscene\.json: file not found$"),
    ("load-int", lambda: sl.load_scene(3), r"^path: expected a path \(str or os\.PathLike\), got int$"),
    ("load-empty", lambda: sl.load_scene(""), r"^path: empty path$"),
    ("json-not-str", lambda: sl.load_scene_json(b"{}"), r"^text: expected the scene's JSON as a str$"),
    ("json-base-dir-nul", lambda: sl.load_scene_json("{}", base_dir="a\x00b"), r"^base_dir a\\x00b: a path may not contain NUL$"),
    # bench's scenes, vary and out.
    ("bench-scene-empty", lambda: sl.bench("", 32, 24), r"^scenes: empty path$"),
    ("bench-scenes-empty-list", lambda: sl.bench([], 32, 24), r"^scenes: an empty list"),
    ("bench-scene-int", lambda: sl.bench(3, 32, 24), r"^scenes: expected a path \(str or os\.PathLike\), got int$"),
    ("bench-scene-missing", lambda: sl.bench(["no-such.json"], 32, 24), r"^scenes no-such\.json: file not found$"),
    ("bench-scene-json-text", lambda: sl.bench(open(SCENE).read(), 32, 24), r"^scenes \{\\n.*: file not found$"),
    ("bench-scene-directory", lambda: sl.bench(SOURCE, 32, 24), r"^scenes .*: not a regular file \(expected a scene file\)$"),
    ("bench-scene-nul", lambda: sl.bench(SCENE + "\x00", 32, 24), r"^scenes .*: a path may not contain NUL$"),
    ("bench-vary-not-list", lambda: sl.bench(SCENE, 32, 24, vary={"lights[0].intensity": 512}), r"^vary\[lights\[0\]\.intensity\]: expected a list of values, got int$"),
    ("bench-vary-set", lambda: sl.bench(SCENE, 32, 24, vary={"lights[0].intensity": {1, 2}}), r"^vary\[lights\[0\]\.intensity\]: expected a list of values, got set$"),
    ("bench-vary-not-json", lambda: sl.bench(SCENE, 32, 24, vary={"lights[0].intensity": [1, b"x"]}), r"^vary\[lights\[0\]\.intensity\]: not a JSON value"),
    ("bench-vary-int", lambda: sl.bench(SCENE, 32, 24, vary=3), r"^vary: expected \{key: \[values\]\}"),
    ("bench-vary-and-override", lambda: sl.bench(SCENE, 32, 24, overrides={"lights[0].intensity": 2}, vary={"lights[0].intensity": [1, 3]}),
     r"^vary\[lights\[0\]\.intensity\]=1,3: lights\[0\]\.intensity is also set by overrides\[lights\[0\]\.intensity\] \(a varied key takes its values from vary alone\)$"),
    # One dict's keys: the same path spelt two ways, or a block after a path inside it, would drop a value unread.
    ("overrides-one-path-twice", lambda: sl.default_scene({"lights[0].intensity": -1, "lights[00].intensity": 2}),
     r"^overrides\[lights\[00\]\.intensity\]: lights\[00\]\.intensity is already set by overrides\[lights\[0\]\.intensity\] \(give each path once\)$"),
    ("overrides-block-after-inner", lambda: sl.default_scene({"lights[0].shadow.map.size": 7, "lights[0].shadow.map": {"filter": "none"}}),
     r"^overrides\[lights\[0\]\.shadow\.map\]: replaces lights\[0\]\.shadow\.map\.size, set by overrides\[lights\[0\]\.shadow\.map\.size\]"),
    ("bench-overrides-block-after-inner", lambda: sl.bench(SCENE, 32, 24, overrides={"lights[0].intensity": -1, "lights[0]": {"type": "directional"}}),
     r"^overrides\[lights\[0\]\]: replaces lights\[0\]\.intensity"),
    ("bench-out-empty", lambda: sl.bench(SCENE, 32, 24, out=""), r"^out: empty path$"),
    ("bench-out-int", lambda: sl.bench(SCENE, 32, 24, out=3), r"^out: expected a path"),
    ("bench-out-file", lambda: sl.bench(SCENE, 32, 24, out=SCENE), r"^out .*torus-floating\.json: exists and is not a directory$"),
    ("bench-out-no-parent", lambda: sl.bench(SCENE, 32, 24, out="no/such/b"), r"^out no/such/b: directory no/such does not exist$"),
]


@pytest.mark.parametrize("name,call,message", CASES, ids=[c[0] for c in CASES])
def test_bad_input(name, call, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a bench that wrongly ran would write here
    with pytest.raises(sl.InputError, match=message) as raised:
        call()
    assert isinstance(raised.value, ValueError) and "\n" not in str(raised.value)
    assert os.listdir(tmp_path) == [], name  # nothing written


SCENE_OBJECT = None


def scene_object():
    global SCENE_OBJECT
    if SCENE_OBJECT is None:
        SCENE_OBJECT = sl.load_scene(SCENE)
    return SCENE_OBJECT


# Arguments of the wrong type: one line naming the argument (pybind11's own
# error lists every signature over four lines); an int past C's int, or a
# number past a double's: InputError (a ValueError).
TYPE_CASES = [
    ("render-width-str", lambda: sl.render(scene_object(), "a", 10), TypeError, r"^width: expected an int, got str$"),
    ("render-width-float", lambda: sl.render(scene_object(), 10.5, 10), TypeError, r"^width: expected an int, got float$"),
    ("render-width-huge", lambda: sl.render(scene_object(), 2**70, 10), sl.InputError,
     r"^width 1180591620717411303424: expected an integer in -2147483648\.\.2147483647$"),
    ("render-time-str", lambda: sl.render(scene_object(), 10, 10, time="x"), TypeError, r"^time: expected a number, got str$"),
    ("render-time-past-double", lambda: sl.render(scene_object(), 10, 10, time=10**400), sl.InputError,
     r"^time 1000.*0: expected a finite number \(past a double's range\)$"),
    ("render-scene-none", lambda: sl.render(None, 10, 10), TypeError, r"^scene: expected a shadowlab\.Scene .*, got NoneType$"),
    ("render-scene-path", lambda: sl.render(SCENE, 10, 10), TypeError, r"^scene: expected a shadowlab\.Scene .*, got str$"),
    ("render-unknown-keyword", lambda: sl.render(scene_object(), 10, 10, foo=1), TypeError, r"^render\(\): no argument named foo$"),
    ("render-missing", lambda: sl.render(scene_object()), TypeError, r"^render\(\): missing argument width$"),
    ("render-too-many", lambda: sl.render(scene_object(), 10, 10, 0.0, 5), TypeError, r"^render\(\) takes at most 4 arguments, got 5$"),
    ("visibility-light-huge", lambda: sl.visibility(scene_object(), 2**40, 10, 10), sl.InputError, r"^light 1099511627776: expected an integer in"),
    ("visibility-coloured-str", lambda: sl.visibility(scene_object(), 0, 10, 10, coloured="yes"), TypeError,
     r"^coloured: expected True or False, got str$"),
    ("compare-soft-samples-huge", lambda: sl.compare(scene_object(), 10, 10, soft_samples=2**31), sl.InputError, r"^soft_samples 2147483648: "),
    ("bench-frames-str", lambda: sl.bench(SCENE, 32, 24, frames="3"), TypeError, r"^frames: expected an int, got str$"),
    ("load-scene-overrides-str", lambda: sl.load_scene(SCENE, "x"), TypeError, r"^overrides: expected a dict \{path: value\}, got str$"),
    ("with-overrides-int", lambda: scene_object().with_overrides(5), TypeError, r"^overrides: expected a dict \{path: value\}, got int$"),
    ("techniques-argument", lambda: sl.techniques(5), TypeError, r"^techniques\(\) takes at most 0 arguments, got 1$"),
]


@pytest.mark.parametrize("name,call,kind,message", TYPE_CASES, ids=[c[0] for c in TYPE_CASES])
def test_argument_of_the_wrong_type(name, call, kind, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(kind, match=message) as raised:
        call()
    assert type(raised.value) is kind and "\n" not in str(raised.value)
    assert os.listdir(tmp_path) == [], name


def test_good_calls_keep_their_conversions():
    import numpy as np
    scene = scene_object()
    assert sl.render(scene, np.int64(16), 12, time=np.float32(0.0)).shape == (12, 16, 4)  # numpy numbers
    assert sl.render(scene, 16, 12, 1).shape == (12, 16, 4)  # an int for the time
    assert sl.visibility(scene, light=0, width=16, height=12, coloured=np.bool_(False)).shape == (12, 16)


def test_paths_may_be_pathlike_and_calls_work_after_errors():
    scene = sl.load_scene(pathlib.Path(SCENE))
    with pytest.raises(ValueError):
        sl.render(scene, 0, 0)
    assert sl.render(scene, 32, 24).shape == (24, 32, 4)


def test_with_overrides_replaces_a_key():
    scene = sl.load_scene(SCENE, {"lights[0].intensity": 2})
    assert scene.with_overrides({"lights[0].intensity": 3}).lights[0]["intensity"] == 3
    assert scene.with_overrides({"lights[00].intensity": 4}).lights[0]["intensity"] == 4  # the same path written another way
    # A block given whole replaces the paths inside it that the scene was loaded with.
    block = scene.with_overrides({"lights[0]": {"type": "directional", "direction": [0, -1, 0]}})
    assert block.lights[0]["intensity"] == 1
    # A path inside a block refines it, in one dict too: its value is applied (and checked).
    with pytest.raises(ValueError, match=r"lights\[0\]\.shadow\.map\.size.*got 7"):
        sl.default_scene({"lights[0].shadow.map": {"filter": "none"}, "lights[0].shadow.map.size": 7})
