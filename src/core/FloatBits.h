#pragma once
// A float's bits as == compares floats: a zero of either sign gives +0's
// bits, so that positions == calls one sort, hash and compare as one (a NaN,
// which == makes equal to nothing, is the caller's to set apart). GPU-free.
#include <bit>
#include <cstdint>

namespace shadowlab {

inline std::uint32_t equalityBits(float v) { return v == 0.0f ? 0u : std::bit_cast<std::uint32_t>(v); }

} // namespace shadowlab
