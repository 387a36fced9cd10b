#pragma once
// Every item's draw block (transforms and material) for one frame, uploaded
// once into one uniform buffer; a draw binds its item's range at
// SL_BINDING_DRAW. One upload per frame instead of one per draw, and a
// technique that draws items gets the same per-item transforms.
#include "gl/Object.h"

#include <shadowlab/Scene.h>

#include <cstddef>
#include <vector>

namespace shadowlab {

class DrawList {
public:
    /// Fills the blocks of `items` (materials from `scene`).
    void upload(const Scene& scene, const std::vector<DrawItem>& items);
    /// Binds item i's block at SL_BINDING_DRAW.
    void bind(std::size_t item) const;

private:
    gl::Buffer buffer_{gl::NoCreate};
    std::size_t capacity_ = 0; ///< bytes the buffer holds
    std::size_t stride_ = 0;   ///< bytes between blocks (the uniform-buffer offset alignment)
    std::vector<unsigned char> staging_;
};

} // namespace shadowlab
