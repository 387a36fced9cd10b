#pragma once
// Scenes an independent exact checker built to find the map's defects
// (issue 58), shared by MapDefectsGLTest and MapMatrixGLTest.

namespace shadowlab::test {

// A far scene (the checker's): a 200 m ground under a sun with boxes 60 m
// from a camera at eye height: every texel of a map that ignored the frame
// spans several pixels at 1920x1080.
inline const char* kFarBoxes = R"({
  "camera": {"position": [0, 1.7, 0], "target": [0, 0.5, -60], "fovY": 40, "near": 0.1, "far": 300},
  "lights": [{"name": "sun", "type": "directional", "direction": [0.7, -0.45, 0.35]}],
  "nodes": [
    {"name": "ground", "shape": {"type": "plane", "size": [200, 200]}},
    {"name": "box 1", "shape": {"type": "box", "size": [2, 4, 2]}, "translation": [-6, 2, -58]},
    {"name": "box 2", "shape": {"type": "box", "size": [1, 5, 1]}, "translation": [-1, 2.5, -62]},
    {"name": "box 3", "shape": {"type": "box", "size": [3, 3, 2]}, "translation": [3, 1.5, -66]},
    {"name": "box 4", "shape": {"type": "box", "size": [1, 2, 1]}, "translation": [6, 1, -55]},
    {"name": "pole", "shape": {"type": "box", "size": [0.3, 6, 0.3]}, "translation": [-3, 3, -52]}
  ]
})";

// The checker's thin casters under a low sun: a 10-degree sun over a 3 cm
// slab lying on a 20 m ground (its shadow 17 cm long) and a floating
// plate; the camera's near plane 0.05 m, its far 200 m, the nearest
// receiver 5.8 m away. Splits placed from the near plane left cascade 0
// (0.05-4.24 m) empty and the whole frame on cascade 1's 6 cm texels.
inline const char* kThinSlab = R"({
  "camera": {"position": [0, 3, 15], "target": [0, 0, 3], "fovY": 45, "near": 0.05, "far": 200},
  "lights": [{"name": "low sun", "type": "directional", "direction": [-0.9848, -0.1736, 0.0],
              "shadow": {"technique": "map"}}],
  "nodes": [
    {"name": "ground", "shape": {"type": "plane", "size": [20, 20]}},
    {"name": "slab", "shape": {"type": "box", "size": [2, 0.03, 1]}, "translation": [0.5, 0.015, 5]},
    {"name": "plate", "shape": {"type": "box", "size": [1.5, 0.02, 1.5]}, "translation": [-2, 0.5, 2]}
  ]
})";

} // namespace shadowlab::test
