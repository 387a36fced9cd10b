// Coarser levels of a dense mesh by quadric-ordered half-edge collapses (MeshLevels.h).
#include "core/MeshLevels.h"

#include "core/Adjacency.h"
#include "core/LargePages.h"
#include "core/VertexHeap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <utility>

namespace shadowlab {

namespace {

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
double squaredDistance(const glm::vec3& point, const glm::vec3& corner0, const glm::vec3& corner1, const glm::vec3& corner2) {
    const glm::dvec3 p(point), a(corner0), b(corner1), c(corner2);
    const auto squared = [&](const glm::dvec3& q) { return glm::dot(p - q, p - q); };
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return squared(a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return squared(b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return squared(a + ab * (d1 / (d1 - d3)));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return squared(c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return squared(a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return squared(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0.0)) return squared(a); // degenerate: a vertex
    const double v = vb / denom, w = vc / denom;
    return squared(a + ab * v + ac * w);
}

class Collapser {
public:
    Collapser(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, MeshLevelWork& work) : work_(work) {
        // The surface's own vertices (welded by position), numbered anew.
        const std::vector<std::uint32_t> weld = weldByPosition(positions);
        Big<std::uint32_t> number(positions.size(), kNone);
        for (std::uint32_t i = 0; i < positions.size(); ++i)
            if (weld[i] == i) original_.push_back(i);
        t_.reserve(indices.size() / 3);
        for (std::uint32_t k = 0; k < original_.size(); ++k) number[original_[k]] = k;
        v_.resize(original_.size());
        q_.resize(original_.size());
        for (std::uint32_t k = 0; k < original_.size(); ++k) v_[k].position = positions[original_[k]];
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            const std::array<std::uint32_t, 3> tri{number[weld[indices[t]]], number[weld[indices[t + 1]]], number[weld[indices[t + 2]]]};
            if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
            t_.push_back({tri});
        }
        live_ = t_.size();
        held_.reserve(v_.size());
        // The triangles around each vertex, one list after another in pool_
        // with a little room each to grow (a collapse brings it u's).
        for (const Triangle& t : t_)
            for (const std::uint32_t v : t.v) ++v_[v].capacity;
        std::size_t at = 0;
        for (Vertex& v : v_) {
            if (v.capacity > 0) v.capacity += kRoom;
            v.start = static_cast<std::uint32_t>(at);
            at += v.capacity;
        }
        pool_.reserve(2 * at); // room to move lists to: packed only when that runs out (append())
        pool_.assign(at, 0);
        reserved_ = at;
        for (std::uint32_t i = 0; i < t_.size(); ++i) {
            const auto& tri = t_[i].v;
            for (const std::uint32_t v : tri) pool_[v_[v].start + v_[v].size++] = i;
            const glm::dvec3 a(v_[tri[0]].position), b(v_[tri[1]].position), c(v_[tri[2]].position);
            const glm::dvec3 cross = glm::cross(b - a, c - a);
            const double length = glm::length(cross);
            if (!(length > 0.0)) continue;
            const glm::dvec3 normal = cross / length;
            for (const std::uint32_t v : tri) q_[v].addPlane(normal, -glm::dot(normal, a), 0.5 * length);
        }
        // An edge used by other than two triangles is open or non-manifold:
        // its vertices never move. Around v, a neighbour w appears once per
        // triangle on the edge vw.
        Big<std::uint32_t> uses(v_.size(), 0);
        for (std::uint32_t v = 0; v < v_.size(); ++v) {
            v_[v].self = static_cast<float>(q_[v].at(glm::dvec3(v_[v].position)));
            const std::uint32_t s = stamp();
            for (const std::uint32_t t : around(v))
                for (const std::uint32_t w : t_[t].v)
                    if (w != v) uses[w] = v_[w].mark == s ? uses[w] + 1 : 1, v_[w].mark = s;
            for (const std::uint32_t t : around(v))
                for (const std::uint32_t w : t_[t].v)
                    if (w != v && uses[w] != 2) v_[v].locked = v_[w].locked = 1;
        }
        for (const Vertex& x : v_) locked_ += x.locked;
        // Every vertex keyed by its cheapest collapse, the heap made at once.
        Big<std::pair<float, std::uint32_t>> keys;
        for (std::uint32_t v = 0; v < v_.size(); ++v)
            if (v_[v].size > 0 && !v_[v].locked) {
                neighbours(v, scratchA_);
                if (cheapest(v, scratchA_)) keys.emplace_back(bucket(v_[v].cost), v);
            }
        heap_ = VertexHeap(v_.size());
        heap_.build(keys);
    }

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
    bool reduceTo(std::size_t target) {
        while (live_ > target) {
            if (heap_.empty()) return false;
            const std::uint32_t u = heap_.top();
            if (valid(u, v_[u].target)) collapse(u, v_[u].target);
            else chooseValid(u);
        }
        return true;
    }

    MeshLevel level() const {
        MeshLevel out;
        out.indices.reserve(live_ * 3);
        for (const Triangle& t : t_)
            if (t.first != kDead)
                for (const std::uint32_t v : t.v) out.indices.push_back(original_[v]);
        // Every removed vertex's distance to the triangle holding it (a
        // vertex still in the level lies on its surface).
        for (const Held& h : held_) out.error = std::max(out.error, h.distance);
        return out;
    }

    /// Numbers the live vertices and triangles anew, in the order they had
    /// (the order every choice breaks its ties by, so the levels come out
    /// the same), with nothing between them: a level's collapses then read
    /// half the memory the one before's did, and fewer cache lines.
    void compact() {
        Big<std::uint32_t> vertexNumber(v_.size(), kNone), triangleNumber(t_.size(), kNone);
        std::uint32_t vertices = 0, triangles = 0;
        for (std::uint32_t v = 0; v < v_.size(); ++v)
            if (!v_[v].removed && v_[v].size > 0) vertexNumber[v] = vertices++;
        for (std::uint32_t t = 0; t < t_.size(); ++t)
            if (t_[t].first != kDead) triangleNumber[t] = triangles++;
        Big<Vertex> v(vertices);
        Big<Quadric> q(vertices);
        Big<std::uint32_t> original(vertices);
        Big<std::uint32_t> pool;
        std::size_t room = 0;
        for (std::uint32_t old = 0; old < v_.size(); ++old)
            if (vertexNumber[old] != kNone) room += v_[old].size + kRoom;
        pool.reserve(2 * room);
        Big<std::pair<float, std::uint32_t>> keys;
        for (std::uint32_t old = 0; old < v_.size(); ++old) {
            const std::uint32_t k = vertexNumber[old];
            if (k == kNone) continue;
            Vertex x = v_[old];
            x.target = x.target == kNone ? kNone : vertexNumber[x.target];
            x.mark = x.near = 0;
            x.start = static_cast<std::uint32_t>(pool.size());
            x.capacity = x.size + kRoom;
            for (const std::uint32_t t : around(old)) pool.push_back(triangleNumber[t]);
            pool.resize(pool.size() + kRoom);
            v[k] = x;
            q[k] = q_[old];
            original[k] = original_[old];
            if (heap_.contains(old)) keys.emplace_back(heap_.cost(old), k);
        }
        Big<Triangle> t;
        t.reserve(triangles);
        for (const Triangle& old : t_)
            if (old.first != kDead) t.push_back({{vertexNumber[old.v[0]], vertexNumber[old.v[1]], vertexNumber[old.v[2]]}, old.first});
        v_ = std::move(v);
        q_ = std::move(q);
        original_ = std::move(original);
        t_ = std::move(t);
        pool_ = std::move(pool);
        reserved_ = room;
        stamp_ = nearStamp_ = 0;
        heap_ = VertexHeap(v_.size());
        heap_.build(keys);
    }

    /// Puts each triangle's held vertices one after another in memory
    /// (collapses walk them triangle by triangle).
    void regroup() {
        Big<Held>& grouped = spareHeld_; // (its memory kept from the last time)
        grouped.clear();
        grouped.reserve(held_.capacity());
        for (Triangle& t : t_) {
            if (t.first == kDead) continue;
            std::uint32_t* link = &t.first;
            for (std::uint32_t h = t.first; h != kNone; h = held_[h].next) {
                *link = static_cast<std::uint32_t>(grouped.size());
                grouped.push_back(held_[h]);
                link = &grouped.back().next;
            }
        }
        std::swap(held_, grouped);
    }

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
    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) {
        out.clear();
        const std::uint32_t s = stamp();
        work_.starVisits += v_[v].size;
        for (const std::uint32_t t : around(v))
            for (const std::uint32_t w : t_[t].v)
                if (w != v && v_[w].mark != s) v_[w].mark = s, out.push_back(w);
    }

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
    bool cheapest(std::uint32_t from, const std::vector<std::uint32_t>& around) {
        Vertex& x = v_[from];
        x.target = kNone;
        for (const std::uint32_t w : around)
            if (const float c = cost(from, w); x.target == kNone || c < x.cost || (c == x.cost && w < x.target)) x.cost = c, x.target = w;
        return x.target != kNone;
    }

    // Keys `from` in the heap by its cheapest collapse onto one of
    // `around` (its neighbours), or takes it out when it may not move.
    void choose(std::uint32_t from, const std::vector<std::uint32_t>& around) {
        if (v_[from].locked || v_[from].removed || !cheapest(from, around)) return heap_.erase(from);
        heap_.set(from, bucket(v_[from].cost));
    }
    void choose(std::uint32_t from) {
        neighbours(from, scratchA_);
        choose(from, scratchA_);
    }

    // As choose(), among the collapses valid now: `from`'s cheapest one was
    // refused. Out of the heap when none is, until a collapse next to it
    // chooses again.
    void chooseValid(std::uint32_t from) {
        neighbours(from, scratchA_);
        std::vector<std::pair<float, std::uint32_t>>& costs = scratchCosts_;
        costs.clear();
        for (const std::uint32_t to : scratchA_) costs.emplace_back(cost(from, to), to);
        std::sort(costs.begin(), costs.end());
        for (const auto& [c, to] : costs)
            if (valid(from, to)) {
                v_[from].target = to;
                v_[from].cost = c;
                return heap_.set(from, bucket(c));
            }
        heap_.erase(from);
    }

    bool valid(std::uint32_t u, std::uint32_t v) {
        if (v_[u].size + v_[v].size > kMostAround + 4) return false; // the two on uv go
        std::size_t shared = 0;
        work_.starVisits += v_[u].size + v_[v].size;
        for (const std::uint32_t t : around(u)) {
            const auto& tri = t_[t].v;
            if (tri[0] == v || tri[1] == v || tri[2] == v) {
                ++shared;
                continue;
            }
            // The triangle with u moved onto v must keep its side.
            std::array<glm::dvec3, 3> before{}, after{};
            for (std::size_t k = 0; k < 3; ++k) {
                before[k] = glm::dvec3(v_[tri[k]].position);
                after[k] = tri[k] == u ? glm::dvec3(v_[v].position) : before[k];
            }
            const glm::dvec3 n0 = glm::cross(before[1] - before[0], before[2] - before[0]);
            const glm::dvec3 n1 = glm::cross(after[1] - after[0], after[2] - after[0]);
            const double l0 = glm::length(n0), l1 = glm::length(n1);
            if (!(l1 > 0.0) || !(l0 > 0.0) || glm::dot(n0, n1) < 0.25 * l0 * l1) return false;
        }
        if (shared != 2) return false;
        // The link condition: u and v share exactly the two vertices
        // opposite their edge, or the collapse pinches the surface.
        const std::uint32_t ofU = stamp();
        for (const std::uint32_t t : around(u))
            for (const std::uint32_t w : t_[t].v)
                if (w != u) v_[w].mark = ofU;
        const std::uint32_t counted = stamp();
        std::size_t common = 0;
        for (const std::uint32_t t : around(v))
            for (const std::uint32_t w : t_[t].v)
                if (w != v && v_[w].mark == ofU) v_[w].mark = counted, ++common;
        return common == 2;
    }

    // Drops triangle t from v's list.
    void drop(std::uint32_t v, std::uint32_t t) {
        std::uint32_t* list = pool_.data() + v_[v].start;
        std::uint32_t* end = list + v_[v].size;
        std::uint32_t* at = std::find(list, end, t);
        if (at == end) return;
        std::copy(at + 1, end, at);
        --v_[v].size;
    }

    // Appends `add` to v's list, moving the list to the pool's end when it
    // has no room (the pool is packed first when it would outgrow what it
    // reserved).
    void append(std::uint32_t v, const std::vector<std::uint32_t>& add) {
        Vertex& x = v_[v];
        const std::size_t size = x.size + add.size();
        if (size > x.capacity) {
            const std::size_t capacity = size + size / 2 + kRoom;
            if (pool_.size() + capacity > pool_.capacity()) pack();
            const std::size_t at = pool_.size();
            pool_.resize(at + capacity);
            std::copy_n(pool_.begin() + static_cast<std::ptrdiff_t>(x.start), x.size, pool_.begin() + static_cast<std::ptrdiff_t>(at));
            reserved_ += capacity - x.capacity;
            x.start = static_cast<std::uint32_t>(at);
            x.capacity = static_cast<std::uint32_t>(capacity);
        }
        std::copy(add.begin(), add.end(), pool_.begin() + static_cast<std::ptrdiff_t>(x.start + x.size));
        x.size = static_cast<std::uint32_t>(size);
    }

    // The lists one after another again, each with its room, in a pool
    // with as much again reserved.
    void pack() {
        Big<std::uint32_t> packed;
        packed.reserve(2 * reserved_);
        for (Vertex& x : v_) {
            const std::size_t at = packed.size();
            packed.insert(packed.end(), pool_.begin() + static_cast<std::ptrdiff_t>(x.start), pool_.begin() + static_cast<std::ptrdiff_t>(x.start + x.size));
            packed.resize(at + x.capacity);
            x.start = static_cast<std::uint32_t>(at);
        }
        pool_ = std::move(packed);
    }

    void collapse(std::uint32_t u, std::uint32_t v) {
        // Every triangle around u changes or goes: u and the removed
        // vertices they held are held again below. The two on uv go (from
        // their third vertex's list and v's too); the others move onto v.
        // v's neighbours before (see the end).
        const std::uint32_t ofV = ++nearStamp_;
        for (const std::uint32_t t : around(v))
            for (const std::uint32_t w : t_[t].v) v_[w].near = ofV;
        changed_.clear();
        changed_.push_back({static_cast<std::uint32_t>(held_.size()), kNone});
        held_.push_back({v_[u].position});
        moved_.clear();
        for (const std::uint32_t t : around(u)) {
            Triangle& tri = t_[t];
            for (std::uint32_t h = tri.first; h != kNone; h = held_[h].next) changed_.push_back({h, t});
            tri.first = kNone;
            if (tri.v[0] == v || tri.v[1] == v || tri.v[2] == v) {
                tri.first = kDead;
                --live_;
                for (const std::uint32_t w : tri.v)
                    if (w != u) drop(w, t);
                continue;
            }
            for (std::uint32_t& w : tri.v)
                if (w == u) w = v;
            moved_.push_back(t);
        }
        reserved_ -= v_[u].capacity;
        v_[u].size = v_[u].capacity = 0;
        append(v, moved_);
        q_[v] += q_[u];
        v_[v].self = static_cast<float>(q_[v].at(glm::dvec3(v_[v].position)));
        v_[u].removed = 1;
        heap_.erase(u);
        hold(u, v);
        // v's quadric grew: its collapses cost otherwise now, and so do its
        // neighbours' onto it. Of those cheapest elsewhere, the ones next to
        // v before only cost more onto it now (a grown quadric is no smaller
        // anywhere); u's, new to v, compare their cheapest with it.
        neighbours(v, scratchB_);
        choose(v, scratchB_);
        for (const std::uint32_t w : scratchB_) {
            if (v_[w].locked) continue;
            if (!heap_.contains(w) || v_[w].target == u || v_[w].target == v) {
                choose(w);
                continue;
            }
            if (v_[w].near == ofV) continue;
            const float c = cost(w, v), was = v_[w].cost;
            if (c < was || (c == was && v < v_[w].target)) v_[w].target = v, v_[w].cost = c, heap_.set(w, bucket(c));
        }
    }

    // Gives each of the collapse's held vertices (changed_) a triangle around
    // v, which now cover what u's and v's did. A vertex is measured against
    // the triangle its old one became (the same one moved; for one that
    // went, the triangle on its edge that stays, through v and its third
    // vertex; for u, one through v) and stays there when that is no farther
    // than it was from the old one, or than the slack; else it goes to the
    // nearest triangle around v.
    void hold(std::uint32_t u, std::uint32_t v) {
        const std::span<const std::uint32_t> list = around(v);
        const float running = kRunningShare * running_;
        std::uint32_t source = kDead, first = kNone;
        for (const auto& [h, from] : changed_) {
            if (from != source) { // changed_ comes triangle by triangle
                source = from;
                first = list.empty() ? kNone : from == kNone ? list.front() : t_[from].first != kDead ? from : through(v, third(from, u, v));
            }
            Held& x = held_[h];
            const double enough = std::max({x.distance, slack_, running}), enough2 = enough * enough;
            double nearest = HUGE_VAL; // squared; none: no triangle left around v (or a NaN position), no finite bound
            std::uint32_t best = kNone;
            if (first != kNone) {
                ++work_.distanceTests;
                if (const double d = squaredDistanceTo(x.position, first); d <= enough2) nearest = d, best = first;
            }
            if (best == kNone)
                for (auto it = list.rbegin(); it != list.rend(); ++it) { // (the triangles moved from u last)
                    ++work_.distanceTests;
                    const double d = squaredDistanceTo(x.position, *it);
                    if (d < nearest) nearest = d, best = *it;
                    if (nearest <= enough2) break;
                }
            // Rounded up: a bound stays one in float.
            x.distance = std::nextafter(static_cast<float>(std::sqrt(nearest)), INFINITY);
            running_ = std::max(running_, x.distance);
            if (best == kNone) continue;
            x.next = t_[best].first;
            t_[best].first = h;
        }
    }

    // The triangle through v and `a` (one of v's), or kNone.
    std::uint32_t through(std::uint32_t v, std::uint32_t a) const {
        for (const std::uint32_t t : around(v))
            if (t_[t].v[0] == a || t_[t].v[1] == a || t_[t].v[2] == a) return t;
        return kNone;
    }

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

} // namespace

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return static_cast<float>(std::sqrt(squaredDistance(p, a, b, c)));
}

std::vector<MeshLevel> meshLevels(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, const MeshLevelOptions& options,
                                  MeshLevelWork* work) {
    std::vector<MeshLevel> levels;
    if (indices.size() / 3 < options.minTriangles) return levels;
    const double reduction = std::clamp(options.reduction, 0.1, 0.9);
    MeshLevelWork counted;
    Collapser collapser(positions, indices, work ? *work : counted);
    std::size_t before = collapser.live();
    while (true) {
        const auto target = static_cast<std::size_t>(static_cast<double>(before) * reduction);
        if (target < options.fewestTriangles) break;
        // Nor below as many triangles as vertices that never move: a disc
        // whose border stays keeps that many less two, and the limit on the
        // triangles around a vertex keeps more. Such a level fails (the rule
        // below) after its costliest collapses, each one re-measuring the
        // hundreds of vertices its coarse triangles hold.
        if (target < collapser.locked()) break;
        const bool reached = collapser.reduceTo(target);

        // A level only where it saves at least a quarter of the one before.
        if (static_cast<double>(collapser.live()) > 0.75 * static_cast<double>(before)) break;
        levels.push_back(collapser.level());
        collapser.setSlack(levels.back().error);
        collapser.compact();
        collapser.regroup();
        before = collapser.live();
        if (!reached) break;
    }
    return levels;
}

} // namespace shadowlab
