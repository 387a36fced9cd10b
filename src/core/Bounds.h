#pragma once
// Axis-aligned bounding boxes in one space (world, object, light).
#include <glm/glm.hpp>

#include <algorithm>
#include <limits>

namespace shadowlab {

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    void add(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Bounds& b) {
        if (b.empty()) return;
        add(b.lo);
        add(b.hi);
    }
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    /// Corner c (0..7): bit 0 picks hi.x, bit 1 hi.y, bit 2 hi.z.
    glm::vec3 corner(int c) const { return glm::vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z); }
    /// The distance from `p` to the box (0 inside it).
    float distanceTo(const glm::vec3& p) const { return glm::length(glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f))); }
    /// The distance from `p` to the farthest corner.
    float farthestFrom(const glm::vec3& p) const { return glm::length(glm::max(glm::abs(lo - p), glm::abs(hi - p))); }
    glm::vec3 size() const { return hi - lo; }
    /// The part of this box inside `o` (empty when they do not overlap).
    Bounds cutTo(const Bounds& o) const {
        Bounds out;
        out.lo = glm::max(lo, o.lo);
        out.hi = glm::min(hi, o.hi);
        return out;
    }
    /// The bounds of this box's eight corners moved by an affine `to`.
    Bounds transformed(const glm::mat4& to) const {
        Bounds out;
        if (empty()) return out;
        for (int c = 0; c < 8; ++c) out.add(glm::vec3(to * glm::vec4(corner(c), 1.0f)));
        return out;
    }
};

} // namespace shadowlab
