// Technique "volume": the uniform block shared by its C++ (src/techniques/
// Volume.cpp) and its GLSL (shadow_volume.*).
#ifndef SHADOWLAB_SHADOW_VOLUME_SHARED_H
#define SHADOWLAB_SHADOW_VOLUME_SHARED_H

#include "shadowlab_shared.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct VolumeUniforms {
    glm::vec4 light;   // the light's position (w = 1), or the direction towards a directional light (w = 0)
    glm::vec4 params;  // x: the book's extrusion distance (beyond the scene's box), yzw unused
};
} // namespace shadowlab::shared
#else
layout(std140, binding = SL_BINDING_TECHNIQUE) uniform VolumeUniforms {
    vec4 light;
    vec4 params;
} volume;
#endif
#endif
