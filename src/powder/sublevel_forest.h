//! Where powder can flow without climbing: the merge forest of a cavity's
//! sublevel sets. Takes a graph of samples (a SampleGrid's neighbours) and a
//! height per sample; adds the samples from the lowest up, and each sample
//! becomes the parent of the components its lower neighbours belonged to.
//! Guarantees: the ancestors of sample m (m included) are exactly the samples
//! s joined to m through samples no higher than s — the powder at s that can
//! reach m going only down or level; a parent is never lower than its child.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace fabvdb::powder {

struct SublevelForest {
    //! Samples by increasing height.
    std::vector<uint32_t> order;
    //! Position of each sample in `order`.
    std::vector<uint32_t> rank;
    //! The sample whose arrival joined this one's component; itself at a root.
    std::vector<uint32_t> parent;
};

SublevelForest sublevel_forest(const std::vector<std::array<uint32_t, 6>>& neighbours, const std::vector<float>& height);

}  // namespace fabvdb::powder
