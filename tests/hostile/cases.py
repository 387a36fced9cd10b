"""The battery's cases. Each is a dict: id, kind, tool (cli|view|py), argv or code,
expect (error|ok|either), names (substrings the one-line error must hold),
setup(dir) to make files in the case's own directory, env, timeout, outputs
(files an accepted run must write), progress (bench progress lines allowed)."""
import copy
import json
import os
import re
import subprocess

from fixtures import BASE, GLTF_CASES

SIZE = ["--width", "48", "--height", "32"]
LONG = "x" * 100000


def C(kind, id, argv=None, expect="error", names=(), tool="cli", timeout=60, setup=None, env=None, outputs=(), progress=False,
      code=None, allow_new=(), absent=()):
    return {"kind": kind, "id": id, "argv": argv, "expect": expect, "names": list(names), "tool": tool, "timeout": timeout,
            "setup": setup, "env": env or {}, "outputs": list(outputs), "progress": progress, "code": code,
            "allow_new": list(allow_new), "absent": list(absent)}


def writer(files):
    """setup that writes {name: text|bytes|None(dir)|('fifo',)} into the case dir."""
    def setup(d):
        for name, data in files.items():
            p = os.path.join(d, name)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            if data is None:
                os.makedirs(p, exist_ok=True)
            elif data == ("fifo",):
                os.mkfifo(p)
            elif isinstance(data, tuple) and data[0] == "symlink":
                os.symlink(data[1], p)
            elif isinstance(data, bytes):
                open(p, "wb").write(data)
            else:
                open(p, "w").write(data if isinstance(data, str) else json.dumps(data))
    return setup


def techniques_tables(binary, env):
    md = subprocess.run([binary, "techniques", "--markdown"], capture_output=True, text=True, env=env, timeout=60).stdout
    tables, tech = {}, None
    for line in md.splitlines():
        m = re.match(r"#### `lights\[i\]\.shadow\.(\w+)`", line)
        if m:
            tech = m.group(1)
            tables[tech] = []
            continue
        if tech and line.startswith("| `"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            key = cells[0].strip("`")
            tables[tech].append({"key": key, "type": cells[1], "default": cells[2].strip("`"), "allowed": cells[3]})
    return tables


def sid(s):
    return re.sub(r"[^A-Za-z0-9]+", "-", s).strip("-")[:40] or "empty"


def option_cases(ctx):
    env = {"LD_LIBRARY_PATH": os.path.join(ctx["snapshot"], "bin")}
    tables = techniques_tables(ctx["bin"], env)
    S = ctx["scenes"]
    sun, point, spot, discs = (os.path.join(S, n) for n in ("two-boxes-sun.json", "room-point.json", "spot-objects.json", "discs.json"))
    point_opts = {"cubePasses", "faceCulling", "diskRadius", "diskGrowth"}
    out = []
    full_int = {"size"}
    full_num = {"constantBias", "warpNear"}
    full_enum = {"filter"}
    for tech, opts in tables.items():
        for o in opts:
            key, typ, allowed = o["key"], o["type"], o["allowed"]
            path = f"lights[0].shadow.{tech}.{key}"
            scene = point if key in point_opts else (discs if tech == "disc" else (spot if key == "atlas" else sun))
            base = ["render", scene, "-o", "out.png"] + SIZE + ["--set", f"lights[0].shadow.technique={tech}"]
            bad = []
            m = re.match(r"(-?[\d.]+)\.\.(-?[\d.]+)", allowed)
            if typ == "integer" and m:
                lo, hi = int(m.group(1)), int(m.group(2))
                bad = [str(lo - 1), str(hi + 1), "1.5", "abc", "null", "1e999", "99999999999999999999999", ""]
                if key in full_int:
                    bad += ["-99999999999999999999999", '"16"', "true", "[16]", "{}", "nan", "inf", "0x10", LONG, "1\x01"]
                valid = str(lo if key != "size" else 64)
                if key == "cascades":
                    valid = str(hi)
            elif typ == "number" and m:
                lo, hi = float(m.group(1)), float(m.group(2))
                bad = [repr(lo - 1 if lo == 0 else lo / 2), repr(hi * 2 + 1), "nan", "1e39", "abc", ""]
                if key in full_num:
                    bad += ["inf", "-inf", "Infinity", "NaN", "1e999", '"0.05"', "true", "[0]", "-0x1", LONG]
                valid = m.group(2)
            elif typ == "boolean":
                bad = ["yes", "1", "null"]
                valid = "true" if o["default"] == "false" else "false"
            elif typ == "string" and allowed.startswith('"'):
                choices = re.findall(r'"([^"]*)"', allowed)
                bad = ["bogus", "5", o["default"].strip('"').upper() or "X", ""]
                if key in full_enum:
                    bad += [LONG, "a\nb", "\x1b[31mred", "{}", "[]", "null", '"hardware', "hard ware", b"\xff\xfe".decode("latin1")]
                valid = None
                for ch in choices:
                    if ch == o["default"].strip('"'):
                        continue
                    sc = scene
                    extra = []
                    if key == "filter" and ch == "pcf20":
                        sc = point
                    if key == "preset" and ch == "lecture-000":
                        sc = point
                    if key == "filter" and ch == "pcss":
                        extra = ["--set", "lights[0].size=2"]
                    if key == "filter" and ch == "dither4":
                        pass
                    argv = ["render", sc, "-o", "out.png"] + SIZE + ["--set", f"lights[0].shadow.technique={tech}", "--set", f"{path}={ch}"] + extra
                    out.append(C("option-valid", f"opt-ok-{tech}-{key}-{sid(ch)}", argv, "ok", outputs=["out.png"]))
            else:  # free strings: their own cases below
                bad = []
                valid = None
            for i, v in enumerate(bad):
                vid = sid(v) if v != LONG else "long"
                out.append(C("option-bad", f"opt-bad-{tech}-{key}-{i}-{vid}", base + ["--set", f"{path}={v}"], "error",
                             names=[f"--set {path}=", path]))
            if valid is not None:
                sc = scene
                extra = []
                if key == "kernel":
                    extra = ["--set", f"lights[0].shadow.map.filter=grid"]
                out.append(C("option-valid", f"opt-ok-{tech}-{key}-{sid(valid)}", base + ["--set", f"{path}={valid}"] + extra, "ok", outputs=["out.png"]))
    # free-string options
    M = "lights[0].shadow.map."
    sunr = ["render", sun, "-o", "out.png"] + SIZE
    for v, exp in [("5 4", "error"), ("1 2 3 4", "error"), ("a b", "error"), ("nan 5", "error"), ("inf 5", "error"), ("-1 5", "error"),
                   ("0 5", "error"), ("1e39 1e40", "error"), ("5,10", "ok"), ("1 1000000", "error"), ("0.0001 5", "error"), ("2 2", "error"),
                   ("", "ok"), ("2 6", "ok"), (" 2  6 ", "either")]:
        argv = sunr + ["--set", M + "cascades=3", "--set", M + "cascadeSplits=" + v]
        out.append(C("option-bad" if exp == "error" else "option-valid", f"opt-cascadeSplits-{sid(v)}-{len(v)}", argv, exp,
                     names=["--set " + M + "cascadeSplits=", M + "cascadeSplits"], outputs=["out.png"] if exp == "ok" else []))
    P = "lights[0].shadow.planar.receivers"
    for v, exp in [("nowhere", "error"), ("ground,nowhere", "error"), (",", "either"), ("tall box", "error"), (LONG, "error"),
                   ("ground", "ok"), ("ground,ground", "either")]:
        argv = sunr + ["--set", "lights[0].shadow.technique=planar", "--set", f"{P}={v}"]
        out.append(C("option-bad" if exp == "error" else "option-valid", f"opt-planar-receivers-{sid(v) if v != LONG else 'long'}", argv, exp,
                     names=[f"--set {P}=", P], outputs=["out.png"] if exp == "ok" else []))
    Dp = "lights[0].shadow.disc.casters"
    discr = ["render", discs, "-o", "out.png"] + SIZE
    for v, exp in [("nowhere", "error"), ("ground", "error"), ("ufo 1,nowhere", "error"), ("ufo 1", "ok"), ("ufo 1,ufo 2", "ok")]:
        out.append(C("option-bad" if exp == "error" else "option-valid", f"opt-disc-casters-{sid(v)}", discr + ["--set", f"{Dp}={v}"], exp,
                     names=[f"--set {Dp}=", Dp], outputs=["out.png"] if exp == "ok" else []))
    return out


def combo_cases(ctx):
    S = ctx["scenes"]
    sun, point, spot = (os.path.join(S, n) for n in ("two-boxes-sun.json", "room-point.json", "spot-objects.json"))
    M = "lights[0].shadow.map."
    r = lambda sc: ["render", sc, "-o", "out.png"] + SIZE
    out = [
        C("combo", "combo-pcf20-on-spot", r(spot) + ["--set", M + "filter=pcf20"], names=["--set " + M + "filter=pcf20"]),
        C("combo", "combo-dither4-on-point", r(point) + ["--set", M + "filter=dither4"], names=["--set " + M + "filter=dither4"]),
        C("combo", "combo-vsm-on-point", r(point) + ["--set", M + "representation=vsm"], names=["--set " + M + "representation=vsm"]),
        C("combo", "combo-atlas-on-directional", r(sun) + ["--set", M + "atlas=true"], "either", names=["--set " + M + "atlas=true"], allow_new=[]),
        C("combo", "combo-atlas-grid-on-spot", r(spot) + ["--set", M + "atlas=true", "--set", M + "filter=grid"], names=["--set " + M]),
        C("combo", "combo-cascades-on-spot", r(spot) + ["--set", M + "cascades=4"], "either", names=["--set " + M + "cascades=4"]),
        C("combo", "combo-splits-without-cascades", r(sun) + ["--set", M + "cascadeSplits=2 6"], names=["--set " + M + "cascadeSplits=2 6"]),
        C("combo", "combo-splits-count-cascades-set-later", r(sun) + ["--set", M + "cascadeSplits=2 6", "--set", M + "cascades=4"],
          names=["--set " + M + "casc"]),
        C("combo", "combo-technique-via-set-splits-bad",
          r(sun) + ["--set", "lights[0].shadow.technique=map", "--set", M + "cascades=3", "--set", M + "cascadeSplits=6 2"],
          names=["--set " + M + "cascadeSplits=6 2", M + "cascadeSplits"]),
        C("combo", "combo-budget-cascades8-16384", r(sun) + ["--set", M + "size=16384", "--set", M + "cascades=8"], names=["--set " + M]),
        C("combo", "combo-budget-msm-8192", r(sun) + ["--set", M + "size=8192", "--set", M + "representation=msm"], "either", names=["--set " + M]),
        C("combo", "combo-budget-rgba8-16384", r(sun) + ["--set", M + "size=16384", "--set", M + "format=rgba8"], names=["--set " + M]),
        C("combo", "combo-budget-cube-16384", r(point) + ["--set", M + "size=16384"], names=["--set " + M + "size=16384"]),
        C("combo", "combo-budget-mipmaps-16384", r(sun) + ["--set", M + "size=16384", "--set", M + "mipmaps=true"], names=["--set " + M]),
        C("combo", "combo-planar-on-point", r(point) + ["--set", "lights[0].shadow.technique=planar"], "either",
          names=["--set lights[0].shadow.technique=planar"]),
        C("combo", "combo-volume-on-spot", r(spot) + ["--set", "lights[0].shadow.technique=volume"], "ok", outputs=["out.png"]),
        C("combo", "combo-disc-without-discs", r(sun) + ["--set", "lights[0].shadow.technique=disc"], "ok", outputs=["out.png"]),
        C("combo", "combo-technique-bogus", r(sun) + ["--set", "lights[0].shadow.technique=bogus"], names=["--set lights[0].shadow.technique=bogus"]),
        C("combo", "combo-lightgrid-300", ["render", os.path.join(S, "many-lights.json"), "-o", "out.png"] + SIZE + ["--set", "lightGrid.count=300"],
          names=["--set lightGrid.count=300"]),
        C("combo", "combo-lightgrid-technique-bogus", ["render", os.path.join(S, "many-lights.json"), "-o", "out.png"] + SIZE +
          ["--set", "lightGrid.light.shadow.technique=bogus"], names=["--set lightGrid.light.shadow.technique=bogus"]),
        C("combo", "combo-atlas-size-300", ["render", os.path.join(S, "many-lights.json"), "-o", "out.png"] + SIZE + ["--set", "shadowAtlas.size=300"],
          names=["--set shadowAtlas.size=300"]),
        C("combo", "combo-atlas-mintile-gt-maxtile", ["render", os.path.join(S, "many-lights.json"), "-o", "out.png"] + SIZE +
          ["--set", "shadowAtlas.minTile=512", "--set", "shadowAtlas.maxTile=64"], names=["--set shadowAtlas."]),
        C("combo", "combo-view-from-point-light", ["render", point, "-o", "out.png"] + SIZE + ["--view-from-light", "0"], names=["--view-from-light 0"]),
        C("combo", "combo-view-from-light-missing", ["render", sun, "-o", "out.png"] + SIZE + ["--view-from-light", "3"], names=["--view-from-light 3"]),
        C("combo", "combo-second-light-budget",
          r(sun) + ["--set", 'lights=[{"type":"directional"},{"type":"directional","shadow":{"map":{"size":16384,"format":"rgba8"}}}]'],
          names=["--set lights=", "lights[1]"]),
        C("combo", "combo-file-splits-set-cascades", ["render", "s.json", "-o", "out.png"] + SIZE + ["--set", M + "cascades=2"],
          names=["cascade"], setup=writer({"s.json": dict(copy.deepcopy(BASE), lights=[{"type": "directional", "shadow": {"map": {"cascades": 4, "cascadeSplits": "1 2 3"}}}])})),
        C("combo", "combo-pcss-hard-light", r(sun) + ["--set", M + "filter=pcss"], "either", names=["--set " + M + "filter=pcss"]),
        C("combo", "combo-lispsm-stabilized-cascades", r(sun) + ["--set", M + "warp=lispsm", "--set", M + "cascades=4"], "either", names=["--set " + M]),
        C("combo", "combo-sdsm-on-spot", r(spot) + ["--set", M + "fit=sdsm"], "either", names=["--set " + M + "fit=sdsm"]),
        C("combo", "combo-volume-alpha-tested-glass", ["render", os.path.join(S, "glass-panel.json"), "-o", "out.png"] + SIZE +
          ["--set", "lights[0].shadow.technique=volume"], "either", names=["lights[0].shadow.technique"]),
        C("combo", "combo-debug-cascades-no-cascades", r(sun) + ["--debug", "cascades"], "ok", outputs=["out.png"]),
    ]
    return out


def set_syntax_cases(ctx):
    b = ["render", "-o", "out.png"] + SIZE
    L = "lights[0].intensity"
    cases = [
        ("noequals", ["--set", "lights"], ["--set lights"]),
        ("empty-key", ["--set", "=5"], ["--set =5"]),
        ("empty", ["--set", ""], ["--set"]),
        ("empty-value-number", ["--set", L + "="], ["--set " + L + "=", L]),
        ("index-negative", ["--set", "lights[-1].intensity=1"], ["--set lights[-1].intensity=1"]),
        ("index-huge", ["--set", "lights[99999999999999999999].intensity=1"], ["--set lights[99999999999999999999].intensity=1"]),
        ("index-fraction", ["--set", "lights[0.5].intensity=1"], ["--set lights[0.5].intensity=1"]),
        ("index-unclosed", ["--set", "lights[0.intensity=1"], ["--set lights[0.intensity=1"]),
        ("double-dot", ["--set", "lights[0]..intensity=1"], ["--set lights[0]..intensity=1"]),
        ("trailing-dot", ["--set", "camera.=1"], ["--set camera.=1"]),
        ("dot-index", ["--set", "lights.0.intensity=1"], ["--set lights.0.intensity=1"]),
        ("index-on-object", ["--set", "camera[0]=1"], ["--set camera[0]=1"]),
        ("key-on-array", ["--set", "lights.x=1"], ["--set lights.x=1"]),
        ("key-on-number", ["--set", "camera.fovY.x=1"], ["--set camera.fovY.x=1"]),
        ("unknown-top", ["--set", "bogus=1"], ["--set bogus=1"]),
        ("long-key", ["--set", "a" * 100000 + "=1"], ["--set aaaa"]),
        ("control-key", ["--set", "cam\x01era.fovY=1"], ["--set cam"]),
        ("newline-value", ["--set", "lights[0].type=spot\nlight"], ["--set lights[0].type=spot", "lights[0].type"]),
        ("invalid-utf8-value", ["--set", b"name=\xff\xfe".decode("utf-8", "surrogateescape")], ["--set name="]),
        ("deep-value", ["--set", "name=" + "[" * 60000 + "]" * 60000], ["--set name="]),
        ("deep-value-300", ["--set", "camera=" + "[" * 300 + "]" * 300], ["--set camera="]),
        ("object-bad-inner", ["--set", 'camera={"fovY":0}'], ['--set camera={"fovY":0}', "camera.fovY"]),
        ("object-unknown-inner", ["--set", 'camera={"fov":30}'], ['--set camera={"fov":30}', "camera.fov"]),
        ("array-bad-element", ["--set", 'lights[0].color=[1,"a",1]'], ["--set lights[0].color=", "lights[0].color[1]"]),
        ("nan-literal", ["--set", L + "=NaN"], ["--set " + L + "=NaN", L]),
        ("inf-literal", ["--set", L + "=Infinity"], ["--set " + L + "=Infinity", L]),
        ("number-1e999", ["--set", L + "=1e999"], ["--set " + L + "=1e999", L]),
        ("number-float-overflow", ["--set", L + "=1e39"], ["--set " + L + "=1e39", L]),
        ("twice", ["--set", L + "=1", "--set", L + "=2"], ["--set " + L + "=2"]),
        ("twice-written-apart", ["--set", L + "=1", "--set", "lights[00].intensity=2"], ["--set lights[00].intensity=2"]),
        ("twice-space", ["--set", L + "=1", "--set", " lights[0].intensity=2"], ["intensity=2"]),
        ("outer-after-inner", ["--set", "lights[0].shadow.map.size=7", "--set", 'lights[0].shadow.map={"filter":"none"}'], ["--set lights[0].shadow.map"]),
        ("mesh-devzero", ["--set", 'nodes=[{"mesh":"/dev/zero"}]'], ["--set nodes=", "/dev/zero"]),
        ("mesh-fifo", ["--set", 'nodes=[{"mesh":"%s"}]' % os.path.join(ctx["fix"], "fifo.obj")], ["--set nodes=", "fifo.obj"]),
        ("mesh-dir", ["--set", 'nodes=[{"mesh":"%s"}]' % os.path.join(ctx["fix"], "dir.obj")], ["--set nodes=", "dir.obj"]),
        ("mesh-missing", ["--set", 'nodes=[{"mesh":"nope.obj"}]'], ["--set nodes=", "nope.obj"]),
        ("mesh-no-ext", ["--set", 'nodes=[{"mesh":"%s"}]' % os.path.join(ctx["fix"], "base.json")], ["--set nodes=", "base.json"]),
        ("texture-devzero", ["--set", 'materials={"m":{"baseColorTexture":"/dev/zero"}}'], ["--set materials=", "/dev/zero"]),
        ("projector-fifo", ["--set", 'lights=[{"type":"spot","position":[0,3,0],"projector":"%s"}]' % os.path.join(ctx["fix"], "fifo.png")],
         ["--set lights=", "fifo.png"]),
        ("light-type-none", ["--set", "lights[0].type=none"], ["--set lights[0].type=none", "lights[0].type"]),
        ("position-on-directional", ["--set", "lights[0].position=[0,1,0]"], ["--set lights[0].position=", "lights[0].position"]),
        ("many-sets-ok", sum([["--set", f"lights[0].shadow.map.{k}={v}"] for k, v in
                              [("size", 256), ("filter", "grid"), ("kernel", 4), ("slopeBias", 2), ("normalBias", 0.5)]], []), None),
        ("inner-after-outer-ok", ["--set", 'lights[0].shadow.map={"size":512}', "--set", "lights[0].shadow.map.size=256"], None),
        ("string-for-type-ok", ["--set", "lights[0].type=directional"], None),
        ("long-name-ok", ["--set", "name=" + LONG], None),
        ("outer-after-inner-whole-light", ["--set", "lights[0].intensity=-1", "--set", 'lights[0]={"type":"directional"}'], ["--set lights[0]"]),
        ("width-twice", ["--width", "64"], ["--width"]),
    ]
    out = []
    for name, args, names in cases:
        if names is None:
            out.append(C("set-syntax", "set-" + name, b + args, "ok", outputs=["out.png"]))
        else:
            out.append(C("set-syntax", "set-" + name, b + args, names=names))
    return out


def vary_cases(ctx):
    base = os.path.join(ctx["fix"], "base.json")
    b = ["bench", base, "-o", "b", "--frames", "1", "--warmup", "0", "--width", "32", "--height", "24"]
    L = "lights[0].intensity"
    cases = [
        ("noequals", ["--vary", L], ["--vary " + L]),
        ("empty-key", ["--vary", "=1,2"], ["--vary =1,2"]),
        ("empty-values", ["--vary", L + "="], ["--vary " + L + "="]),
        ("empty-value-between", ["--vary", L + "=1,,2"], ["--vary " + L + "=1,,2"]),
        ("empty-arg", ["--vary", ""], ["--vary"]),
        ("duplicate-values", ["--vary", L + "=1,1"], ["--vary " + L + "=1,1"]),
        ("duplicate-key", ["--vary", L + "=1,2", "--vary", L + "=3"], ["--vary " + L + "=3"]),
        ("duplicate-key-written-apart", ["--vary", L + "=1,2", "--vary", "lights[00].intensity=3"], ["--vary lights[00].intensity=3"]),
        ("inner-and-outer", ["--vary", "lights[0].shadow.map.size=256,512", "--vary", 'lights[0].shadow.map={"size":64}'], ["--vary lights[0].shadow.map"]),
        ("vary-and-set", ["--set", L + "=2", "--vary", L + "=1,3"], ["--vary " + L + "=1,3", "--set " + L + "=2"]),
        ("unknown-key", ["--vary", "camera.fov=30,40"], ["--vary camera.fov=", "camera.fov"]),
        ("bad-second-value", ["--vary", L + "=1,-1"], ["--vary " + L, "-1", L]),
        ("bad-technique", ["--vary", "lights[0].shadow.technique=map,bogus"], ["--vary lights[0].shadow.technique", "bogus"]),
        ("index-out-of-range", ["--vary", "lights[5].intensity=1,2"], ["--vary lights[5].intensity=", "lights[5]"]),
        ("too-many-runs", ["--vary", "lights[0].shadow.map.size=" + ",".join(str(16 + i) for i in range(101)),
                           "--vary", L + "=" + ",".join(str(i) for i in range(100))], ["--vary"]),
        ("json-object-values", ["--vary", 'lights[0].shadow.map={"size":7},{"size":8}'], ["--vary lights[0].shadow.map"]),
        ("nan-value", ["--vary", L + "=1,nan"], ["--vary " + L, L]),
        ("control-char", ["--vary", "lights[0].shadow.map.filter=none,\x1b[2J"], ["--vary lights[0].shadow.map.filter"]),
        ("combo-bad", ["--vary", "lights[0].shadow.map.filter=pcf20,none"], ["--vary lights[0].shadow.map.filter", "pcf20"]),
        ("combo-bad-across", ["--vary", "lights[0].shadow.map.cascades=1,3", "--vary", "lights[0].shadow.map.cascadeSplits=2 6"],
         ["--vary lights[0].shadow.map.casc"]),
        ("flips-one-frame", ["--flips"], ["--flips"]),
        ("ok-two", ["--vary", L + "=1,2"], None),
        ("ok-long-name", ["--vary", "name=a," + LONG], None),
        ("ok-spaces", ["--vary", "lights[0].shadow.map.filter=none, grid"], "either"),
    ]
    out = []
    for name, args, names in cases:
        if names is None:
            out.append(C("vary", "vary-" + name, b + args, "ok", progress=True, outputs=["b/results.json"]))
        elif names == "either":
            out.append(C("vary", "vary-" + name, b + args, "either", progress=True, names=["--vary"]))
        else:
            out.append(C("vary", "vary-" + name, b + args, names=names, progress=True))
    # bench scene lists
    fx = ctx["fix"]
    for name, scn, names in [("missing", "nope.json", ["nope.json"]), ("dir", os.path.join(fx, "dir.json"), ["dir.json"]),
                             ("fifo", os.path.join(fx, "fifo.json"), ["fifo.json"]), ("devzero", "/dev/zero", ["/dev/zero"]),
                             ("empty-file", os.path.join(fx, "empty.json"), ["empty.json"]), ("empty-arg", "", ["scene"]),
                             ("second-bad", os.path.join(fx, "deep.json"), ["deep.json"])]:
        out.append(C("vary", "bench-scene-" + name, ["bench", base, scn, "-o", "b", "--frames", "1", "--warmup", "0", "--width", "32", "--height", "24"],
                     names=names, progress=True))
    S = ctx["scenes"]
    sun, point = os.path.join(S, "two-boxes-sun.json"), os.path.join(S, "room-point.json")
    bb = ["-o", "b", "--frames", "1", "--warmup", "0", "--width", "32", "--height", "24"]
    out.append(C("vary", "bench-set-bad-for-one-scene", ["bench", point, sun] + bb + ["--set", "lights[0].shadow.map.filter=pcf20"],
                 names=["--set lights[0].shadow.map.filter=pcf20", "two-boxes-sun.json"], progress=True))
    out.append(C("vary", "bench-vary-bad-for-one-scene", ["bench", point, sun] + bb + ["--vary", "lights[0].shadow.map.filter=hardware,pcf20"],
                 names=["--vary lights[0].shadow.map.filter=", "pcf20", "two-boxes-sun.json"], progress=True))
    out.append(C("vary", "bench-same-scene-twice", ["bench", base, base, "-o", "b", "--frames", "1", "--warmup", "0", "--width", "32", "--height", "24"],
                 "either", names=["base.json"], progress=True))
    return out


def scene_json_cases(ctx):
    def mut(f):
        s = copy.deepcopy(BASE)
        f(s)
        return s
    def cam(k, v):
        return lambda s: s["camera"].__setitem__(k, v)
    def light(k, v, base=None):
        def f(s):
            if base:
                s["lights"][0] = dict(base)
            if v is DEL:
                s["lights"][0].pop(k, None)
            else:
                s["lights"][0][k] = v
        return f
    def node(i, k, v):
        return lambda s: s["nodes"][i].__setitem__(k, v)
    def shape(v):
        return lambda s: s["nodes"][1].__setitem__("shape", v)
    def top(k, v):
        return lambda s: s.__setitem__(k, v)
    DEL = object()
    SPOT = {"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0]}
    POINT = {"type": "point", "position": [0, 4, 0]}
    muts = [
        ("top-name-number", top("name", 5), "name"),
        ("top-ambient-negative", top("ambient", [-1, 0, 0]), "ambient"),
        ("top-ambient-float-overflow", top("ambient", [1e39, 0, 0]), "ambient"),
        ("top-background-string", top("background", "black"), "background"),
        ("top-unknown-key", top("lihgts", []), "lihgts"),
        ("camera-array", top("camera", []), "camera"),
        ("camera-position-string", cam("position", "x"), "camera.position"),
        ("camera-position-2", cam("position", [1, 2]), "camera.position"),
        ("camera-position-mixed", cam("position", [1, 2, "a"]), "camera.position"),
        ("camera-position-1e39", cam("position", [1e39, 0, 0]), "camera.position"),
        ("camera-target-eq-position", cam("target", [3, 3, 5]), "camera"),
        ("camera-up-zero", cam("up", [0, 0, 0]), "camera.up"),
        ("camera-up-parallel", cam("up", [3, 2.5, 5]), "camera"),
        ("camera-fovy-0", cam("fovY", 0), "camera.fovY"),
        ("camera-fovy-180", cam("fovY", 180), "camera.fovY"),
        ("camera-fovy-string", cam("fovY", "45"), "camera.fovY"),
        ("camera-near-0", cam("near", 0), "camera.near"),
        ("camera-far-lt-near", cam("far", 0.05), "camera.far"),
        ("camera-path-sine", cam("path", {"type": "sine"}), "camera.path"),
        ("camera-path-times-decreasing", cam("path", {"type": "keyframes", "times": [1, 0], "positions": [[3, 3, 5], [3, 3, 6]], "targets": [[0, 0, 0], [0, 0, 0]]}), "camera.path.times"),
        ("camera-path-count-mismatch", cam("path", {"type": "keyframes", "times": [0, 1], "positions": [[3, 3, 5]], "targets": [[0, 0, 0], [0, 0, 0]]}), "camera.path.positions"),
        ("camera-path-no-targets", cam("path", {"type": "keyframes", "times": [0], "positions": [[3, 3, 5]]}), "camera.path"),
        ("camera-path-empty-times", cam("path", {"type": "keyframes", "times": [], "positions": [], "targets": []}), "camera.path.times"),
        ("camera-path-through-up", cam("path", {"type": "keyframes", "times": [0, 1], "positions": [[0, 5, 0.001], [0, 5, 0]], "targets": [[0, 0, 0], [0, 0, 0]]}), "camera.path"),
        ("camera-unknown", cam("fov", 30), "camera.fov"),
        ("materials-array", top("materials", []), "materials"),
        ("material-shininess-0", top("materials", {"m": {"shininess": 0}}), "materials.m.shininess"),
        ("material-alpha-2", top("materials", {"m": {"alpha": 2}}), "materials.m.alpha"),
        ("material-alphamode-bogus", top("materials", {"m": {"alphaMode": "bogus"}}), "materials.m.alphaMode"),
        ("material-alphacutoff-neg", top("materials", {"m": {"alphaCutoff": -1}}), "materials.m.alphaCutoff"),
        ("material-basecolor-neg", top("materials", {"m": {"baseColor": [-1, 0, 0]}}), "materials.m.baseColor"),
        ("material-unknown", top("materials", {"m": {"colour": [1, 0, 0]}}), "materials.m.colour"),
        ("material-texture-number", top("materials", {"m": {"baseColorTexture": 5}}), "materials.m.baseColorTexture"),
        ("material-texture-empty", top("materials", {"m": {"baseColorTexture": ""}}), "materials.m.baseColorTexture"),
        ("node-material-undefined", node(1, "material", "nope"), "nodes[1].material"),
        ("lights-object", top("lights", {}), "lights"),
        ("light-no-type", light("type", DEL), "lights[0]"),
        ("light-type-area", light("type", "area"), "lights[0].type"),
        ("light-intensity-neg", light("intensity", -1), "lights[0].intensity"),
        ("light-intensity-string", light("intensity", "1"), "lights[0].intensity"),
        ("light-position-on-directional", light("position", [0, 1, 0]), "lights[0].position"),
        ("light-direction-zero", light("direction", [0, 0, 0]), "lights[0].direction"),
        ("light-direction-on-point", light("direction", [0, -1, 0], POINT), "lights[0].direction"),
        ("light-point-no-position", light("position", DEL, POINT), "lights[0]"),
        ("light-range-neg", light("range", -1, POINT), "lights[0].range"),
        ("light-inner-gt-outer", light("innerCone", 40, SPOT), "lights[0].innerCone"),
        ("light-outer-90", light("outerCone", 90, SPOT), "lights[0].outerCone"),
        ("light-outer-0", light("outerCone", 0, SPOT), "lights[0].outerCone"),
        ("light-size-neg", light("size", -1), "lights[0].size"),
        ("light-directional-size-90", light("size", 90), "lights[0].size"),
        ("light-projector-missing", light("projector", "nope.png", SPOT), "lights[0].projector"),
        ("light-projector-dir", light("projector", ".", SPOT), "lights[0].projector"),
        ("light-path-on-directional", light("path", {"type": "sine"}), "lights[0].path"),
        ("light-path-type-bogus", light("path", {"type": "spiral"}, POINT), "lights[0].path.type"),
        ("light-path-times-equal", light("path", {"type": "keyframes", "times": [0, 0], "positions": [[0, 4, 0], [0, 4, 1]]}, POINT), "lights[0].path.times"),
        ("light-path-freq-neg", light("path", {"type": "sine", "angularFrequency": -1}, POINT), "lights[0].path.angularFrequency"),
        ("light-path-amplitude-overflow", light("path", {"type": "sine", "amplitude": [3e38, 0, 0]}, dict(POINT, position=[3e38, 4, 0])), "lights[0].path.amplitude"),
        ("light-shadow-string", light("shadow", "map"), "lights[0].shadow"),
        ("light-shadow-technique-bogus", light("shadow", {"technique": "bogus"}), "lights[0].shadow.technique"),
        ("light-shadow-technique-number", light("shadow", {"technique": 5}), "lights[0].shadow.technique"),
        ("light-shadow-map-size-7", light("shadow", {"map": {"size": 7}}), "lights[0].shadow.map.size"),
        ("light-shadow-unknown-block", light("shadow", {"mapp": {}}), "lights[0].shadow.mapp"),
        ("light-shadow-unknown-option", light("shadow", {"map": {"sise": 512}}), "lights[0].shadow.map.sise"),
        ("light-shadow-volume-unused-bad", light("shadow", {"technique": "map", "volume": {"method": "bogus"}}), "lights[0].shadow.volume.method"),
        ("lightgrid-count-300", top("lightGrid", {"count": 300}), "lightGrid.count"),
        ("lightgrid-count-neg", top("lightGrid", {"count": -1}), "lightGrid.count"),
        ("lightgrid-count-fraction", top("lightGrid", {"count": 1.5}), "lightGrid.count"),
        ("lightgrid-seed-neg", top("lightGrid", {"seed": -1}), "lightGrid.seed"),
        ("lightgrid-seed-2-31", top("lightGrid", {"seed": 2**31}), "lightGrid.seed"),
        ("lightgrid-min-gt-max", top("lightGrid", {"min": [1, 1], "max": [0, 0]}), "lightGrid.m"),
        ("lightgrid-spots-2", top("lightGrid", {"spots": 2}), "lightGrid.spots"),
        ("lightgrid-light-position", top("lightGrid", {"light": {"position": [0, 0, 0]}}), "lightGrid.light"),
        ("lightgrid-light-keyframes", top("lightGrid", {"light": {"path": {"type": "keyframes", "times": [0], "positions": [[0, 0, 0]]}}}), "lightGrid.light"),
        ("lightgrid-light-bad-option", top("lightGrid", {"count": 2, "light": {"shadow": {"map": {"size": 7}}}}), "lightGrid.light"),
        ("atlas-size-300", top("shadowAtlas", {"size": 300}), "shadowAtlas.size"),
        ("atlas-size-32768", top("shadowAtlas", {"size": 32768}), "shadowAtlas.size"),
        ("atlas-mintile-3", top("shadowAtlas", {"minTile": 3}), "shadowAtlas.minTile"),
        ("atlas-mintile-gt-maxtile", top("shadowAtlas", {"minTile": 512, "maxTile": 64}), "shadowAtlas."),
        ("atlas-texels-0", top("shadowAtlas", {"texelsPerPixel": 0}), "shadowAtlas.texelsPerPixel"),
        ("atlas-budget-neg", top("shadowAtlas", {"updateBudget": -1}), "shadowAtlas.updateBudget"),
        ("nodes-object", top("nodes", {}), "nodes"),
        ("node-shape-and-mesh", node(1, "mesh", "x.obj"), "nodes[1]"),
        ("node-shape-type-blob", shape({"type": "blob"}), "nodes[1].shape.type"),
        ("node-shape-no-type", shape({"size": [1, 1, 1]}), "nodes[1].shape"),
        ("node-sphere-segments-2", shape({"type": "sphere", "segments": 2}), "nodes[1].shape.segments"),
        ("node-sphere-segments-1025", shape({"type": "sphere", "segments": 1025}), "nodes[1].shape.segments"),
        ("node-sphere-segments-2-64", shape({"type": "sphere", "segments": 2**64}), "nodes[1].shape.segments"),
        ("node-sphere-segments-fraction", shape({"type": "sphere", "segments": 1.5}), "nodes[1].shape.segments"),
        ("node-sphere-segments-string", shape({"type": "sphere", "segments": "48"}), "nodes[1].shape.segments"),
        ("node-torus-minor-ge-major", shape({"type": "torus", "majorRadius": 1, "minorRadius": 1}), "nodes[1].shape"),
        ("node-box-size-zero", shape({"type": "box", "size": [1, 0, 1]}), "nodes[1].shape.size"),
        ("node-plane-size-1", shape({"type": "plane", "size": [1]}), "nodes[1].shape.size"),
        ("node-disc-radius-neg", shape({"type": "disc", "radius": -1}), "nodes[1].shape.radius"),
        ("node-shape-unknown-key", shape({"type": "box", "radius": 1}), "nodes[1].shape.radius"),
        ("node-scale-0", node(1, "scale", 0), "nodes[1].scale"),
        ("node-scale-vec-zero", node(1, "scale", [1, 0, 1]), "nodes[1].scale"),
        ("node-scale-neg", node(1, "scale", -1), "nodes[1].scale"),
        ("node-scale-tiny", node(1, "scale", 1e-300), "nodes[1].scale"),
        ("node-rotation-string", node(1, "rotation", "x"), "nodes[1].rotation"),
        ("node-rotation-1e39", node(1, "rotation", [1e39, 0, 0]), "nodes[1].rotation"),
        ("node-translation-overflow-composed", lambda s: s["nodes"].append({"translation": [3e38, 0, 0], "children": [{"translation": [3e38, 0, 0], "shape": {"type": "box"}}]}), "nodes[2]"),
        ("node-scale-overflow-composed", lambda s: s["nodes"].append({"scale": 1e20, "children": [{"scale": 1e20, "shape": {"type": "box"}}]}), "nodes[2]"),
        ("node-children-number", node(1, "children", 5), "nodes[1].children"),
        ("node-casts-string", node(1, "castsShadows", "yes"), "nodes[1].castsShadows"),
        ("node-name-number", node(1, "name", 5), "nodes[1].name"),
        ("node-mesh-number", lambda s: s["nodes"].append({"mesh": 5}), "nodes[2].mesh"),
        ("node-mesh-empty", lambda s: s["nodes"].append({"mesh": ""}), "nodes[2].mesh"),
        ("node-unknown-key", node(1, "shadows", True), "nodes[1].shadows"),
        ("node-material-number", node(1, "material", 5), "nodes[1].material"),
    ]
    out = []
    for name, f, path in muts:
        out.append(C("scene-json", "json-" + name, ["render", "s.json", "-o", "out.png"] + SIZE, names=["s.json", path], setup=writer({"s.json": mut(f)})))
    raw = [
        ("syntax-open-brace", "{", None), ("syntax-missing-value", '{"name":}', None), ("syntax-single-quotes", "{'name': 'a'}", None),
        ("syntax-trailing-comma", '{"name": "a",}', None), ("syntax-comment", '// c\n{}', None), ("syntax-nan", '{"camera":{"fovY":NaN}}', None),
        ("syntax-1e999", '{"camera":{"fovY":1e999}}', None), ("syntax-5000-digits", '{"camera":{"fovY":' + "9" * 5000 + "}}", None),
        ("syntax-two-values", "{}{}", None), ("top-array", "[]", None), ("top-number", "5", None), ("top-null", "null", None),
        ("invalid-utf8", b'{"name": "\xff\xfe"}', None), ("nul-byte", b'{"name": "a\x00b"}', None), ("control-in-key", '{"li\\u0001ghts": []}', None),
        ("lone-surrogate", '{"name": "\\ud800"}', None), ("deep-nesting", "[" * 100000 + "]" * 100000, None),
        ("deep-nesting-201", '{"name":' + "[" * 201 + "]" * 201 + "}", None), ("empty", "", None), ("whitespace", " \n\t ", None),
        ("binary", bytes(range(256)) * 16, None),
    ]
    for name, text, _ in raw:
        out.append(C("scene-json", "json-" + name, ["render", "s.json", "-o", "out.png"] + SIZE, names=["s.json"], setup=writer({"s.json": text})))
    out.append(C("scene-json", "json-duplicate-key", ["render", "s.json", "-o", "out.png"] + SIZE, "either", names=["s.json", "name"],
                 setup=writer({"s.json": '{"name": "a", "name": "b"}'})))
    out.append(C("scene-json", "json-bom", ["render", "s.json", "-o", "out.png"] + SIZE, "either", names=["s.json"],
                 setup=writer({"s.json": b"\xef\xbb\xbf{}"})))
    fx = ctx["fix"]
    out.append(C("scene-json", "json-many-lights-300", ["render", os.path.join(fx, "many-lights.json"), "-o", "out.png"] + SIZE, names=["many-lights.json", "lights"]))
    out.append(C("scene-json", "json-children-150-levels", ["render", os.path.join(fx, "deep-children.json"), "-o", "out.png"] + SIZE, names=["deep-children.json"]))
    out.append(C("scene-json", "json-ok-base", ["render", os.path.join(fx, "base.json"), "-o", "out.png"] + SIZE, "ok", outputs=["out.png"]))
    out.append(C("scene-json", "json-ok-camera-far-1e30", ["render", "s.json", "-o", "out.png"] + SIZE, "ok", outputs=["out.png"],
                 setup=writer({"s.json": mut(cam("far", 1e30))})))
    out.append(C("scene-json", "json-ok-camera-near-1e-30", ["render", "s.json", "-o", "out.png"] + SIZE, "ok", outputs=["out.png"],
                 setup=writer({"s.json": mut(cam("near", 1e-30))})))
    out.append(C("scene-json", "json-ok-4-spheres-1024-segments", ["render", "s.json", "-o", "out.png"] + SIZE, "ok", outputs=["out.png"], timeout=120,
                 setup=writer({"s.json": mut(lambda s: s["nodes"].extend([{"shape": {"type": "sphere", "segments": 1024, "rings": 1024}}] * 4))})))
    # 400 spheres of 1024x1024 segments (2M triangles each): a 2 KB file asking for ~70 GB. Run under a 4 GB
    # address-space limit so that it cannot take this machine's memory; clean is a one-line refusal naming the file.
    c = C("scene-json", "json-geometry-400-spheres", ["render", "s.json", "-o", "out.png"] + SIZE, names=["s.json"], timeout=120,
          setup=writer({"s.json": mut(lambda s: s["nodes"].extend([{"shape": {"type": "sphere", "segments": 1024, "rings": 1024}}] * 400))}))
    c["aslimit"] = 4 << 30
    out.append(c)
    # scene paths
    for name, path, names in [("missing", "nope.json", ["nope.json"]), ("directory", os.path.join(fx, "dir.json"), ["dir.json"]),
                              ("fifo", os.path.join(fx, "fifo.json"), ["fifo.json"]), ("devzero", "/dev/zero", ["/dev/zero"]),
                              ("devzero-symlink", os.path.join(fx, "zero.json"), ["zero.json"]), ("devnull", "/dev/null", ["/dev/null"]),
                              ("empty-file", os.path.join(fx, "empty.json"), ["empty.json"]), ("symlink-loop", os.path.join(fx, "loop1.json"), ["loop1.json"]),
                              ("name-too-long", "a" * 5000 + ".json", ["aaaa"]), ("newline-name", "a\nb.json", ["a\\nb.json"]),
                              ("empty-arg", "", ["scene"]), ("dash", "-", ["-"]), ("proc-dir", "/proc/self", ["/proc/self"]),
                              ("nul-json", os.path.join(fx, "nul.json"), ["nul.json"]), ("latin1", os.path.join(fx, "latin1.json"), ["latin1.json"])]:
        out.append(C("scene-path", "path-" + name, ["render", path, "-o", "out.png"] + SIZE, names=names))
        if name in ("fifo", "devzero", "directory"):
            out.append(C("scene-path", "path-compare-" + name, ["compare", path, "-o", "c", "--width", "32", "--height", "24"], names=names))
    return out


def mesh_cases(ctx):
    fx = ctx["fix"]
    out = []
    either = {"empty.obj", "comments.obj", "gltf-mode-points.gltf", "gltf-sparse.gltf"}
    ok = {"ok.obj", "gltf-ok.gltf", "glb-ok.glb"}
    names = sorted(n for n in os.listdir(fx) if n.startswith("scene-mesh-")) if os.path.isdir(fx) else []
    if not names:  # listed before the fixtures exist: from the generator's own lists
        meshes = ["ok.obj", "empty.obj", "comments.obj", "index-past.obj", "index-zero.obj", "index-negative-past.obj", "index-huge.obj",
                  "vt-past.obj", "vn-past.obj", "two-vertex-face.obj", "short-vertex.obj", "nan-vertex.obj", "inf-vertex.obj", "word-vertex.obj",
                  "garbage.obj", "truncated.obj", "face-letters.obj", "fifo.obj", "dir.obj", "zero.obj", "zero.gltf"]
        meshes += [f"gltf-{n}.gltf" for n in GLTF_CASES] + ["gltf-truncated.gltf", "gltf-not-json.gltf", "gltf-array.gltf"]
        meshes += ["glb-ok.glb", "glb-bad-magic.glb", "glb-version-1.glb", "glb-length-past-file.glb", "glb-truncated.glb", "glb-json-not-json.glb",
                   "glb-no-bin-chunk.glb", "glb-empty.glb", "glb-header-only.glb", "glb-chunk-length-huge.glb", "glb-is-gltf-text.glb"]
        names = [f"scene-mesh-{m}.json" for m in meshes]
    for n in names:
        m = n[len("scene-mesh-"):-len(".json")]
        exp = "ok" if m in ok else ("either" if m in either else "error")
        out.append(C("mesh", "mesh-" + sid(m), ["render", os.path.join(fx, n), "-o", "out.png"] + SIZE, exp, names=[m],
                     outputs=["out.png"] if exp == "ok" else []))
    for t in ["ok.png", "notpng.png", "trunc.png", "huge-header.png", "wide.png", "fifo.png", "dir.png", "zero.png", "nope.png"]:
        exp = "ok" if t == "ok.png" else "error"
        out.append(C("texture", "texture-" + sid(t), ["render", os.path.join(fx, f"scene-tex-{t}.json"), "-o", "out.png"] + SIZE, exp,
                     names=[t, "materials.m.baseColorTexture"], outputs=["out.png"] if exp == "ok" else []))
    out.append(C("texture", "texture-projector-huge", ["render", os.path.join(ctx["scenes"], "slide-projector.json"), "-o", "out.png"] + SIZE +
                 ["--set", "lights[0].projector=" + os.path.join(fx, "huge-header.png")], names=["--set lights[0].projector=", "huge-header.png"]))
    return out


def output_cases(ctx):
    fx = ctx["fix"]
    r = ["render", os.path.join(fx, "base.json")] + SIZE
    out = []
    for name, args, names, setup in [
        ("no-parent", ["-o", "no/such/dir/a.png"], ["-o no/such/dir/a.png"], None),
        ("is-directory", ["-o", "d.png"], ["-o d.png"], writer({"d.png": None})),
        ("dot", ["-o", "."], ["-o ."], None),
        ("jpg", ["-o", "a.jpg"], ["-o a.jpg"], None),
        ("no-extension", ["-o", "a"], ["-o a"], None),
        ("empty", ["-o", ""], ["-o"], None),
        ("proc-unwritable", ["-o", "/proc/hostile.png"], ["/proc/hostile.png"], None),
        ("sys-unwritable", ["-o", "/sys/hostile.png"], ["/sys/hostile.png"], None),
        ("parent-is-file", ["-o", "f/a.png"], ["-o f/a.png"], writer({"f": "x"})),
        ("name-too-long", ["-o", "a" * 300 + ".png"], ["-o aaaa"], None),
        ("path-too-long", ["-o", "/".join(["d" * 200] * 30) + ".png"], ["-o ddd"], None),
        ("field-999", ["-o", "f%999d.png", "--frames", "2"], ["-o f%999d.png"], None),
        ("field-minus-999", ["-o", "f%-999d.png", "--frames", "2"], ["-o f%-999d.png"], None),
        ("field-two", ["-o", "f%d%d.png", "--frames", "2"], ["-o f%d%d.png"], None),
        ("field-s", ["-o", "f%s.png", "--frames", "2"], ["-o f%s.png"], None),
        ("field-n", ["-o", "f%n.png", "--frames", "2"], ["-o f%n.png"], None),
        ("field-lld", ["-o", "f%lld.png", "--frames", "2"], ["-o f%lld.png"], None),
        ("field-star", ["-o", "f%*d.png", "--frames", "2"], ["-o f%*d.png"], None),
        ("field-trailing-percent", ["-o", "f%.png"], ["-o f%.png"], None),
        ("frames-no-field", ["-o", "a.png", "--frames", "3"], ["-o a.png", "--frames 3"], None),
        ("frames-one-is-dir", ["-o", "f%d.png", "--frames", "3"], ["f2.png"], writer({"f2.png": None})),
        ("frames-field-makes-dir-path", ["-o", "x%d/a.png", "--frames", "2"], ["x"], None),
        ("debug-images-empty", ["-o", "a.png", "--debug-images", ""], ["--debug-images"], None),
        ("debug-images-is-file", ["-o", "a.png", "--debug-images", "f"], ["--debug-images f"], writer({"f": "x"})),
        ("debug-images-under-file", ["-o", "a.png", "--debug-images", "f/g"], ["--debug-images f/g"], writer({"f": "x"})),
        ("debug-images-unwritable", ["-o", "a.png", "--debug-images", "/proc/dbg"], ["--debug-images /proc/dbg"], None),
        ("debug-bogus", ["-o", "a.png", "--debug", "bogus"], ["--debug"], None),
        ("debug-empty", ["-o", "a.png", "--debug", ""], ["--debug"], None),
        ("debug-output-collides-dir", ["-o", "a.png", "--debug", "shadow-maps"], ["a-"], writer({"a-light0-map.png": None, "a-sun-map.png": None,
                                                                                                "a-light-0-map.png": None, "a-map-0.png": None})),
        ("fsize-limit", ["-o", "a.png", "--width", "512", "--height", "512"], ["a.png"], None),
    ]:
        env = {}
        c = C("output", "out-" + name, r + args, names=names, setup=setup, env=env)
        if name == "fsize-limit":
            c["fsize"] = 4096
            c["argv"] = ["render", os.path.join(fx, "base.json")] + args
        out.append(c)
    # render to an existing file replaces it: fine
    out.append(C("output", "out-ok-replace-existing", r + ["-o", "a.png"], "ok", outputs=["a.png"], setup=writer({"a.png": "old"})))
    out.append(C("output", "out-ok-frames", r + ["-o", "f_%03d.png", "--frames", "3"], "ok", outputs=["f_000.png", "f_002.png"]))
    out.append(C("output", "out-ok-percent-escape", r + ["-o", "p%%.png"], "ok", outputs=["p%.png"]))
    out.append(C("output", "out-ok-debug-images", r + ["-o", "a.png", "--debug-images", "dbg/x"], "ok", outputs=["a.png", "dbg/x"]))
    out.append(C("output", "out-ok-upper-PNG", r + ["-o", "a.PNG"], "ok", outputs=["a.PNG"]))
    out.append(C("output", "out-ok-newline-in-name", r + ["-o", "a\nb.png"], "ok", outputs=["a\nb.png"]))
    # compare
    cmp_ = ["compare", os.path.join(fx, "base.json"), "--width", "32", "--height", "24"]
    for name, args, names, setup in [
        ("is-file", ["-o", "f"], ["-o f"], writer({"f": "x"})),
        ("no-parent", ["-o", "no/such/c"], ["-o no/such/c"], None),
        ("empty", ["-o", ""], ["-o"], None),
        ("unwritable", ["-o", "/proc/cmp"], ["/proc/cmp"], None),
        ("output-is-dir", ["-o", "c"], ["c/"], writer({"c/error-0.png": None})),
        ("output-is-dir-metrics", ["-o", "c"], ["c/metrics.json"], writer({"c/metrics.json": None})),
    ]:
        out.append(C("output", "cmp-out-" + name, cmp_ + args, names=names, setup=setup,
                     allow_new=["c"] if name.startswith("output-is-dir") else []))
    out.append(C("output", "cmp-out-ok-existing-dir", cmp_ + ["-o", "c"], "ok", outputs=["c/metrics.json"], setup=writer({"c/keep.txt": "keep"})))
    out[-1]["preserve"] = ["c/keep.txt"]
    out.append(C("output", "cmp-out-fails-in-existing-dir", cmp_ + ["-o", "c", "--set", "lights[0].shadow.map.size=16384", "--set", "lights[0].shadow.map.format=rgba8"],
                 names=["--set lights[0].shadow.map"], setup=writer({"c/keep.txt": "keep", "c/metrics.json": "old"})))
    out[-1]["preserve"] = ["c/keep.txt", "c/metrics.json"]
    out.append(C("output", "out-debug-images-collides-dir", r + ["-o", "a.png", "--debug-images", "dbg"], names=["light0-map.png"],
                 setup=writer({"dbg/light0-map.png": None, "dbg/keep.txt": "keep"}), allow_new=[]))
    out[-1]["preserve"] = ["dbg/keep.txt"]
    out.append(C("output", "out-replace-keeps-old-on-failure", r + ["-o", "a.png", "--debug", "shadow-maps"], names=["a-light0-map.png"],
                 setup=writer({"a.png": "old", "a-light0-map.png": None})))
    out[-1]["preserve"] = ["a.png"]
    # bench
    bn = ["bench", os.path.join(fx, "base.json"), "--frames", "1", "--warmup", "0", "--width", "32", "--height", "24"]
    for name, args, names, setup in [
        ("is-file", ["-o", "f"], ["-o f"], writer({"f": "x"})),
        ("no-parent", ["-o", "no/such/b"], ["-o no/such/b"], None),
        ("empty", ["-o", ""], ["-o"], None),
        ("unwritable", ["-o", "/proc/bench"], ["/proc/bench"], None),
        ("devnull", ["-o", "/dev/null"], ["-o /dev/null"], None),
    ]:
        out.append(C("output", "bench-out-" + name, bn + args, names=names, setup=setup, progress=True))
    out.append(C("output", "bench-out-ok-existing-dir-kept", bn + ["-o", "b"], "ok", outputs=["b/results.json"], progress=True,
                 setup=writer({"b/keep.txt": "keep", "b/results.json": "old"})))
    out[-1]["preserve"] = ["b/keep.txt"]
    out.append(C("output", "bench-out-stale-partial-removed", bn + ["-o", "b"], "ok", outputs=["b/results.json"], progress=True,
                 setup=writer({"b.partial-999999/results.json": "stale"})))
    return out


def flag_cases(ctx):
    fx = ctx["fix"]
    base = os.path.join(fx, "base.json")
    r = ["render", base, "-o", "a.png"]
    cmp_ = ["compare", base, "-o", "c"]
    bn = ["bench", base, "-o", "b", "--frames", "1", "--warmup", "0"]
    out = []
    for cmd, pre in [("render", r), ("compare", cmp_), ("bench", bn)]:
        for name, args, names in [
            ("width-100000", ["--width", "100000", "--height", "10"], ["--width 100000"]),
            ("width-16385", ["--width", "16385", "--height", "16"], ["--width 16385"]),
            ("size-16384-sq", ["--width", "16384", "--height", "16384"], ["--width 16384 --height 16384"]),
            ("width-0", ["--width", "0"], ["--width"]),
            ("width-neg", ["--width", "-1"], ["--width"]),
            ("width-frac", ["--width", "1.5"], ["--width"]),
            ("width-abc", ["--width", "abc"], ["--width"]),
            ("width-empty", ["--width", ""], ["--width"]),
            ("width-2-31", ["--width", "2147483648"], ["--width"]),
            ("width-2-64", ["--width", "18446744073709551616"], ["--width"]),
            ("width-hex", ["--width", "0x40"], ["--width"]),
            ("time-nan", ["--time", "nan"], ["--time"]),
            ("time-inf", ["--time", "inf"], ["--time"]),
            ("time-empty", ["--time", ""], ["--time"]),
            ("time-abc", ["--time", "abc"], ["--time"]),
            ("time-1e400", ["--time", "1e400"], ["--time"]),
            ("set-empty", ["--set", ""], ["--set"]),
            ("unknown-flag", ["--bogus"], ["--bogus"]),
            ("extra-positional", ["extra.json"] if cmd != "bench" else ["--frames"], ["extra.json"] if cmd != "bench" else ["--frames"]),
        ]:
            if cmd != "render" and name not in ("width-100000", "size-16384-sq", "width-abc", "time-nan", "time-empty", "unknown-flag", "width-empty"):
                continue
            out.append(C("flags", f"flag-{cmd}-{name}", pre + args, "either" if name == "width-hex" else "error", names=names, progress=cmd == "bench",
                         allow_new=[]))
    more = [
        ("render-frames-0", r + ["--frames", "0"], ["--frames"]),
        ("render-frames-100001", r + ["--frames", "100001"], ["--frames"]),
        ("render-fps-0", ["render", base, "-o", "f%d.png", "--frames", "2", "--fps", "0"], ["--fps"]),
        ("render-fps-neg", ["render", base, "-o", "f%d.png", "--frames", "2", "--fps", "-30"], ["--fps"]),
        ("render-fps-nan", ["render", base, "-o", "f%d.png", "--frames", "2", "--fps", "nan"], ["--fps"]),
        ("render-fps-empty", r + ["--fps", ""], ["--fps"]),
        ("render-fps-tiny-time-overflow", ["render", base, "-o", "f%d.png", "--frames", "2", "--fps", "1e-310", "--width", "16", "--height", "16"], ["--fps"]),
        ("render-time-huge-frames", ["render", base, "-o", "f%d.png", "--frames", "2", "--time", "1.7e308", "--fps", "1e-308"], ["--time"]),
        ("render-view-from-light-neg", r + ["--view-from-light", "-1"], ["--view-from-light"]),
        ("render-view-from-light-256", r + ["--view-from-light", "256"], ["--view-from-light"]),
        ("render-view-from-light-1", r + ["--view-from-light", "1"], ["--view-from-light 1"]),
        ("compare-samples-0", cmp_ + ["--samples", "0"], ["--samples"]),
        ("compare-samples-65537", cmp_ + ["--samples", "65537"], ["--samples"]),
        ("compare-rays-past-limit", ["compare", base, "-o", "c", "--set", "lights[0].size=2", "--samples", "65536", "--width", "320", "--height", "180"],
         ["--samples 65536"]),
        ("bench-frames-0", bn[:4] + ["--frames", "0"], ["--frames"]),
        ("bench-warmup-neg", bn + ["--warmup", "-1"], ["--warmup"]),
        ("bench-warmup-1001", bn + ["--warmup", "1001"], ["--warmup"]),
        ("bench-rounds-0", bn + ["--rounds", "0"], ["--rounds"]),
        ("bench-rounds-101", bn + ["--rounds", "101"], ["--rounds"]),
        ("bench-rounds-text", bn + ["--rounds", "two"], ["--rounds"]),
        ("bench-fps-0", bn + ["--fps", "0"], ["--fps"]),
        ("bench-fps-inf", bn + ["--fps", "inf"], ["--fps"]),
        ("bench-clock-bogus", bn + ["--clock", "bogus"], ["--clock"]),
        ("bench-clock-empty", bn + ["--clock", ""], ["--clock"]),
        ("bench-clock-gpu-on-llvmpipe", bn + ["--clock", "gpu-timestamp", "--width", "32", "--height", "24"], ["--clock"]),
        ("bench-vary-empty", bn + ["--vary"], ["--vary"]),
        ("no-command", [], ["command"]),
        ("unknown-command", ["paint"], ["paint"]),
        ("unknown-command-control", ["pa\x1bint"], ["pa"]),
        ("techniques-extra", ["techniques", "extra"], ["extra"]),
        ("info-flag", ["info", "--bogus"], ["--bogus"]),
        ("env-memory-limit-abc", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_MEMORY_LIMIT_BYTES"]),
        ("env-memory-limit-empty", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_MEMORY_LIMIT_BYTES"]),
        ("env-memory-limit-100", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_MEMORY_LIMIT_BYTES"]),
        ("env-memory-limit-neg", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_MEMORY_LIMIT_BYTES"]),
        ("env-memory-limit-huge", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_MEMORY_LIMIT_BYTES"]),
        ("env-memory-limit-small", r + ["--width", "320", "--height", "240"], ["--width 320 --height 240"]),
        ("env-device-kib-abc", r + ["--width", "32", "--height", "24"], ["SHADOWLAB_DEVICE_MEMORY_KIB"]),
        ("env-device-kib-tiny", r + ["--width", "320", "--height", "240"], ["--width 320"]),
        ("env-device-kib-tiny-map", r + ["--width", "32", "--height", "24", "--set", "lights[0].shadow.map.size=8192"], ["--set lights[0].shadow.map.size=8192"]),
    ]
    envs = {"env-memory-limit-abc": {"SHADOWLAB_MEMORY_LIMIT_BYTES": "abc"}, "env-memory-limit-empty": {"SHADOWLAB_MEMORY_LIMIT_BYTES": ""},
            "env-memory-limit-100": {"SHADOWLAB_MEMORY_LIMIT_BYTES": "100"}, "env-memory-limit-neg": {"SHADOWLAB_MEMORY_LIMIT_BYTES": "-5"},
            "env-memory-limit-huge": {"SHADOWLAB_MEMORY_LIMIT_BYTES": "99999999999999999999999999"},
            "env-memory-limit-small": {"SHADOWLAB_MEMORY_LIMIT_BYTES": "100000"},
            "env-device-kib-abc": {"SHADOWLAB_DEVICE_MEMORY_KIB": "abc"}, "env-device-kib-tiny": {"SHADOWLAB_DEVICE_MEMORY_KIB": "1"},
            "env-device-kib-tiny-map": {"SHADOWLAB_DEVICE_MEMORY_KIB": "20000"}}
    # accepted by design: CLI11 reads 0x40 as 64; llvmpipe has timer queries; an empty variable is unset; a huge
    # budget is a finite decimal; the device memory stands in for frames, not for maps (the maps' budget is 1 GiB)
    either = {"render-width-hex", "bench-clock-gpu-on-llvmpipe", "env-memory-limit-empty", "env-memory-limit-huge", "env-device-kib-tiny-map"}
    for name, argv, names in more:
        out.append(C("flags", "flag-" + name, argv, "either" if name in either else "error", names=names, progress=name.startswith("bench"), env=envs.get(name)))
    # valid flag edges
    for name, argv, outs in [("render-1x1", r + ["--width", "1", "--height", "1"], ["a.png"]),
                             ("render-time-neg", r + ["--width", "32", "--height", "24", "--time", "-5"], ["a.png"]),
                             ("render-view-from-light-0", r + ["--width", "32", "--height", "24", "--view-from-light", "0"], ["a.png"]),
                             ("compare-samples-1-soft", cmp_ + ["--width", "32", "--height", "24", "--samples", "1", "--set", "lights[0].size=2"], ["c/metrics.json"]),
                             ("bench-flips", bn[:4] + ["--warmup", "0", "--width", "32", "--height", "24", "--frames", "2", "--flips"], ["b/results.json"]),
                             ("info", ["info"], []), ("techniques", ["techniques"], []), ("techniques-markdown", ["techniques", "--markdown"], [])]:
        out.append(C("flags", "flag-ok-" + name, argv, "ok", outputs=outs, progress=name.startswith("bench")))
    return out


def view_cases(ctx):
    fx = ctx["fix"]
    base = os.path.join(fx, "base.json")
    v = ["view", base, "--width", "320", "--height", "240"]
    out = []
    scripts = [
        ("unknown-action", "frobnicate\nquit\n", ["s.txt:1"]),
        ("set-no-equals", "set lights\nquit\n", ["s.txt:1"]),
        ("set-bad-value", "set lights[0].intensity=-1\nquit\n", ["s.txt:1", "lights[0].intensity"]),
        ("set-unknown-key", "set camera.fov=30\nquit\n", ["s.txt:1", "camera.fov"]),
        ("set-bad-technique", "set lights[0].shadow.technique=bogus\nquit\n", ["s.txt:1", "lights[0].shadow.technique"]),
        ("set-index-out", "set lights[7].intensity=1\nquit\n", ["s.txt:1", "lights[7]"]),
        ("set-budget", "set lights[0].shadow.map.size=16384\nset lights[0].shadow.map.format=rgba8\nwait 2\nquit\n", ["s.txt:"]),
        ("set-mesh-devzero", 'set nodes[1]={"mesh":"/dev/zero"}\nquit\n', ["s.txt:1", "/dev/zero"]),
        ("wait-neg", "wait -1\nquit\n", ["s.txt:1"]),
        ("wait-abc", "wait abc\nquit\n", ["s.txt:1"]),
        ("wait-huge", "wait 99999999999999999999\nquit\n", ["s.txt:1"]),
        ("wait-100001", "wait 100001\nquit\n", ["s.txt:1"]),
        ("wait-empty", "wait\nquit\n", ["s.txt:1"]),
        ("screenshot-empty", "screenshot\nquit\n", ["s.txt:1"]),
        ("screenshot-jpg", "screenshot a.jpg\nquit\n", ["s.txt:1", "a.jpg"]),
        ("screenshot-dir", "screenshot d.png\nquit\n", ["s.txt:1", "d.png"]),
        ("screenshot-no-parent", "screenshot no/such/a.png\nquit\n", ["s.txt:1", "no/such"]),
        ("screenshot-unwritable", "screenshot /proc/v.png\nquit\n", ["s.txt:1", "/proc/v.png"]),
        ("save-empty", "save\nquit\n", ["s.txt:1"]),
        ("save-dot", "save .\nquit\n", ["s.txt:1"]),
        ("save-dir", "save d.png\nquit\n", ["s.txt:1"]),
        ("save-no-parent", "save no/such/s.json\nquit\n", ["s.txt:1"]),
        ("save-unwritable", "save /proc/s.json\nquit\n", ["s.txt:1", "/proc/s.json"]),
        ("resize-small", "resize 10 10\nquit\n", ["s.txt:1"]),
        ("resize-huge", "resize 100000 100000\nquit\n", ["s.txt:1"]),
        ("resize-16384", "resize 16384 16384\nquit\n", ["s.txt:1"]),
        ("resize-words", "resize a b\nquit\n", ["s.txt:1"]),
        ("resize-three", "resize 100 100 100\nquit\n", ["s.txt:1"]),
        ("compare-missing-dir", "compare nope\nquit\n", ["s.txt:1", "nope"]),
        ("compare-file", "compare f\nquit\n", ["s.txt:1", "f"]),
        ("compare-fifo", "compare " + os.path.join(fx, "fifo.txt") + "\nquit\n", ["s.txt:1", "fifo.txt"]),
        ("compare-unwritable", "compare /proc/self\nquit\n", ["s.txt:1", "/proc/self"]),
        ("quit-arg", "quit now\n", ["s.txt:1"]),
        ("minimize-arg", "minimize 3\nquit\n", ["s.txt:1"]),
        ("nul-line", b"wait 1\nset lights[0].intensity=2\x00junk\nquit\n", ["s.txt:2"]),
        ("invalid-utf8", b"set name=\xff\xfe\nquit\n", ["s.txt:1"]),
        ("long-unknown", LONG + "\nquit\n", ["s.txt:1"]),
        ("binary", bytes(range(1, 256)) * 4, ["s.txt:"]),
        ("escape-in-action", "\x1b[2Jscreenshot a.png\nquit\n", ["s.txt:1"]),
        ("screenshot-then-bad-set", "screenshot a.png\nwait 1\nset lights[0].intensity=-1\nquit\n", ["s.txt:3"]),
    ]
    for name, text, names in scripts:
        files = {"s.txt": text, "d.png": None, "f": "x"}
        out.append(C("view-script", "view-script-" + name, v + ["--script", "s.txt", "--frames", "200"], names=names, tool="view",
                     setup=writer(files), timeout=60))
    for name, path, names, setup in [("missing", "nope.txt", ["nope.txt"], None), ("dir", os.path.join(fx, "dir.txt"), ["dir.txt"], None),
                                     ("fifo", os.path.join(fx, "fifo.txt"), ["fifo.txt"], None), ("devzero", "/dev/zero", ["/dev/zero"], None),
                                     ("huge", "big.txt", ["big.txt"], writer({"big.txt": "wait 0\n" * 200000})),
                                     ("empty-arg", "", ["--script"], None)]:
        out.append(C("view-script", "view-scriptfile-" + name, v + ["--script", path], names=names, tool="view", setup=setup))
    ok_scripts = [
        ("long-name", "set name=" + LONG + "\nquit\n", []),
        ("crlf", "set lights[0].intensity=2\r\nwait 1\r\nscreenshot a.png\r\nquit\r\n", ["a.png"]),
        ("comments", "# hi\n\n   \nset lights[0].intensity=2 # two\nquit\n", []),
        ("empty-with-frames", "", []),
        ("compare-dir", "compare cmp\nquit\n", ["cmp/error-0.png"]),
        ("save", "set lights[0].intensity=2\nsave saved.json\nquit\n", ["saved.json"]),
        ("resize", "resize 200 150\nscreenshot a.png\nquit\n", ["a.png"]),
    ]
    for name, text, outs in ok_scripts:
        files = {"s.txt": text, "cmp": None}
        out.append(C("view-script", "view-ok-" + name, v + ["--script", "s.txt", "--frames", "300"], "ok", tool="view", setup=writer(files),
                     outputs=outs, timeout=120))
    # the script's compare must finish before quit
    out.append(C("view-script", "view-ok-compare-last-line", v + ["--script", "s.txt"], "ok", tool="view",
                 setup=writer({"s.txt": "compare cmp\n", "cmp": None}), names=["compare"], outputs=["cmp/error-0.png"], timeout=60))
    for name, args, names, setup in [
        ("width-63", ["--width", "63"], ["--width"], None), ("width-16385", ["--width", "16385"], ["--width"], None),
        ("size-16384", ["--width", "16384", "--height", "16384"], ["--width 16384"], None),
        ("frames-neg", ["--frames", "-1"], ["--frames"], None),
        ("screenshot-no-frames", ["--screenshot", "a.png"], ["--screenshot"], None),
        ("screenshot-jpg", ["--frames", "2", "--screenshot", "a.jpg"], ["--screenshot a.jpg"], None),
        ("screenshot-dir", ["--frames", "2", "--screenshot", "d.png"], ["--screenshot d.png"], writer({"d.png": None})),
        ("screenshot-empty", ["--frames", "2", "--screenshot", ""], ["--screenshot"], None),
        ("screenshot-unwritable", ["--frames", "2", "--screenshot", "/proc/v.png"], ["/proc/v.png"], None),
        ("set-bad", ["--frames", "2", "--set", "lights[0].intensity=-1"], ["--set lights[0].intensity=-1"], None),
        ("set-twice", ["--frames", "2", "--set", "lights[0].intensity=1", "--set", "lights[0].intensity=2"], ["--set lights[0].intensity=2"], None),
        ("memory-limit-env", ["--frames", "2"], ["--width 320"], None),
    ]:
        c = C("view-flags", "view-flag-" + name, (v[:2] if "--width" in args else v) + args, names=names, tool="view", setup=setup)
        if name == "memory-limit-env":
            c["env"] = {"SHADOWLAB_MEMORY_LIMIT_BYTES": "100000"}
        out.append(c)
    for name, scene, names in [("scene-missing", "nope.json", ["nope.json"]), ("scene-fifo", os.path.join(fx, "fifo.json"), ["fifo.json"]),
                               ("scene-bad-json", os.path.join(fx, "empty.json"), ["empty.json"]),
                               ("scene-bad-mesh", os.path.join(fx, "scene-mesh-index-past.obj.json"), ["index-past.obj"])]:
        out.append(C("view-flags", "view-" + name, ["view", scene, "--frames", "2", "--width", "320", "--height", "240"], names=names, tool="view"))
    out.append(C("view-flags", "view-ok-screenshot", v + ["--frames", "3", "--screenshot", "a.png"], "ok", tool="view", outputs=["a.png"]))
    return out


def python_cases(ctx):
    fx = ctx["fix"]
    P = []
    def py(name, code, names, expect="error"):
        P.append(C("python", "py-" + name, tool="py", code=code, names=names, expect=expect))
    py("render-width-str", 'sl.render(D(), "a", 10)', ["width"])
    py("render-width-float", "sl.render(D(), 10.5, 10)", ["width"])
    py("render-width-huge-int", "sl.render(D(), 2**70, 10)", ["width"])
    py("render-width-neg", "sl.render(D(), -5, 10)", ["width"])
    py("render-width-bool", "sl.render(D(), True, 10)", ["width"], "either")
    py("render-width-numpy", "import numpy; sl.render(D(), numpy.int64(16), 16)", [], "ok")
    py("render-size-past-memory", "sl.render(D(), 1000000, 1000000)", ["width"])
    py("render-height-100000", "sl.render(D(), 10, 100000)", ["height 100000"])
    py("render-time-str", 'sl.render(D(), 10, 10, time="x")', ["time"])
    py("render-time-nan", "sl.render(D(), 10, 10, time=float('nan'))", ["time"])
    py("render-time-1e308", "sl.render(D(), 10, 10, time=1e308)", ["time"], "either")
    py("render-scene-none", "sl.render(None, 10, 10)", ["scene"])
    py("render-scene-str", "sl.render(SCENE, 10, 10)", ["scene"])
    py("render-unknown-kwarg", "sl.render(D(), 10, 10, frames=2)", ["frames"])
    py("visibility-light-neg", "sl.visibility(D(), -1, 10, 10)", ["light"])
    py("visibility-light-huge", "sl.visibility(D(), 2**40, 10, 10)", ["light"])
    py("visibility-light-str", 'sl.visibility(D(), "0", 10, 10)', ["light"])
    py("visibility-coloured-str", 'sl.visibility(D(), 0, 10, 10, coloured="yes")', ["coloured"])
    py("reference-samples-0", "sl.reference(D(), 0, 10, 10, soft_samples=0)", ["soft_samples"])
    py("reference-samples-neg", "sl.reference(D(), 0, 10, 10, soft_samples=-1)", ["soft_samples"])
    py("compare-samples-2-31", "sl.compare(D(), 10, 10, soft_samples=2**31)", ["soft_samples"])
    py("compare-width-0", "sl.compare(D(), 0, 10)", ["width"])
    py("debug-images-height-0", "sl.debug_images(D(), 10, 0)", ["height"])
    py("bench-frames-0", "sl.bench(None, 16, 16, frames=0)", ["frames"])
    py("bench-warmup-neg", "sl.bench(None, 16, 16, warmup=-1)", ["warmup"])
    py("bench-fps-0", "sl.bench(None, 16, 16, fps=0)", ["fps"])
    py("bench-fps-nan", "sl.bench(None, 16, 16, fps=float('nan'))", ["fps"])
    py("bench-flips-one-frame", "sl.bench(None, 16, 16, frames=1, flips=True)", ["flips"])
    py("bench-vary-empty-key", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary={"": [1]})', ["vary"])
    py("bench-vary-empty-list", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary={"lights[0].intensity": []})', ["vary[lights[0].intensity]"])
    py("bench-vary-unknown-key", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary={"camera.fov": [30, 40]})', ["vary[camera.fov]"])
    py("bench-vary-bad-value", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary={"lights[0].intensity": [1, -1]})', ["vary[lights[0].intensity]"])
    py("bench-vary-tuple-bad", "sl.bench(None, 16, 16, frames=1, warmup=0, vary=[(1, 2)])", ["vary"])
    py("bench-vary-dup-key", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary=[("lights[0].intensity", [1]), ("lights[0].intensity", [2])])', ["vary"])
    py("bench-vary-too-many", 'sl.bench(None, 16, 16, frames=1, warmup=0, vary={"lights[0].intensity": list(range(101)), "lights[0].shadow.map.size": list(range(16, 117))})', ["vary"])
    py("bench-scene-default-object", "sl.bench([D()], 16, 16, frames=1, warmup=0)", ["scenes"])
    py("bench-scene-json-object", 'sl.bench([sl.load_scene_json("{}")], 16, 16, frames=1, warmup=0)', ["scenes"])
    py("bench-scene-fifo", f'sl.bench("{fx}/fifo.json", 16, 16, frames=1, warmup=0)', ["fifo.json"])
    py("bench-scene-devzero", 'sl.bench("/dev/zero", 16, 16, frames=1, warmup=0)', ["/dev/zero"])
    py("bench-out-devnull", 'sl.bench(None, 16, 16, frames=1, warmup=0, out="/dev/null")', ["out /dev/null"])
    py("bench-out-unwritable", 'sl.bench(None, 16, 16, frames=1, warmup=0, out="/proc/pyb")', ["out /proc/pyb"])
    py("bench-out-nul", 'sl.bench(None, 16, 16, frames=1, warmup=0, out="a\\x00b")', ["out"])
    py("bench-overrides-bad", 'sl.bench(None, 16, 16, frames=1, warmup=0, overrides={"lights[0].intensity": -1})', ["overrides[lights[0].intensity]"])
    py("bench-ok-out", 'sl.bench(None, 16, 16, frames=1, warmup=0, out="bo")', [], "ok")
    py("load-devzero", 'sl.load_scene("/dev/zero")', ["/dev/zero"])
    py("load-fifo", f'sl.load_scene("{fx}/fifo.json")', ["fifo.json"])
    py("load-dir", f'sl.load_scene("{fx}/dir.json")', ["dir.json"])
    py("load-empty-file", f'sl.load_scene("{fx}/empty.json")', ["empty.json"])
    py("load-bytes-path", f'sl.load_scene(b"{fx}/base.json")', ["path"], "either")
    py("load-overrides-str", 'sl.load_scene(SCENE, "x")', ["overrides"])
    py("load-overrides-list", 'sl.load_scene(SCENE, [("lights[0].intensity", 1)])', ["overrides"])
    py("overrides-size-huge", 'D({"lights[0].shadow.map.size": 10**30})', ["overrides[lights[0].shadow.map.size]"])
    py("overrides-size-inf", 'D({"lights[0].shadow.map.size": float("inf")})', ["overrides[lights[0].shadow.map.size]"])
    py("overrides-filter-bogus", 'D({"lights[0].shadow.map.filter": "bogus"})', ["overrides[lights[0].shadow.map.filter]"])
    py("overrides-empty-key", 'D({"": 1})', ["overrides"])
    py("overrides-object-value", 'D({"lights[0].intensity": object()})', ["overrides[lights[0].intensity]"])
    py("overrides-long-key", 'D({"a" * 100000: 1})', ["overrides["])
    py("overrides-control-key", 'D({"cam\\nera.fovY": 1})', ["overrides["])
    py("overrides-unknown-key", 'D({"camera.fov": 1})', ["overrides[camera.fov]"])
    py("overrides-outer-after-inner-equivalent", 'D({"lights[0].shadow.map.size": 7, "lights[0].shadow.map": {"filter": "none"}})', ["overrides[lights[0].shadow.map"])
    py("overrides-dup-written-apart", 'D({"lights[0].intensity": -1, "lights[00].intensity": 2})', ["overrides[lights[0"])
    py("with-overrides-bad", 'D().with_overrides({"camera.fovY": 0})', ["overrides[camera.fovY]"])
    py("with-overrides-not-dict", "D().with_overrides(5)", ["overrides"])
    py("json-invalid", 'sl.load_scene_json("{")', ["<json>"])
    py("json-deep", 'sl.load_scene_json("[" * 100000 + "]" * 100000)', ["<json>"])
    py("json-mesh-missing", 'sl.load_scene_json(\'{"nodes":[{"mesh":"nope.obj"}]}\', base_dir="/nonexistent")', ["nope.obj"])
    py("json-base-dir-int", 'sl.load_scene_json("{}", base_dir=5)', ["base_dir"])
    py("json-mesh-devzero", 'sl.load_scene_json(\'{"nodes":[{"mesh":"/dev/zero"}]}\')', ["/dev/zero"])
    py("json-gltf-bad", f'sl.load_scene_json(\'{{"nodes":[{{"mesh":"gltf-accessor-count-huge.gltf"}}]}}\', base_dir="{fx}")', ["gltf-accessor-count-huge.gltf"])
    py("scene-attr-set", "s = D(); s.name = 'x'", [], "error")
    P[-1]["exc_ok"] = ["AttributeError"]  # a read-only property: Python's own exception
    py("techniques-arg", "sl.techniques(5)", ["techniques"], "either")
    py("context-ok", "c = sl.Context(); assert c.max_texture_size > 0", [], "ok")
    py("render-after-errors-ok", "\ntry:\n    sl.render(D(), 0, 0)\nexcept ValueError: pass\nassert sl.render(D(), 16, 16).shape == (16, 16, 4)", [], "ok")
    return P


def build_cases(ctx):
    cases = []
    for f in (option_cases, combo_cases, set_syntax_cases, vary_cases, scene_json_cases, mesh_cases, output_cases, flag_cases, view_cases, python_cases):
        cases += f(ctx)
    for c in cases:
        c.setdefault("fsize", None)
    return cases
