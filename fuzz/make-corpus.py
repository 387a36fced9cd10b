#!/usr/bin/env python3
"""Writes the fuzz seed corpus: small valid inputs and the reproducers of
issue 12 (each named repro-*). Run from the repository root; the output is
committed, so this only needs re-running when a seed is added.

Layout: fuzz/corpus/<target>/ per fuzz target (scene, obj, gltf, glb), and
fuzz/corpus/files/ with the files scene inputs may reference (mesh, texture).
A scene input is the JSON text, optionally followed by a NUL byte and
NUL-separated --set overrides (see FuzzScene.cpp)."""
import base64, json, os, struct, zlib

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

def write(target, name, data):
    os.makedirs(os.path.join(root, target), exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(root, target, name), mode) as f:
        f.write(data)

def png(width, height):
    raw = b"".join(b"\0" + b"\xff\x80\x40\xff" * width for _ in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

# --- glTF ------------------------------------------------------------------
POSITIONS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
URI = "data:application/octet-stream;base64," + base64.b64encode(POSITIONS).decode()

def gltf(accessor=None, nodes=None, scene_nodes=(0,), extra=None, uri=URI):
    acc = {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}
    acc.update(accessor or {})
    doc = {"asset": {"version": "2.0"},
           "buffers": [{"byteLength": 36, **({"uri": uri} if uri else {})}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
           "accessors": [acc],
           "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}}]}],
           "nodes": nodes if nodes is not None else [{"mesh": 0}],
           "scenes": [{"nodes": list(scene_nodes)}], "scene": 0}
    doc.update(extra or {})
    return doc

def glb(doc, binary):
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body

gltf_cases = {
    "triangle.gltf": gltf(),
    "repro-accessor-offset-wraps.gltf": gltf({"byteOffset": 2**64 - 12}),
    "repro-accessor-count-huge.gltf": gltf({"count": 2**64 // 12}),
    "repro-view-offset-wraps.gltf": gltf(extra={"bufferViews": [{"buffer": 0, "byteOffset": 2**64 - 8, "byteLength": 44}]}),
    "repro-node-chain-20000.gltf": gltf(nodes=[{"children": [i + 1]} for i in range(19999)] + [{"mesh": 0}]),
    "repro-node-cycle.gltf": gltf(nodes=[{"children": [1]}, {"children": [0], "mesh": 0}]),
    "repro-node-two-parents.gltf": gltf(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}], scene_nodes=(0, 1)),
    "repro-translation-1e300.gltf": gltf(nodes=[{"mesh": 0, "translation": [1e300, 0, 0]}]),
    "repro-scale-overflows-composed.gltf": gltf(nodes=[{"children": [1], "scale": [1e30, 1, 1]}, {"mesh": 0, "scale": [1e30, 1, 1]}]),
}
for name, doc in gltf_cases.items():
    write("gltf", name, json.dumps(doc))
# Found by fuzzing: a buffer of byteLength 0 beside a 36-byte BIN chunk made
# tinygltf throw std::out_of_range (vector::at) from inside its loader.
write("glb", "repro-buffer-length-0-with-bin.glb", glb({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 0}]}, bytes(36)))
# Found by fuzzing: a buffer URI naming a directory (tinygltf took its size as 2^63 - 1).
write("gltf", "repro-buffer-uri-directory.gltf", json.dumps(gltf(uri=".")))
write("gltf", "repro-buffer-uri-percent.gltf",
      '{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": "%%%ageAAAAAgD8AAAAA"}], "bufene": 0}')
write("gltf", "repro-json-nested-10000.gltf", '{"asset":{"version":"2.0"},"extras":' + "[" * 10000 + "]" * 10000 + "}")
write("gltf", "repro-texture-16385x1.gltf", json.dumps(gltf(extra={
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
    "textures": [{"source": 0}],
    "images": [{"name": "wide", "uri": "data:image/png;base64," + base64.b64encode(png(16385, 1)).decode()}],
    "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}]})))

write("glb", "triangle.glb", glb(gltf(uri=None), POSITIONS))
write("glb", "repro-accessor-offset-wraps.glb", glb(gltf({"byteOffset": 2**64 - 12}, uri=None), POSITIONS))
write("glb", "repro-node-chain-20000.glb", glb(gltf(nodes=[{"children": [i + 1]} for i in range(19999)] + [{"mesh": 0}], uri=None), POSITIONS))
nested = b'{"asset":{"version":"2.0"},"extras":' + b"[" * 10000 + b"]" * 10000 + b"}"
nested += b" " * (-len(nested) % 4)
write("glb", "repro-json-nested-10000.glb", b"glTF" + struct.pack("<II", 2, 20 + len(nested)) + struct.pack("<II", len(nested), 0x4E4F534A) + nested)

# --- OBJ -------------------------------------------------------------------
write("obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n")
write("obj", "quad-negative.obj", "o quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n")
write("obj", "repro-control-bytes.obj", "v 0 0 0\nv 1 0 0\nv 0 1\v\f\r 2\nf 1 2 3\n")
write("obj", "repro-bad-number-cr.obj", "v 0 0 0\nv 1\r5 0 0\nv 0 1 0\nf 1 2 3\n")

# --- files scenes may reference ---------------------------------------------
write("files", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
write("files", "triangle.gltf", json.dumps(gltf()))
write("files", "texture.png", png(2, 2))
write("files", "wide-16385x1.png", png(16385, 1))
write("files", "chain.gltf", json.dumps(gltf_cases["repro-node-chain-20000.gltf"]))

# --- scenes ----------------------------------------------------------------
def scene(doc, *overrides):
    text = doc if isinstance(doc, str) else json.dumps(doc)
    return text.encode() + b"".join(b"\0" + o.encode() if isinstance(o, str) else b"\0" + o for o in overrides)

light = {"type": "directional", "direction": [0, -1, 0]}
write("scene", "minimal.json", scene({"lights": [light], "nodes": [{"shape": {"type": "box"}}]}))
write("scene", "meshes-and-texture.json", scene({
    "materials": {"t": {"baseColorTexture": "texture.png"}},
    "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0]}],
    "nodes": [{"mesh": "triangle.obj", "material": "t", "children": [{"mesh": "triangle.gltf", "translation": [1, 0, 0]}]}]},
    "lights[0].intensity=2", "camera.fovY=60"))
write("scene", "light-paths.json", scene({
    "lights": [{"type": "point", "position": [0, 2, 0], "path": {"type": "sine", "amplitude": [0, 0, 3], "angularFrequency": 0.5}},
               {"type": "spot", "position": [0, 3, 0], "path": {"type": "keyframes", "times": [0, 1, 2],
                                                                "positions": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "loop": True}}]},
    "lights[0].path.phase=1"))
write("scene", "camera-path.json", scene({
    "camera": {"position": [0, 2, 10], "path": {"type": "keyframes", "times": [0, 1, 2.5],
                                                "positions": [[0, 2, 10], [1, 2, 9], [1, 5, 9]],
                                                "targets": [[0, 0, 0], [0.5, 0, 0], [2, 0, -1]], "loop": True}},
    "lights": [light]},
    "camera.path.targets[2]=[2, 0, -2]"))
for path in sorted(os.listdir(os.path.join(root, "..", "..", "scenes"))):
    if not path.endswith(".json"):
        continue  # scenes/images/ holds what the scenes reference
    with open(os.path.join(root, "..", "..", "scenes", path)) as f:
        text = f.read()
    if "bunny.obj" not in text:  # the bunny is a file outside the corpus (and 70k triangles to load per run)
        write("scene", "bundled-" + path, text)
write("scene", "repro-children-nested-10000.json", '{"nodes":' + '[{"children":' * 10000 + "[]" + "}]" * 10000 + "}")
write("scene", "repro-set-index-past-2^64.json", scene({"lights": [light]}, "lights[99999999999999999999].intensity=1"))
write("scene", "repro-newline-in-key.json", scene('{"na\\nme": 1}'))
write("scene", "repro-newline-in-mesh-path.json", scene({"nodes": [{"mesh": "a\nb.obj"}]}))
write("scene", "repro-newline-in-set-value.json", scene({"lights": [light]}, "lights[0].intensity=1\n2"))
write("scene", "repro-invalid-utf8-in-set.json", scene({"lights": [light]}, b"name=a\xffb"))
write("scene", "repro-segments-2^64-1.json", scene('{"nodes":[{"shape":{"type":"torus","majorSegments":18446744073709551615}}]}'))
write("scene", "repro-camera-3e38.json", scene({"camera": {"position": [3e38, 3e38, 3e38]}}))
write("scene", "repro-direction-1e30.json", scene({"lights": [{"type": "directional", "direction": [1e30, 1e30, 1e30]}]}))
write("scene", "repro-lights-300.json", scene(json.dumps({"lights": [light] * 300}, separators=(",", ":"))))
write("scene", "repro-texture-is-directory.json", scene({"materials": {"m": {"baseColorTexture": "."}}}))
write("scene", "repro-translation-overflows-composed.json", scene(
    {"nodes": [{"translation": [3e38, 0, 0], "children": [{"translation": [3e38, 0, 0], "shape": {"type": "box"}}]}]}))
write("scene", "repro-gltf-chain-20000.json", scene({"nodes": [{"mesh": "chain.gltf"}]}))
