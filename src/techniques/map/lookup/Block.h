#pragma once
// Technique "map": its uniform block (shaders/shadow_map_shared.h,
// shared::MapUniforms at SL_BINDING_TECHNIQUE), filled per light.
#include "techniques/TechniqueBlock.h"
#include "techniques/map/Light.h"
#include "techniques/map/passes/Arrays.h"

#include <shadowlab/Scene.h>

#include "shadow_map_shared.h"

namespace shadowlab::map {

class MapBlock {
public:
    /// The block for light `p` (in array `g`), written and bound.
    void upload(const MapLight& p, const MapArray& g, const Light& light, bool translucent);
    /// The block for light `p` whose map is in the shadow atlas (MapAtlas): its tiles and bias, written and bound.
    void uploadAtlas(const MapLight& p, const Light& light);
    /// Only the shadow pass's camera (the block's first member).
    void setLightClip(const glm::mat4& lightClipFromWorld);
    /// The shadow pass's camera for layer c of `p`'s (a cascade's, or the
    /// one map's): the CPU's, or the GPU's fit (MapLight::gpuFit).
    void setCamera(const MapLight& p, std::size_t c);
    /// The moments' passes: radius (texels), axis (unused: the variant says it) and the depth layer they are made from.
    void setBlur(float radius, float axis, float layer);
    /// The last uploaded block with another shadow-pass camera, whole.
    void writeWithLightClip(const glm::mat4& lightClipFromWorld);
    /// The last uploaded block again, whole.
    void restore();

private:
    /// The GPU's fit over the camera's members (MapLight::gpuFit), if any.
    void copyFit();
    TechniqueBlock<shared::MapUniforms> block_;
    shared::MapUniforms uniforms_{};  ///< what upload() last wrote
    const gl::Buffer* fitted_ = nullptr;  ///< and the GPU's fit it took
    bool fittedCascades_ = false;         ///< a fit of cascades
    bool fittedWarp_ = false;             ///< a fit of warped cameras (one map, or cascades not stabilised)
};

} // namespace shadowlab::map
