// The edge collapser's set-up and levels (EdgeCollapser.h).
#include "core/EdgeCollapser.h"

#include "core/Adjacency.h"

#include <cmath>

namespace shadowlab::detail {

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

Collapser::Collapser(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, MeshLevelWork& work) : work_(work) {
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

bool Collapser::reduceTo(std::size_t target) {
    while (live_ > target) {
        if (heap_.empty()) return false;
        const std::uint32_t u = heap_.top();
        if (valid(u, v_[u].target)) collapse(u, v_[u].target);
        else chooseValid(u);
    }
    return true;
}

MeshLevel Collapser::level() const {
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

void Collapser::compact() {
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

void Collapser::regroup() {
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

} // namespace shadowlab::detail
