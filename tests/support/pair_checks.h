//! A check of triangle pairs found between two merged meshes (the first
//! `split` triangles one mesh, the rest the other, each clean alone): sorted,
//! each pair once, every pair (i, j) with i in the first and j in the second.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace fabvdb::test {

inline void expect_sorted_pairs_across(const std::vector<std::pair<uint32_t, uint32_t>>& pairs, uint32_t split) {
    EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
    EXPECT_EQ(std::adjacent_find(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [i, j] : pairs) {
        EXPECT_LT(i, split);
        EXPECT_GE(j, split);
    }
}

}  // namespace fabvdb::test
