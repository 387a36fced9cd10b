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
layout(std140) SL_BINDING(SL_BINDING_TECHNIQUE) uniform VolumeUniforms {
    vec4 light;
    vec4 params;
} volume;

// Shared by the geometry shader and the CPU path's vertex shader, so both
// put every vertex of a volume at the very same place.
vec3 towardsLight(vec3 p) { return volume.light.w > 0.5 ? volume.light.xyz - p : volume.light.xyz; }
#if BOOK
// Ganovelli et al. §8.5: the silhouette swept to a finite distance, beyond the scene's box.
vec4 atInfinity(vec3 p) { return frame.clipFromWorld * vec4(p - normalize(towardsLight(p)) * volume.params.x, 1.0); }
#else
vec4 atInfinity(vec3 p) { return frame.clipFromWorld * vec4(-towardsLight(p), 0.0); }
#endif
vec4 here(vec3 p) { return frame.clipFromWorld * vec4(p, 1.0); }
#endif
#endif
