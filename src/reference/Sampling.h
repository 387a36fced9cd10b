#pragma once
/// @file Sampling.h
/// The soft lights' sample points: per-sample random numbers (Pcg32), an
/// orthonormal basis around a direction, and the concentric map of the unit
/// square onto the unit disk. Private to the reference.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace shadowlab::reference {

// Per-sample random numbers: a PCG32 stream (O'Neill 2014) whose state comes
// from splitmix64(seed, sample index), so every sample's jitter is fixed by
// the seed alone, whatever thread traces it.
class Pcg32 {
public:
    Pcg32(unsigned seed, std::uint64_t index) {
        std::uint64_t z = (std::uint64_t(seed) << 32 ^ index) + 0x9E3779B97F4A7C15ull;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        state_ = z ^ (z >> 31);
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + 1442695040888963407ull;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    /// Uniform in [0, 1): 24 random mantissa bits.
    float uniform() { return float(next() >> 8) * 0x1.0p-24f; }
private:
    std::uint64_t state_ = 0;
};

// Orthonormal basis around unit w (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): no branch on a threshold, no singularity.
inline void orthonormalBasis(const glm::vec3& w, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, w.z);
    const float a = -1.0f / (sign + w.z);
    const float c = w.x * w.y * a;
    t = glm::vec3(1.0f + sign * w.x * w.x * a, sign * c, -sign * w.x);
    b = glm::vec3(c, sign + w.y * w.y * a, -w.y);
}

// Shirley-Chiu concentric map of the unit square onto the unit disk:
// area-preserving (uniform in, uniform out) and low-distortion, so jittered
// grid strata stay compact on the disk. Returns polar (radius, angle).
inline void concentricDisk(float u, float v, float& radius, float& angle) {
    const float a = 2.0f * u - 1.0f;
    const float b = 2.0f * v - 1.0f;
    constexpr float quarterPi = std::numbers::pi_v<float> / 4.0f;
    if (a == 0.0f && b == 0.0f) {
        radius = 0.0f;
        angle = 0.0f;
    } else if (std::abs(a) > std::abs(b)) {
        radius = a;
        angle = quarterPi * (b / a);
    } else {
        radius = b;
        angle = 2.0f * quarterPi - quarterPi * (a / b);
    }
}

} // namespace shadowlab::reference
