#pragma once
/// @file LightSetup.h
/// A light resolved once for a batch of shadow rays (LightSetup): its type,
/// position, direction, cone and range as light_reach.h reads them, and
/// what its soft samples are drawn from. Private to the reference.
#include "reference/RayTracer.h"

#include "light_reach.h"

#include <glm/glm.hpp>

namespace shadowlab::reference {

// Everything a ray needs to know about the light, resolved once per call.
struct LightSetup {
    LightType type = LightType::Directional;
    glm::vec3 position{0.0f};
    glm::vec3 towardLight{0.0f, 1.0f, 0.0f}; // directional: -direction, unit
    glm::vec3 axis{0.0f, -1.0f, 0.0f};       // spot: direction, unit
    glm::vec3 coneT{1.0f, 0.0f, 0.0f};       // directional soft: basis around towardLight
    glm::vec3 coneB{0.0f, 0.0f, 1.0f};
    float cosOuter = -1.0f;
    float range = 0.0f;
    float size = 0.0f;              // point/spot: disk radius
    float oneMinusCosHalf = 0.0f;   // directional: 1 - cos(half angular diameter)
    bool soft = false;

    int shaderType = SL_LIGHT_DIRECTIONAL; // the SL_LIGHT_* code of `type`

    // The sample can receive this light at all: valid, within its reach
    // (shared::slLightReaches, the definition lighting.frag uses: spot cone,
    // range) and facing its centre on the geometric normal.
    bool reaches(const SurfaceSample& s) const {
        if (!s.valid) return false;
        if (!shared::slLightReaches(shaderType, position, axis, range, cosOuter, s.position)) return false;
        const glm::vec3 toLight = type == LightType::Directional ? towardLight : position - s.position;
        return glm::dot(s.normal, toLight) > 0.0f;
    }
};

// The setup of `light`. Throws shadowlab::Error for a zero or non-finite
// direction (directional and spot lights).
LightSetup makeLightSetup(const Light& light);

} // namespace shadowlab::reference
