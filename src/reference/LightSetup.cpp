/// @file LightSetup.cpp
/// The light resolved once per batch of rays (makeLightSetup), which samples
/// it reaches at all (lightReach), and where a shadow ray leaves its surface
/// (offsetRayOrigin).
#include "reference/LightSetup.h"

#include "reference/Sampling.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

namespace shadowlab::reference {

LightSetup makeLightSetup(const Light& light) {
    LightSetup setup;
    setup.type = light.type;
    setup.position = light.position;
    setup.range = light.range;
    setup.soft = light.size > 0.0f;
    setup.shaderType = light.type == LightType::Directional ? SL_LIGHT_DIRECTIONAL
                       : light.type == LightType::Spot      ? SL_LIGHT_SPOT
                                                            : SL_LIGHT_POINT;
    const std::string who = "RayTracer: light '" + light.name + "': ";
    if (light.type != LightType::Point) {
        const float len = glm::length(light.direction);
        if (!(len > 0.0f) || !std::isfinite(len))
            throw Error(who + "direction must be a finite nonzero vector");
        setup.axis = light.direction / len;
        setup.towardLight = -setup.axis;
    }
    if (light.type == LightType::Spot)
        setup.cosOuter = std::cos(glm::radians(light.outerConeDeg));
    if (setup.soft) {
        if (light.type == LightType::Directional) {
            // size = angular diameter in degrees; the half angle is at most pi.
            const float half = std::min(glm::radians(light.size) * 0.5f, std::numbers::pi_v<float>);
            setup.oneMinusCosHalf = 1.0f - std::cos(half);
            orthonormalBasis(setup.towardLight, setup.coneT, setup.coneB);
        } else {
            setup.size = light.size;
        }
    }
    return setup;
}

glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
    // Wachter and Binder, "A Fast and Robust Method for Avoiding
    // Self-Intersection", Ray Tracing Gems ch. 6 (2019): move each coordinate
    // by kIntScale * n_i units in its own last place (integer arithmetic on
    // the float's bits, so the step cannot be rounded away); near zero, where
    // ulps vanish, by kFloatScale * n_i scene units instead.
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    glm::vec3 o;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(p[i]) < kOrigin) {
            o[i] = p[i] + kFloatScale * n[i];
            continue;
        }
        // Away from zero the bits of |p| stay far from the sign bit and
        // from wrapping, so the step is computed on unsigned bits (defined
        // modular arithmetic; -0.0f, whose bits are INT_MIN, never gets here).
        const auto ulps = static_cast<std::int32_t>(kIntScale * n[i]);
        const std::uint32_t step = static_cast<std::uint32_t>(p[i] < 0.0f ? -ulps : ulps);
        o[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(p[i]) + step);
    }
    // Plus a push along the normal for the rasterizer's error: p is a
    // position the GPU interpolated into an RGBA32F target, which can lie a
    // few ulps of the largest coordinate (more where the plane equation
    // cancels) below the triangle Embree sees. 2^-16 of the largest
    // coordinate is 128 of its ulps; CompareGLTest measured at most 5.7 on a
    // large tilted plane (RasterizedPositionsLieWithinTheOriginPush).
    constexpr float kPushPerUnit = 1.0f / 65536.0f;
    const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
    return o + (kPushPerUnit * magnitude) * n;
}

std::vector<std::uint8_t> lightReach(const Light& light, const std::vector<SurfaceSample>& samples) {
    const LightSetup setup = makeLightSetup(light);
    std::vector<std::uint8_t> out(samples.size(), 0);
    for (std::size_t i = 0; i < samples.size(); ++i) out[i] = setup.reaches(samples[i]) ? 1 : 0;
    return out;
}

} // namespace shadowlab::reference
