#pragma once
// A min-heap of vertex numbers keyed by a cost, that knows where each
// vertex is in it, so that a vertex's key can change in place and a vertex
// can leave from anywhere (core/MeshLevels.cpp: each vertex keyed by its
// cheapest collapse). At most one entry a vertex; ties go to the lower
// vertex number, a total order, so the order things come out in does not
// depend on the order they went in. GPU-free.
#include "core/LargePages.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace shadowlab {

class VertexHeap {
public:
    /// For vertices 0..vertices-1; empty.
    explicit VertexHeap(std::size_t vertices) : place_(vertices, kOut) {}

    bool empty() const { return heap_.empty(); }
    /// The vertex with the lowest cost (not empty()).
    std::uint32_t top() const { return heap_.front().vertex; }
    bool contains(std::uint32_t v) const { return place_[v] != kOut; }
    /// v's cost (contains(v)).
    float cost(std::uint32_t v) const { return heap_[place_[v]].cost; }

    /// Puts each (cost, vertex) of `entries` in at once, into an empty heap
    /// (faster than set() one by one: linear, not n log n).
    template <class Entries>
    void build(const Entries& entries) {
        heap_.clear();
        for (const auto& [cost, v] : entries) {
            place_[v] = static_cast<std::uint32_t>(heap_.size());
            heap_.push_back({cost, v});
        }
        for (std::size_t i = heap_.size() / kArity + 1; i-- > 0;)
            if (i < heap_.size()) down(i);
    }

    /// Puts `v` in at `cost`, or moves it there.
    void set(std::uint32_t v, float cost) {
        std::size_t i = place_[v];
        if (i == kOut) {
            i = heap_.size();
            heap_.push_back({cost, v});
        } else {
            heap_[i].cost = cost;
        }
        down(up(i));
    }

    /// Takes `v` out, if it is in.
    void erase(std::uint32_t v) {
        const std::size_t i = place_[v];
        if (i == kOut) return;
        place_[v] = kOut;
        const Entry last = heap_.back();
        heap_.pop_back();
        if (i == heap_.size()) return;
        heap_[i] = last;
        down(up(i));
    }

private:
    static constexpr std::uint32_t kOut = 0xffffffffu;
    struct Entry {
        float cost;
        std::uint32_t vertex;
    };
    static bool before(const Entry& a, const Entry& b) { return a.cost < b.cost || (a.cost == b.cost && a.vertex < b.vertex); }

    void put(std::size_t i, const Entry& e) {
        heap_[i] = e;
        place_[e.vertex] = static_cast<std::uint32_t>(i);
    }
    // Four children a node (entry i's are 4i + 1..4i + 4, in one cache
    // line): half the levels of a binary heap, so fewer misses a change.
    static constexpr std::size_t kArity = 4;

    // Moves the entry at i towards the root while it goes before its parent; returns where it ends.
    std::size_t up(std::size_t i) {
        const Entry e = heap_[i];
        for (; i > 0 && before(e, heap_[(i - 1) / kArity]); i = (i - 1) / kArity) put(i, heap_[(i - 1) / kArity]);
        put(i, e);
        return i;
    }
    // Moves the entry at i towards the leaves while a child goes before it.
    void down(std::size_t i) {
        const Entry e = heap_[i];
        for (std::size_t first = kArity * i + 1; first < heap_.size(); first = kArity * i + 1) {
            std::size_t child = first;
            for (std::size_t c = first + 1; c < std::min(first + kArity, heap_.size()); ++c)
                if (before(heap_[c], heap_[child])) child = c;
            if (!before(heap_[child], e)) break;
            put(i, heap_[child]);
            i = child;
        }
        put(i, e);
    }

    std::vector<Entry, LargePages<Entry>> heap_;
    std::vector<std::uint32_t, LargePages<std::uint32_t>> place_; ///< per vertex, its index in heap_, or kOut
};

} // namespace shadowlab
