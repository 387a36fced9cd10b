#pragma once
// The clustered light list on the GPU: the lights that have no shadow pass of
// their own after the base pass (Technique::joinsLightList: none, or a map
// in the shadow atlas) beyond the base pass's light,
// shaded together in one pass (lighting.frag's LIGHT_LIST variant) instead
// of a pass each. Binned per frame on the CPU (geometry/LightTiles.h).
#include "geometry/LightTiles.h"
#include "gl/Object.h"

#include <shadowlab/Scene.h>

#include <vector>

namespace shadowlab {

class LightList {
public:
    /// Uploads `lights` (indices into scene.lights), each with its shadow
    /// (ListedLight::shadow, from its technique), and their tiles for the
    /// frame seen through `viewFromWorld` and `clipFromView` at `size`.
    void upload(const Scene& scene, const std::vector<int>& lights, const std::vector<glm::vec4>& shadows, const glm::mat4& viewFromWorld,
                const glm::mat4& clipFromView, glm::ivec2 size);
    /// Binds both buffers at SL_STORAGE_LIGHT_LIST and SL_STORAGE_LIGHT_TILES.
    void bind() const;
    /// The last upload's tiles (entries, culled lights).
    const LightTiles& tiles() const { return tiles_; }

private:
    gl::Buffer lights_{gl::NoCreate}, cells_{gl::NoCreate};
    std::size_t lightBytes_ = 0, cellBytes_ = 0;  ///< capacities
    LightTiles tiles_;
};

} // namespace shadowlab
