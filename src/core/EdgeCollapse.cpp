// One collapse of the edge collapser and its bookkeeping: validity, the
// neighbours' new costs, the triangle lists, the removed vertices held
// (EdgeCollapser.h).
#include "core/EdgeCollapser.h"

#include <cmath>

namespace shadowlab::detail {

void Collapser::neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) {
    out.clear();
    const std::uint32_t s = stamp();
    work_.starVisits += v_[v].size;
    for (const std::uint32_t t : around(v))
        for (const std::uint32_t w : t_[t].v)
            if (w != v && v_[w].mark != s) v_[w].mark = s, out.push_back(w);
}

bool Collapser::cheapest(std::uint32_t from, const std::vector<std::uint32_t>& around) {
    Vertex& x = v_[from];
    x.target = kNone;
    for (const std::uint32_t w : around)
        if (const float c = cost(from, w); x.target == kNone || c < x.cost || (c == x.cost && w < x.target)) x.cost = c, x.target = w;
    return x.target != kNone;
}

void Collapser::choose(std::uint32_t from, const std::vector<std::uint32_t>& around) {
    if (v_[from].locked || v_[from].removed || !cheapest(from, around)) return heap_.erase(from);
    heap_.set(from, bucket(v_[from].cost));
}

void Collapser::choose(std::uint32_t from) {
    neighbours(from, scratchA_);
    choose(from, scratchA_);
}

void Collapser::chooseValid(std::uint32_t from) {
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

bool Collapser::valid(std::uint32_t u, std::uint32_t v) {
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

void Collapser::drop(std::uint32_t v, std::uint32_t t) {
    std::uint32_t* list = pool_.data() + v_[v].start;
    std::uint32_t* end = list + v_[v].size;
    std::uint32_t* at = std::find(list, end, t);
    if (at == end) return;
    std::copy(at + 1, end, at);
    --v_[v].size;
}

void Collapser::append(std::uint32_t v, const std::vector<std::uint32_t>& add) {
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

void Collapser::pack() {
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

void Collapser::collapse(std::uint32_t u, std::uint32_t v) {
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

void Collapser::hold(std::uint32_t u, std::uint32_t v) {
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

std::uint32_t Collapser::through(std::uint32_t v, std::uint32_t a) const {
    for (const std::uint32_t t : around(v))
        if (t_[t].v[0] == a || t_[t].v[1] == a || t_[t].v[2] == a) return t;
    return kNone;
}

} // namespace shadowlab::detail
