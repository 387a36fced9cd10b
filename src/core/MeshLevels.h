#pragma once
// Coarser versions of a dense triangle mesh for depth-only passes (a shadow
// map's casters): where a map texel covers many of a caster's triangles,
// drawing them all costs the rasteriser its setup per triangle for depths a
// few larger triangles give within a fraction of a texel. GPU-free.
//
// Each level is made by edge collapses onto one of the edge's own vertices
// (a half-edge collapse, ordered by Garland and Heckbert's quadric error),
// so a level is an index list over the mesh's own vertices: the vertex
// buffer is shared, and every vertex of a level lies on the mesh's surface.
// Vertices are welded by position first (a mesh splits them for normals and
// uvs); those on an open or non-manifold edge never move, and a collapse
// that would turn a triangle over or pinch the surface is refused.
//
// The cost is about n log n in the triangles, the memory linear, and the
// result the same every run (a large mesh is built in two halves on two
// threads, MeshLevelOptions::splitTriangles): a heap holds each vertex once, keyed by its
// cheapest collapse (ties by vertex number); no vertex gathers more than 32
// triangles; each removed vertex is held by one triangle of the level and
// measured again only when a collapse changes that triangle (MeshLevel::error).
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab {

struct MeshLevel {
    std::vector<std::uint32_t> indices; ///< triangles over the mesh's own vertices, winding kept
    /// Object space: no vertex of the mesh's triangles lies farther than this
    /// from the level's surface. Each removed vertex is held by one triangle
    /// of the level and this is the largest distance from such a vertex to
    /// its triangle: an upper bound, the nearest triangle being no farther.
    /// A vertex is given the nearest triangle around the vertex it collapses
    /// into, and again, among those around the collapse's vertex, whenever a
    /// collapse changes or removes its triangle (the triangles around that
    /// vertex then cover the region the changed ones did).
    float error = 0.0f;
};

/// A level as a draw chooses it (GpuScene::levels, TechniqueHost::detailLevels).
struct DetailLevel {
    float error = 0.0f;        ///< MeshLevel::error
    std::size_t triangles = 0; ///< the level's triangles
};

struct MeshLevelOptions {
    std::size_t minTriangles = 4096;   ///< meshes with fewer triangles get no levels
    double reduction = 0.5;            ///< each level keeps at most this share of the triangles of the one before (0.1..0.9)
    std::size_t fewestTriangles = 256; ///< no level is made below this many triangles
    /// A mesh of at least this many triangles is simplified in two halves at
    /// once, on two threads (split at the median along its longest side; the
    /// cut's vertices never move, so each level's error bound holds for the
    /// whole and the levels are the same every run); 0: never.
    std::size_t splitTriangles = 262144;
};

/// What building a mesh's levels took, counted in steps rather than timed
/// (unit tests bound these per triangle; speed is `shadowlab bench`'s).
struct MeshLevelWork {
    std::uint64_t distanceTests = 0; ///< pointTriangleDistance calls (measuring MeshLevel::error)
    std::uint64_t costs = 0;         ///< quadric costs of collapses worked out (ordering them)
    std::uint64_t starVisits = 0;    ///< triangles looked at around vertices (validity, neighbours, moves)
};

/// The coarser levels of the triangle mesh (`indices` over `positions`),
/// finest first; none for a small mesh or one that cannot be reduced.
/// `work`, when given, receives what it took.
std::vector<MeshLevel> meshLevels(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
                                  const MeshLevelOptions& options = {}, MeshLevelWork* work = nullptr);

/// The distance from `p` to the triangle (a, b, c).
float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

} // namespace shadowlab
