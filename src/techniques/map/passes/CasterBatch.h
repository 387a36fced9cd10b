#pragma once
// Technique "map": the opaque casters in world space, all in one vertex
// and one index buffer, so that a shadow atlas tile draws every caster it
// culls in one call (glMultiDrawElements) instead of a draw, a vertex
// array and a uniform range per caster: with 64 lights' tiles a frame,
// those per-draw costs were most of their shadow passes on llvmpipe.
// Built once per upload and kept while the casters' transforms stay.
// Casters with holes (alphaMode mask) are not in it: they need their
// uv and texture, and are drawn one by one (MapAtlas::draw).
#include "techniques/Technique.h"

#include <cstdint>
#include <vector>

namespace shadowlab::map {

/// What the casters' world geometry follows from: the upload and every
/// item's mesh, material, caster flag and transform (a hash).
std::uint64_t casterInputs(const FrameInfo& frame);

class MapCasterBatch {
public:
    /// Makes the buffers for `frame`'s items unless they hold them already.
    void update(const FrameInfo& frame);
    /// Whether item i is in the batch (an opaque caster).
    bool holds(std::size_t item) const { return item < first_.size() && count_[item] > 0; }
    /// Draws the items `wanted` picks (those in the batch only) with
    /// `program` (a vertex stage reading world positions at location 0),
    /// in one call; returns the triangles drawn.
    std::size_t draw(const gl::Program& program, const std::vector<std::size_t>& wanted);

private:
    std::uint64_t builtFor_ = 0;
    bool built_ = false;
    gl::Buffer vertices_{gl::NoCreate}, indices_{gl::NoCreate};
    gl::VertexArray vao_{gl::NoCreate};
    std::vector<std::uint32_t> first_, count_;  ///< per item: its first index and index count (0: not in the batch)
    std::vector<GLsizei> counts_;               ///< scratch for the draw
    std::vector<const void*> offsets_;
};

} // namespace shadowlab::map
