//! Disjoint sets (union-find) over the indices 0 .. size − 1, shared by every
//! pass that gathers connected pieces (shells, patches, regions, elements,
//! cups). A set is named by its root, always its least index, so the names
//! do not depend on the order the unions came in. Finds halve the path.
//! Header-only; amortised almost constant time per operation.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace fabvdb {

class DisjointSets {
public:
    explicit DisjointSets(size_t count = 0) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0u); }

    //! A new set holding only the next index; returns it.
    uint32_t add() {
        parent_.push_back(uint32_t(parent_.size()));
        return parent_.back();
    }

    //! The root of x's set.
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }

    //! Joins the sets of a and b; returns the root of the joined set.
    uint32_t unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return a;
        if (b < a) std::swap(a, b);
        parent_[b] = a;
        return a;
    }

    size_t size() const { return parent_.size(); }

private:
    std::vector<uint32_t> parent_;
};

}  // namespace fabvdb
