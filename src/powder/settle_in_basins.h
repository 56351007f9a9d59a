//! Powder coming to rest in a cavity for one gravity, on the samples of a
//! sublevel forest (sublevel_forest.h): each sample's powder slides down to
//! the local minimum below it (always to the lowest neighbour), then fills
//! the sublevel components from the bottom up. A component holds at most the
//! room of its samples; what it cannot hold spills over its top into the
//! component it joins, and is shared among that component's other branches
//! by the room each has left. Powder that finds no room anywhere leaves.
//! Takes one cavity's samples lowest first and which of them have room (a
//! sample with none is one the powder drains from: it slides on through).
//! Guarantees: every sample ends with 0 to 1 of powder, none where there is
//! no room; the powder kept plus the powder that leaves is the powder given.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "powder/sublevel_forest.h"

namespace fabvdb::powder {

//! Per sample: the local minimum its powder slides to (itself if no
//! neighbour is lower), following `forest`'s order.
std::vector<uint32_t> slide_targets(const std::vector<std::array<uint32_t, 6>>& neighbours, const SublevelForest& forest);

//! Scratch space for settle_in_basins, sized for `sample_count` samples
//! (reused across calls to avoid allocations).
class BasinFill {
public:
    explicit BasinFill(size_t sample_count);

    //! `samples`: one cavity's samples in `forest`'s order; bit i of
    //! `no_room` (empty: none set) says `samples[i]` holds no powder; `fill`
    //! per sample (all samples of the forest), 0 to 1, updated in place.
    //! Returns the powder that leaves.
    double settle(const std::vector<uint32_t>& samples, const SublevelForest& forest,
                  const std::vector<uint32_t>& slide_to, const std::vector<uint64_t>& no_room,
                  std::vector<double>& fill);

private:
    //! Per sample: its own room, the powder that reaches its subtree, the
    //! subtree's room, what its children hold of their own and the room they
    //! have left, and the share of that room the spill fills.
    std::vector<double> own_, water_, room_, kept_, lack_, share_;
};

}  // namespace fabvdb::powder
