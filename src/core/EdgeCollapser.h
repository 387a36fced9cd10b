#pragma once
// The edge collapser behind meshLevels (MeshLevels.h): Garland and
// Heckbert's quadrics ordering half-edge collapses, a heap of vertices by
// their cheapest collapse, and each removed vertex held by a triangle of
// the level to bound its error. Set-up and levels: EdgeCollapser.cpp; one
// collapse and its bookkeeping: EdgeCollapse.cpp. Internal to core.
#include "core/LargePages.h"
#include "core/MeshLevels.h"
#include "core/VertexHeap.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

namespace shadowlab::detail {

// The symmetric 4x4 quadric of Garland and Heckbert: the sum of squared
// distances to a set of planes, weighted.
struct Quadric {
    std::array<double, 10> q{}; // xx xy xz xw yy yz yw zz zw ww

    void addPlane(const glm::dvec3& n, double d, double w) {
        q[0] += w * n.x * n.x; q[1] += w * n.x * n.y; q[2] += w * n.x * n.z; q[3] += w * n.x * d;
        q[4] += w * n.y * n.y; q[5] += w * n.y * n.z; q[6] += w * n.y * d;
        q[7] += w * n.z * n.z; q[8] += w * n.z * d;
        q[9] += w * d * d;
    }
    Quadric& operator+=(const Quadric& o) {
        for (std::size_t i = 0; i < q.size(); ++i) q[i] += o.q[i];
        return *this;
    }
    double at(const glm::dvec3& p) const {
        return q[0] * p.x * p.x + 2.0 * q[1] * p.x * p.y + 2.0 * q[2] * p.x * p.z + 2.0 * q[3] * p.x + q[4] * p.y * p.y +
               2.0 * q[5] * p.y * p.z + 2.0 * q[6] * p.y + q[7] * p.z * p.z + 2.0 * q[8] * p.z + q[9];
    }
};

constexpr std::uint32_t kNone = 0xffffffffu;

// The collapser's large arrays (core/LargePages.h: fewer page faults).
template <class T>
using Big = std::vector<T, LargePages<T>>;

// The squared distance from p to the triangle (a, b, c), through its
// closest point by the triangle's Voronoi regions (Ericson, Real-Time
// Collision Detection, 5.1.5). In double: in float, a point inside a long
// sliver (a flat region's collapses make them) came out 4e-5 of a unit
// square away from it, or not, by the order of the corners.
double squaredDistance(const glm::vec3& point, const glm::vec3& corner0, const glm::vec3& corner1, const glm::vec3& corner2);

class Collapser {
public:
    Collapser(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, MeshLevelWork& work);

    std::size_t live() const { return live_; }
    /// The vertices that never move (on an open or non-manifold edge).
    std::size_t locked() const { return locked_; }

    /// From now on a removed vertex whose triangle changes stays with what
    /// that triangle became while it lies within `slack` of it (the last
    /// level's error: no later level's error is raised past it that way),
    /// and the level's running bound starts again.
    void setSlack(float slack) {
        slack_ = slack;
        running_ = 0.0f;
    }

    /// Collapses the cheapest valid edges until at most `target` triangles
    /// live; false when no valid collapse is left first.
    bool reduceTo(std::size_t target);

    MeshLevel level() const;

    /// Numbers the live vertices and triangles anew, in the order they had
    /// (the order every choice breaks its ties by, so the levels come out
    /// the same), with nothing between them: a level's collapses then read
    /// half the memory the one before's did, and fewer cache lines.
    void compact();

    /// Puts each triangle's held vertices one after another in memory
    /// (collapses walk them triangle by triangle).
    void regroup();

private:
    // The most triangles a collapse may leave around its vertex: each step
    // around a vertex costs as many, and a mesh whose border never moves
    // would otherwise end in fans of hundreds (a grid's inside).
    static constexpr std::size_t kMostAround = 32;
    // Room each vertex's list of triangles has to grow at first.
    static constexpr std::uint32_t kRoom = 4;
    // A changed triangle's held vertex stays with it within this share of
    // the largest distance measured for the level so far (setSlack): all of
    // it, since a vertex within that distance cannot raise the level's error
    // and a search around the collapse's vertex costs a test per triangle.
    static constexpr float kRunningShare = 1.0f;
    // The mantissa bits of a collapse's cost its heap key keeps (bucket()).
    static constexpr int kCostBits = 1;
    // Triangle::first of a triangle collapsed away.
    static constexpr std::uint32_t kDead = kNone - 1;

    // Per vertex, what a collapse near it reads and writes, close together
    // (its quadric, read only for its own collapses, is in q_).
    struct Vertex {
        glm::vec3 position;
        std::uint32_t target = kNone; ///< in heap_: the neighbour its cheapest collapse moves it onto
        float cost = 0.0f;            ///< in heap_: that collapse's cost
        float self = 0.0f;            ///< its quadric at its position
        std::uint32_t mark = 0;       ///< the stamp() it was last marked with
        std::uint32_t near = 0;       ///< the collapse (nearStamp_) it was last next to the target of
        std::uint32_t start = 0, size = 0, capacity = 0; ///< its live triangles: size of them from pool_[start], room for capacity
        std::uint8_t removed = 0, locked = 0;
    };
    struct Triangle {
        std::array<std::uint32_t, 3> v;
        std::uint32_t first = kNone; ///< the first removed vertex it holds (held_[first], then through Held::next); kDead: gone
    };
    // A removed vertex, held by a live triangle.
    struct Held {
        glm::vec3 position;
        float distance = 0.0f;      ///< to the triangle holding it
        std::uint32_t next = kNone; ///< the next one that triangle holds
    };

    std::span<const std::uint32_t> around(std::uint32_t v) const { return {pool_.data() + v_[v].start, v_[v].size}; }

    // A fresh value for Vertex::mark (every vertex unmarked by it).
    std::uint32_t stamp() {
        if (++stamp_ == 0) {
            for (Vertex& v : v_) v.mark = 0;
            stamp_ = 1;
        }
        return stamp_;
    }

    // The distinct vertices sharing a triangle with v, into `out` (in the order met).
    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out);

    // The heap's key for a collapse of `cost`: the cost with all but its
    // top mantissa bits cleared, so that collapses within a few percent of
    // each other's cost come out by vertex number, which is spatial order
    // (neighbouring collapses read the same memory).
    static float bucket(float cost) {
        std::uint32_t bits;
        std::memcpy(&bits, &cost, sizeof bits);
        bits &= ~((1u << (23 - kCostBits)) - 1u);
        std::memcpy(&cost, &bits, sizeof bits);
        return cost;
    }

    // Garland and Heckbert's cost of moving `from` onto `to`: both
    // quadrics at `to`'s position.
    float cost(std::uint32_t from, std::uint32_t to) {
        ++work_.costs;
        return static_cast<float>(std::max(0.0, q_[from].at(glm::dvec3(v_[to].position)) + v_[to].self));
    }

    // Finds `from`'s cheapest collapse onto one of `around` (its
    // neighbours; ties: the lower vertex number) into its target and cost;
    // false when it has none.
    bool cheapest(std::uint32_t from, const std::vector<std::uint32_t>& around);

    // Keys `from` in the heap by its cheapest collapse onto one of
    // `around` (its neighbours), or takes it out when it may not move.
    void choose(std::uint32_t from, const std::vector<std::uint32_t>& around);
    void choose(std::uint32_t from);

    // As choose(), among the collapses valid now: `from`'s cheapest one was
    // refused. Out of the heap when none is, until a collapse next to it
    // chooses again.
    void chooseValid(std::uint32_t from);

    bool valid(std::uint32_t u, std::uint32_t v);

    // Drops triangle t from v's list.
    void drop(std::uint32_t v, std::uint32_t t);

    // Appends `add` to v's list, moving the list to the pool's end when it
    // has no room (the pool is packed first when it would outgrow what it
    // reserved).
    void append(std::uint32_t v, const std::vector<std::uint32_t>& add);

    // The lists one after another again, each with its room, in a pool
    // with as much again reserved.
    void pack();

    void collapse(std::uint32_t u, std::uint32_t v);

    // Gives each of the collapse's held vertices (changed_) a triangle around
    // v, which now cover what u's and v's did. A vertex is measured against
    // the triangle its old one became (the same one moved; for one that
    // went, the triangle on its edge that stays, through v and its third
    // vertex; for u, one through v) and stays there when that is no farther
    // than it was from the old one, or than the slack; else it goes to the
    // nearest triangle around v.
    void hold(std::uint32_t u, std::uint32_t v);

    // The triangle through v and `a` (one of v's), or kNone.
    std::uint32_t through(std::uint32_t v, std::uint32_t a) const;

    // The vertex of triangle t that is neither a nor b.
    std::uint32_t third(std::uint32_t t, std::uint32_t a, std::uint32_t b) const {
        const auto& tri = t_[t].v;
        return tri[0] != a && tri[0] != b ? tri[0] : tri[1] != a && tri[1] != b ? tri[1] : tri[2];
    }

    double squaredDistanceTo(const glm::vec3& p, std::uint32_t t) const {
        const auto& tri = t_[t].v;
        return squaredDistance(p, v_[tri[0]].position, v_[tri[1]].position, v_[tri[2]].position);
    }

    MeshLevelWork& work_;
    Big<std::uint32_t> original_; ///< per vertex here, its number in the mesh (the first of its position)
    Big<Vertex> v_;
    Big<Quadric> q_;
    Big<Triangle> t_;
    std::size_t live_ = 0, locked_ = 0;
    Big<std::uint32_t> pool_; ///< every vertex's list of triangles (Vertex::start)
    std::size_t reserved_ = 0;        ///< the lists' capacities' sum
    VertexHeap heap_{0};              ///< the vertices that may move, by their cheapest collapse
    float slack_ = 0.0f, running_ = 0.0f; ///< setSlack
    std::uint32_t stamp_ = 0, nearStamp_ = 0;
    Big<Held> held_, spareHeld_; ///< the removed vertices; regroup()'s
    std::vector<std::pair<std::uint32_t, std::uint32_t>> changed_; ///< a collapse's held vertices, each with its old triangle (kNone: u)
    std::vector<std::uint32_t> moved_, scratchA_, scratchB_;
    std::vector<std::pair<float, std::uint32_t>> scratchCosts_;
};

} // namespace shadowlab::detail
