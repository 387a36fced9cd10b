// Coarser levels of a dense mesh by quadric-ordered half-edge collapses (MeshLevels.h).
#include "core/MeshLevels.h"

#include "core/Adjacency.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <unordered_map>

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

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

struct Candidate {
    double cost;
    std::uint32_t from, to;
    std::uint32_t fromStamp, toStamp;
    bool operator>(const Candidate& o) const { return cost > o.cost; }
};

class Collapser {
public:
    Collapser(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) : p_(positions) {
        const std::size_t n = positions.size();
        weld_ = weldByPosition(positions);
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            const std::array<std::uint32_t, 3> tri{weld_[indices[t]], weld_[indices[t + 1]], weld_[indices[t + 2]]};
            if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
            tris_.push_back(tri);
        }
        alive_.assign(tris_.size(), 1);
        live_ = tris_.size();
        around_.resize(n);
        quadric_.resize(n);
        removed_.assign(n, 0);
        locked_.assign(n, 0);
        stamp_.assign(n, 0);
        into_.resize(n);
        for (std::uint32_t v = 0; v < n; ++v) into_[v] = v;
        std::unordered_map<std::uint64_t, int> uses;
        uses.reserve(tris_.size() * 2);
        for (std::uint32_t t = 0; t < tris_.size(); ++t) {
            const auto& tri = tris_[t];
            const glm::dvec3 a(p_[tri[0]]), b(p_[tri[1]]), c(p_[tri[2]]);
            const glm::dvec3 cross = glm::cross(b - a, c - a);
            const double length = glm::length(cross);
            for (int k = 0; k < 3; ++k) {
                around_[tri[static_cast<std::size_t>(k)]].push_back(t);
                ++uses[edgeKey(tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)])];
            }
            if (length <= 0.0) continue;
            const glm::dvec3 normal = cross / length;
            for (const std::uint32_t v : tri) quadric_[v].addPlane(normal, -glm::dot(normal, a), 0.5 * length);
        }
        for (const auto& [key, count] : uses) {
            if (count == 2) continue;
            locked_[static_cast<std::uint32_t>(key >> 32)] = 1;
            locked_[static_cast<std::uint32_t>(key & 0xffffffffu)] = 1;
        }
        for (const auto& [key, count] : uses) {
            const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
            push(a, b);
            push(b, a);
        }
    }

    std::size_t live() const { return live_; }

    /// Collapses the cheapest valid edges until at most `target` triangles
    /// live; false when no valid collapse is left first.
    bool reduceTo(std::size_t target) {
        while (live_ > target) {
            if (heap_.empty()) return false;
            const Candidate c = heap_.top();
            heap_.pop();
            if (removed_[c.from] || removed_[c.to] || stamp_[c.from] != c.fromStamp || stamp_[c.to] != c.toStamp) continue;
            collapse(c.from, c.to);
        }
        return true;
    }

    MeshLevel level() {
        MeshLevel out;
        for (std::uint32_t t = 0; t < tris_.size(); ++t)
            if (alive_[t]) out.indices.insert(out.indices.end(), tris_[t].begin(), tris_[t].end());
        // Each welded vertex against the live triangles around the vertex it
        // went into, then around the corners of the nearest one found, for as
        // long as that finds a nearer one: a walk over the surface towards
        // the vertex (any triangle's distance bounds the nearest's).
        double error = 0.0;
        for (std::uint32_t v = 0; v < p_.size(); ++v) {
            if (weld_[v] != v || !removed_[v]) continue;
            double nearest = HUGE_VAL;
            // From where the last level's walk ended (those corners may have gone since: where they went).
            std::array<std::uint32_t, 3>& corners = hint_[v];
            if (corners[0] == kNone) corners = {v, v, v};
            for (std::uint32_t& c : corners) c = find(c);
            for (int step = 0; step < 64 && nearest > 0.0; ++step) {
                std::array<std::uint32_t, 3> next = corners;
                for (const std::uint32_t from : corners)
                    for (const std::uint32_t t : around_[from]) {
                        if (!alive_[t]) continue;
                        const auto& tri = tris_[t];
                        const double d = pointTriangleDistance(p_[v], p_[tri[0]], p_[tri[1]], p_[tri[2]]);
                        if (d < nearest) nearest = d, next = tri;
                    }
                if (next == corners) break;
                corners = next;
            }
            error = std::max(error, nearest);
        }
        out.error = static_cast<float>(error);
        return out;
    }

private:
    std::uint32_t find(std::uint32_t v) {
        while (into_[v] != v) {
            into_[v] = into_[into_[v]];
            v = into_[v];
        }
        return v;
    }

    void push(std::uint32_t from, std::uint32_t to) {
        if (locked_[from] || removed_[from] || removed_[to]) return;
        Quadric q = quadric_[from];
        q += quadric_[to];
        heap_.push({std::max(0.0, q.at(glm::dvec3(p_[to]))), from, to, stamp_[from], stamp_[to]});
    }

    // The vertices sharing a live triangle with v.
    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) const {
        out.clear();
        for (const std::uint32_t t : around_[v]) {
            if (!alive_[t]) continue;
            for (const std::uint32_t w : tris_[t])
                if (w != v) out.push_back(w);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    bool valid(std::uint32_t u, std::uint32_t v) {
        int shared = 0;
        for (const std::uint32_t t : around_[u]) {
            if (!alive_[t]) continue;
            const auto& tri = tris_[t];
            if (tri[0] == v || tri[1] == v || tri[2] == v) {
                ++shared;
                continue;
            }
            // The triangle with u moved onto v must keep its side.
            std::array<glm::dvec3, 3> before{}, after{};
            for (std::size_t k = 0; k < 3; ++k) {
                before[k] = glm::dvec3(p_[tri[k]]);
                after[k] = tri[k] == u ? glm::dvec3(p_[v]) : before[k];
            }
            const glm::dvec3 n0 = glm::cross(before[1] - before[0], before[2] - before[0]);
            const glm::dvec3 n1 = glm::cross(after[1] - after[0], after[2] - after[0]);
            const double l0 = glm::length(n0), l1 = glm::length(n1);
            if (!(l1 > 0.0) || !(l0 > 0.0) || glm::dot(n0, n1) < 0.25 * l0 * l1) return false;
        }
        if (shared != 2) return false;
        // The link condition: u and v share exactly the two vertices
        // opposite their edge, or the collapse pinches the surface.
        neighbours(u, scratchU_);
        neighbours(v, scratchV_);
        std::size_t common = 0;
        for (std::size_t i = 0, j = 0; i < scratchU_.size() && j < scratchV_.size();) {
            if (scratchU_[i] < scratchV_[j]) ++i;
            else if (scratchV_[j] < scratchU_[i]) ++j;
            else ++common, ++i, ++j;
        }
        return common == 2;
    }

    void collapse(std::uint32_t u, std::uint32_t v) {
        if (!valid(u, v)) return;
        for (const std::uint32_t t : around_[u]) {
            if (!alive_[t]) continue;
            auto& tri = tris_[t];
            if (tri[0] == v || tri[1] == v || tri[2] == v) {
                alive_[t] = 0;
                --live_;
                continue;
            }
            for (std::uint32_t& w : tri)
                if (w == u) w = v;
            around_[v].push_back(t);
        }
        around_[u].clear();
        std::vector<std::uint32_t>& list = around_[v];
        list.erase(std::remove_if(list.begin(), list.end(), [&](std::uint32_t t) { return !alive_[t]; }), list.end());
        quadric_[v] += quadric_[u];
        removed_[u] = 1;
        into_[u] = v;
        // v's candidates cost otherwise now (its quadric grew): stamp out the
        // old ones and push them again; no other vertex's changed.
        ++stamp_[v];
        neighbours(v, scratchU_);
        for (const std::uint32_t w : scratchU_) {
            push(v, w);
            push(w, v);
        }
    }

    const std::vector<glm::vec3>& p_;
    std::vector<std::uint32_t> weld_;
    std::vector<std::array<std::uint32_t, 3>> tris_;
    std::vector<std::uint8_t> alive_;
    std::size_t live_ = 0;
    std::vector<std::vector<std::uint32_t>> around_;
    std::vector<Quadric> quadric_;
    std::vector<std::uint8_t> removed_, locked_;
    std::vector<std::uint32_t> stamp_, into_;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> heap_;
    std::vector<std::uint32_t> scratchU_, scratchV_;
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<std::array<std::uint32_t, 3>> hint_ = std::vector<std::array<std::uint32_t, 3>>(p_.size(), {kNone, kNone, kNone});
};

} // namespace

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // The closest point by the triangle's Voronoi regions (Ericson, Real-Time Collision Detection, 5.1.5).
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(p - a);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return glm::length(p - b);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return glm::length(p - c);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const float denom = va + vb + vc;
    if (!(std::abs(denom) > 0.0f)) return glm::length(p - a); // degenerate: a vertex
    const float v = vb / denom, w = vc / denom;
    return glm::length(p - (a + ab * v + ac * w));
}

std::vector<MeshLevel> meshLevels(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, const MeshLevelOptions& options) {
    std::vector<MeshLevel> levels;
    if (indices.size() / 3 < options.minTriangles) return levels;
    const double reduction = std::clamp(options.reduction, 0.1, 0.9);
    Collapser collapser(positions, indices);
    std::size_t before = collapser.live();
    while (true) {
        const auto target = static_cast<std::size_t>(static_cast<double>(before) * reduction);
        if (target < options.fewestTriangles) break;
        const bool reached = collapser.reduceTo(target);
        // A level only where it saves at least a quarter of the one before.
        if (static_cast<double>(collapser.live()) > 0.75 * static_cast<double>(before)) break;
        levels.push_back(collapser.level());
        before = collapser.live();
        if (!reached) break;
    }
    return levels;
}

} // namespace shadowlab
