#pragma once
/// @file Shapes.h
/// Procedural meshes. Every shape is centred on the origin of its bounding
/// box (round shapes exactly so when their segment count is a multiple of 4,
/// as the defaults are; otherwise the polygon's corners fall unevenly), with +Y up, counter-clockwise front faces, unit normals and uvs in
/// [0,1]. Sizes are in scene units; each function throws shadowlab::Error
/// for a size that is not finite and > 0 or a segment count below its minimum.
#include <shadowlab/Export.h>
#include <shadowlab/Scene.h>

namespace shadowlab::shapes {

/// Flat square-cornered plane in XZ, normal +Y, `width` along X, `depth` along Z.
SHADOWLAB_API Mesh plane(float width, float depth);
/// Axis-aligned box with flat-shaded faces (24 vertices).
SHADOWLAB_API Mesh box(const glm::vec3& size);
/// UV sphere. segments >= 3 (around Y), rings >= 2 (pole to pole).
SHADOWLAB_API Mesh sphere(float radius, int segments = 48, int rings = 24);
/// Torus around the Y axis (ring lies in XZ). majorRadius > minorRadius.
/// majorSegments >= 3, minorSegments >= 3.
SHADOWLAB_API Mesh torus(float majorRadius, float minorRadius, int majorSegments = 64, int minorSegments = 32);
/// Capped cylinder along Y, centred (y from -height/2 to +height/2). segments >= 3.
SHADOWLAB_API Mesh cylinder(float radius, float height, int segments = 48);
/// Capped cone along Y, base at y = -height/2, apex at +height/2. segments >= 3.
SHADOWLAB_API Mesh cone(float radius, float height, int segments = 48);
/// Square-based pyramid (as in the lecture scenes): base `baseWidth` x `baseWidth`
/// at y = -height/2, apex at +height/2, flat-shaded (18 vertices).
SHADOWLAB_API Mesh pyramid(float baseWidth, float height);
/// A flat disc of `radius` in the XZ plane facing +Y (one-sided, like
/// plane()), a fan of `segments` triangles around a vertex at the origin
/// (the technique "disc" knows a disc by this and shadows with the exact
/// circle of radius `radius`).
SHADOWLAB_API Mesh disc(float radius, int segments = 128);

} // namespace shadowlab::shapes
