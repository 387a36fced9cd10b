"""Input files for the battery, made fresh in FIX by make_fixtures (stdlib only)."""
import base64
import json
import os
import shutil
import struct
import zlib

LIGHT = {"type": "directional", "direction": [-0.4, -1.0, -0.3]}
GROUND = {"name": "ground", "shape": {"type": "plane", "size": [6, 6]}}
BOX = {"name": "box", "shape": {"type": "box"}, "translation": [0, 0.8, 0]}
BASE = {"camera": {"position": [3, 3, 5], "target": [0, 0.5, 0]}, "lights": [LIGHT], "nodes": [GROUND, BOX]}


def png_bytes(w, h, rgba=None):
    raw = b"".join(b"\x00" + (rgba or b"\x80\x40\x20\xff") * w for _ in range(h))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def png_header_only(w, h):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(b"\x00" * 64)) + chunk(b"IEND", b"")


# A triangle: 3 float VEC3 positions (36 bytes) then 3 uint16 indices (6 bytes, padded to 8).
POS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
IDX = struct.pack("<3H", 0, 1, 2) + b"\x00\x00"
BIN = POS + IDX


def gltf_doc(bin_uri="tri.bin", **patch):
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}],
        "buffers": [{"uri": bin_uri, "byteLength": len(BIN)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }
    return doc


def glb(doc, binchunk=BIN, magic=b"glTF", version=2, length_delta=0, json_bytes=None):
    j = json_bytes if json_bytes is not None else json.dumps(doc).encode()
    j += b" " * (-len(j) % 4)
    body = struct.pack("<I4s", len(j), b"JSON") + j
    if binchunk is not None:
        b = binchunk + b"\x00" * (-len(binchunk) % 4)
        body += struct.pack("<I4s", len(b), b"BIN\x00") + b
    return magic + struct.pack("<II", version, 12 + len(body) + length_delta) + body


def setpath(doc, path, value):
    """path like 'accessors.0.count'; value None deletes."""
    keys = path.split(".")
    cur = doc
    for k in keys[:-1]:
        cur = cur[int(k)] if isinstance(cur, list) else cur[k]
    k = keys[-1]
    if isinstance(cur, list):
        k = int(k)
    if value is None:
        del cur[k]
    else:
        cur[k] = value


# name -> (patches, description). Each makes FIX/gltf-NAME.gltf and a scene FIX/scene-gltf-NAME.json
GLTF_CASES = {
    "ok": [],
    "no-asset": [("asset", None)],
    "version-1": [("asset", {"version": "1.0"})],
    "buffer-missing-file": [("buffers.0.uri", "nope.bin")],
    "buffer-length-past-file": [("buffers.0.byteLength", 4096)],
    "view-past-buffer": [("bufferViews.0.byteOffset", 40)],
    "accessor-count-past-view": [("accessors.0.count", 1000)],
    "accessor-count-huge": [("accessors.0.count", 2**40)],
    "accessor-count-negative": [("accessors.0.count", -3)],
    "accessor-componenttype-bad": [("accessors.0.componentType", 5130)],
    "accessor-position-vec2": [("accessors.0.type", "VEC2")],
    "accessor-index-missing": [("meshes.0.primitives.0.indices", 7)],
    "accessor-bufferview-missing": [("accessors.0.bufferView", 9)],
    "stride-too-small": [("bufferViews.0.byteStride", 4)],
    "index-float": [("accessors.1.componentType", 5126)],
    "node-mesh-missing": [("nodes.0.mesh", 5)],
    "scene-node-missing": [("scenes.0.nodes", [3])],
    "scene-index-missing": [("scene", 4)],
    "material-missing": [("meshes.0.primitives.0.material", 9)],
    "mode-points": [("meshes.0.primitives.0.mode", 0)],
    "mode-bad": [("meshes.0.primitives.0.mode", 99)],
    "alphamode-bogus": [("materials.0.alphaMode", "BOGUS")],
    "alphacutoff-negative": [("materials.0.alphaCutoff", -1)],
    "basecolor-over-1": [("materials.0.pbrMetallicRoughness.baseColorFactor", [2, 0, 0, 1])],
    "basecolor-short": [("materials.0.pbrMetallicRoughness.baseColorFactor", [1, 0])],
    "texture-missing-image": [("materials.0.pbrMetallicRoughness.baseColorTexture", {"index": 0}), ("textures", [{"source": 3}])],
    "image-uri-missing": [("materials.0.pbrMetallicRoughness.baseColorTexture", {"index": 0}), ("textures", [{"source": 0}]), ("images", [{"uri": "nope.png"}])],
    "image-not-png": [("materials.0.pbrMetallicRoughness.baseColorTexture", {"index": 0}), ("textures", [{"source": 0}]), ("images", [{"uri": "notpng.png"}])],
    "extension-required": [("extensionsRequired", ["KHR_draco_mesh_compression"]), ("extensionsUsed", ["KHR_draco_mesh_compression"])],
    "data-uri-bad-base64": [("buffers.0.uri", "data:application/octet-stream;base64,@@@@not base64!!")],
    "translation-1e39": [("nodes.0.translation", [1e39, 0, 0])],
    "matrix-nan-like": [("nodes.0.matrix", [1e308] * 16)],
    "node-cycle": [("nodes", [{"mesh": 0, "children": [1]}, {"children": [0]}])],
    "buffer-uri-directory": [("buffers.0.uri", ".")],
    "buffer-uri-devzero": [("buffers.0.uri", "/dev/zero")],
    "sparse": [("accessors.0.sparse", {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}})],
}


def make_fixtures(fix, scenes):
    if os.path.lexists(fix):
        shutil.rmtree(fix)
    os.makedirs(fix)
    W = lambda name, data: open(os.path.join(fix, name), "wb" if isinstance(data, bytes) else "w").write(data)
    W("base.json", json.dumps(BASE, indent=1))
    W("empty.json", "")
    W("ws.json", "   \n\t\n")
    W("nul.json", b'{"name": "a\x00b"}')
    W("bom.json", b"\xef\xbb\xbf" + json.dumps(BASE).encode())
    W("latin1.json", b'{"name": "caf\xe9"}')
    W("deep.json", "[" * 100000 + "]" * 100000)
    W("deep-children.json", json.dumps({"nodes": [{"children": []}]})[:-3] + "")  # overwritten below
    # 150 levels of hierarchy = 300+ JSON levels
    node = {"shape": {"type": "box"}}
    for _ in range(150):
        node = {"children": [node]}
    W("deep-children.json", json.dumps({"lights": [LIGHT], "nodes": [node]}))
    W("many-lights.json", json.dumps({"lights": [LIGHT] * 300, "nodes": [GROUND]}))
    os.mkfifo(os.path.join(fix, "fifo.json"))
    os.mkfifo(os.path.join(fix, "fifo.obj"))
    os.mkfifo(os.path.join(fix, "fifo.png"))
    os.mkfifo(os.path.join(fix, "fifo.txt"))
    os.makedirs(os.path.join(fix, "dir.json"))
    os.makedirs(os.path.join(fix, "dir.obj"))
    os.makedirs(os.path.join(fix, "dir.png"))
    os.makedirs(os.path.join(fix, "dir.txt"))
    os.symlink("/dev/zero", os.path.join(fix, "zero.json"))
    os.symlink("/dev/zero", os.path.join(fix, "zero.obj"))
    os.symlink("/dev/zero", os.path.join(fix, "zero.png"))
    os.symlink("/dev/zero", os.path.join(fix, "zero.gltf"))
    os.symlink("loop2.json", os.path.join(fix, "loop1.json"))
    os.symlink("loop1.json", os.path.join(fix, "loop2.json"))
    # textures
    W("ok.png", png_bytes(4, 4))
    W("notpng.png", "this is not a png\n")
    W("trunc.png", png_bytes(64, 64)[:60])
    W("huge-header.png", png_header_only(100000, 100000))
    W("wide.png", png_header_only(70000, 1))
    # OBJ
    objs = {
        "ok.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "empty.obj": "",
        "comments.obj": "# nothing\n\n",
        "index-past.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
        "index-zero.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
        "index-negative-past.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -9\n",
        "index-huge.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n",
        "vt-past.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/5 2/1 3/1\n",
        "vn-past.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//4 2//1 3//1\n",
        "two-vertex-face.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
        "short-vertex.obj": "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "nan-vertex.obj": "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "inf-vertex.obj": "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "word-vertex.obj": "v a b c\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "garbage.obj": None,
        "truncated.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2",
        "face-letters.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n",
    }
    for name, text in objs.items():
        if text is None:
            W(name, bytes(range(256)) * 64)
        else:
            W(name, text)
    # glTF
    W("tri.bin", BIN)
    for name, patches in GLTF_CASES.items():
        doc = gltf_doc()
        for p, v in patches:
            if p in ("textures", "images", "extensionsRequired", "extensionsUsed") or "." not in p:
                if v is None:
                    doc.pop(p, None)
                else:
                    doc[p] = v
            else:
                setpath(doc, p, v)
        W(f"gltf-{name}.gltf", json.dumps(doc))
    W("gltf-truncated.gltf", json.dumps(gltf_doc())[:120])
    W("gltf-not-json.gltf", "glTF binary?\n")
    W("gltf-array.gltf", "[]")
    # GLB
    W("glb-ok.glb", glb(dict(gltf_doc(), buffers=[{"byteLength": len(BIN)}])))
    d = dict(gltf_doc(), buffers=[{"byteLength": len(BIN)}])
    W("glb-bad-magic.glb", glb(d, magic=b"gltf"))
    W("glb-version-1.glb", glb(d, version=1))
    W("glb-length-past-file.glb", glb(d, length_delta=1000))
    W("glb-truncated.glb", glb(d)[:50])
    W("glb-json-not-json.glb", glb(d, json_bytes=b"{not json"))
    W("glb-no-bin-chunk.glb", glb(d, binchunk=None))
    W("glb-empty.glb", b"")
    W("glb-header-only.glb", b"glTF" + struct.pack("<II", 2, 12))
    W("glb-chunk-length-huge.glb", b"glTF" + struct.pack("<II", 2, 40) + struct.pack("<I4s", 0xFFFFFFF0, b"JSON") + b"{}      " + b"\x00" * 8)
    W("glb-is-gltf-text.glb", json.dumps(gltf_doc()))
    # a scene per mesh file
    meshes = [n for n in os.listdir(fix) if n.endswith((".obj", ".gltf", ".glb"))]
    for m in meshes:
        scene = {"lights": [LIGHT], "nodes": [GROUND, {"name": "m", "mesh": m, "translation": [0, 0.5, 0]}]}
        W(f"scene-mesh-{m}.json", json.dumps(scene))
    # textures via a material
    for t in ["ok.png", "notpng.png", "trunc.png", "huge-header.png", "wide.png", "fifo.png", "dir.png", "zero.png", "nope.png"]:
        scene = dict(BASE, materials={"m": {"baseColorTexture": t}}, nodes=[dict(GROUND, material="m"), BOX])
        W(f"scene-tex-{t}.json", json.dumps(scene))
