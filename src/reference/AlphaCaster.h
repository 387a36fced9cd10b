#pragma once
/// @file AlphaCaster.h
/// What the tracer's occlusion filters read and gather: an alpha-tested or
/// translucent caster's texture coordinates, material and texture
/// (RayTracer::AlphaCaster), the transmittance each ray of a packet has
/// gathered (TransmitContext), and the two filters (AlphaCaster.cpp).
/// Private to the reference.
#include "reference/RayTracer.h"

#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab::reference {

struct RayTracer::AlphaCaster {
    std::vector<glm::vec2> uvs;           ///< per vertex (empty: all (0, 0))
    std::vector<std::uint32_t> indices;   ///< three per triangle, as the geometry's
    float alpha = 1.0f, cutoff = 0.5f;
    bool translucent = false;             ///< blend: light passes, filtered by transmittanceAt()
    glm::vec3 baseColor{1.0f};            ///< linear
    const ImageRGBA8* texture = nullptr;  ///< the base-colour texture (the tracer's copy), or none

    // The texture at uv as the GPU reads it (alpha_test.h: textureLod level
    // 0, bilinear, repeating), each texel through `fetch` (its bytes).
    template <class Fetch>
    auto bilinear(glm::vec2 uv, const Fetch& fetch) const {
        const int w = texture->width, h = texture->height;
        const float x = uv.x * static_cast<float>(w) - 0.5f, y = uv.y * static_cast<float>(h) - 0.5f;
        const float fx0 = std::floor(x), fy0 = std::floor(y), fx = x - fx0, fy = y - fy0;
        const auto at = [&](float xf, float yf) {
            const long xi = ((static_cast<long>(xf) % w) + w) % w, yi = ((static_cast<long>(yf) % h) + h) % h;
            return fetch(&texture->pixels[(static_cast<std::size_t>(yi) * static_cast<std::size_t>(w) + static_cast<std::size_t>(xi)) * 4]);
        };
        const auto top = at(fx0, fy0) + fx * (at(fx0 + 1.0f, fy0) - at(fx0, fy0));
        const auto bottom = at(fx0, fy0 + 1.0f) + fx * (at(fx0 + 1.0f, fy0 + 1.0f) - at(fx0, fy0 + 1.0f));
        return top + fy * (bottom - top);
    }
    bool hasTexture() const { return texture && texture->width > 0 && texture->height > 0; }
    // Its alpha at uv: the bytes / 255.
    float textureAlpha(glm::vec2 uv) const {
        return bilinear(uv, [](const std::uint8_t* p) { return static_cast<float>(p[3]) / 255.0f; });
    }
    // Its colour at uv, decoded from sRGB as the GPU's SRGB8_ALPHA8 is.
    glm::vec4 textureAt(glm::vec2 uv) const {
        const auto linear = [](std::uint8_t c) {
            const float v = static_cast<float>(c) / 255.0f;
            return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
        };
        return bilinear(uv, [&](const std::uint8_t* p) { return glm::vec4(linear(p[0]), linear(p[1]), linear(p[2]), static_cast<float>(p[3]) / 255.0f); });
    }
    glm::vec2 uvAt(unsigned prim, float u, float v) const {
        if (uvs.empty()) return glm::vec2(0.0f);
        const std::size_t base = static_cast<std::size_t>(prim) * 3;
        return (1.0f - u - v) * uvs[indices[base]] + u * uvs[indices[base + 1]] + v * uvs[indices[base + 2]];
    }
    // A translucent (blend) surface's transmittance at barycentrics (u, v)
    // of triangle `prim`: white through its clear parts, its colour where it
    // is opaque (alpha_test.h's surfaceTransmittance on the GPU).
    glm::vec3 transmittanceAt(unsigned prim, float u, float v) const {
        glm::vec4 c(baseColor, alpha);
        if (hasTexture()) c *= textureAt(uvAt(prim, u, v));
        return glm::mix(glm::vec3(1.0f), glm::vec3(c), c.a);
    }
    // Whether the surface is there at barycentrics (u, v) of triangle `prim`.
    bool solidAt(unsigned prim, float u, float v) const {
        const float a = alpha * (hasTexture() ? textureAlpha(uvAt(prim, u, v)) : 1.0f);
        return a >= cutoff;
    }
};

// The intersect context every packet is traced with: the transmittance each
// ray (its RTCRay::id, a lane of the packet) has gathered through translucent
// casters, and the translucent triangles it has already crossed (Embree may
// report a triangle more than once with spatial splits).
struct TransmitContext {
    RTCIntersectContext base;  // first: the filter gets a pointer to it
    std::array<glm::vec3, 16> transmit;
    std::array<std::array<std::uint64_t, 8>, 16> crossed;
    std::array<int, 16> crossedCount;
    void reset() {
        transmit.fill(glm::vec3(1.0f));
        crossedCount.fill(0);
    }
};

// Embree's occlusion filter for a translucent caster: the ray goes on,
// filtered by the surface's transmittance (once per triangle crossed).
void translucentFilter(const RTCFilterFunctionNArguments* args);

// Embree's occlusion filter for an alpha-tested caster: a hit in one of its
// holes is rejected, the ray goes on.
void alphaFilter(const RTCFilterFunctionNArguments* args);

} // namespace shadowlab::reference
