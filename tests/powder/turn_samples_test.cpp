//! turn_samples on hand-built powder (powder_block.h): a 3 × 3 × 4 block of
//! cells 1 mm apart, printed with gravity −z, later turns −z and +z.
//! - A few samples: both grids keep all (stride 1), one cavity of 36.
//! - Ranks go up the block along −gravity, in sample order within a layer
//!   (the later counts as the higher). The chain from the first sample of
//!   the bottom layer holds every sample (all reach it going down or
//!   level); from the first of the top layer the top layer's nine, from its
//!   seventh the three after it.
//! - Floors: halfway below the bottom layer, and beside a side wall's
//!   lower edge; none inside.
//! - Links: the 26 around an inner sample all exist; a diagonal step whose
//!   face steps are both missing is no link; nor is a step into another
//!   cavity (two layers on either side of a wall thinner than the grid).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "powder/turn_samples.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::kNoSample;
using fabvdb::powder::SampleChains;
using fabvdb::powder::TurnSamples;
using fabvdb::powder::turn_samples;

//! The grid sample at `cell` (the block's samples are in x, y, z order).
uint32_t at(const Cell& cell) { return uint32_t(cell[0] + 3 * cell[1] + 9 * cell[2]); }

//! The ranks of the chain from grid sample `a`.
std::set<uint32_t> chain(const SampleChains& chains, uint32_t a) {
    std::set<uint32_t> visited;
    for (; a != kNoSample; a = chains.after_run[a])
        for (uint32_t r = chains.rank[a]; r < chains.run_end[a]; ++r) EXPECT_TRUE(visited.insert(r).second);
    return visited;
}

struct Block : SampleBlock {
    Block() : SampleBlock(3, 3, 4, {{0, 0, -1}, {0, 0, 1}}) {}
};

}  // namespace

TEST(TurnSamples, FewSamplesKeepEveryOneInOneCavity) {
    const Block block;
    const TurnSamples& s = block.samples;
    EXPECT_EQ(s.first_grid.size(), 36u);
    EXPECT_EQ(s.later_grid.size(), 36u);
    EXPECT_EQ(s.first_count, (std::vector<uint32_t>{36}));
    EXPECT_EQ(s.later_count, (std::vector<uint32_t>{36}));
    EXPECT_EQ(s.later_gravity.size(), 2u);
    for (size_t i = 0; i < 36; ++i) EXPECT_EQ(s.later_local[s.later_chains[0].by_rank[0][i]], i);
}

TEST(TurnSamples, RanksRiseAgainstGravityAndChainsReachDown) {
    const Block block;
    const TurnSamples& s = block.samples;
    const auto& position = block.powder.position;
    for (size_t r = 1; r < 36; ++r) {
        EXPECT_LE(position[s.first_chains.by_rank[0][r - 1]][2], position[s.first_chains.by_rank[0][r]][2]);
        EXPECT_GE(position[s.later_chains[1].by_rank[0][r - 1]][2], position[s.later_chains[1].by_rank[0][r]][2]);
    }
    EXPECT_EQ(chain(s.first_chains, at({0, 0, 0})).size(), 36u);
    EXPECT_EQ(chain(s.first_chains, at({0, 0, 3})), (std::set<uint32_t>{27, 28, 29, 30, 31, 32, 33, 34, 35}));
    EXPECT_EQ(chain(s.first_chains, at({0, 2, 3})), (std::set<uint32_t>{33, 34, 35}));
    // Under +z the top is the bottom.
    EXPECT_EQ(chain(s.later_chains[1], at({0, 0, 3})).size(), 36u);
    EXPECT_EQ(chain(s.later_chains[1], at({0, 0, 0})).size(), 9u);
    for (uint32_t a = 0; a < 36; ++a) EXPECT_EQ(s.first_rank[a], s.first_chains.rank[a]);
}

TEST(TurnSamples, FloorsLieHalfwayToTheEmptyCellBelow) {
    const Block block;
    const auto& relief = block.samples.later_relief[0];
    EXPECT_FLOAT_EQ(relief.height[at({1, 1, 2})], 2.0f);
    EXPECT_FLOAT_EQ(relief.floor[at({1, 1, 0})], -0.5f);
    EXPECT_FLOAT_EQ(relief.floor[at({0, 1, 1})], 0.5f);
    EXPECT_TRUE(std::isinf(relief.floor[at({1, 1, 1})]) && relief.floor[at({1, 1, 1})] < 0);
    // Under +z the top layer rests on the ceiling.
    EXPECT_FLOAT_EQ(block.samples.later_relief[1].floor[at({1, 1, 3})], -3.5f);
}

TEST(TurnSamples, DiagonalLinksNeverCutAWallsEdge) {
    const Block block;
    const auto& inner = block.samples.later_links[at({1, 1, 1})];
    EXPECT_EQ(std::count(inner.begin(), inner.end(), kNoSample), 0);
    const auto& corner = block.samples.later_links[at({0, 0, 0})];
    EXPECT_EQ(std::count_if(corner.begin(), corner.end(), [](uint32_t c) { return c != kNoSample; }), 7);
    // A flat 3 × 3 layer without (1, 0) and (0, 1): from (0, 0) to (1, 1) only diagonally.
    const auto patches = room_patches();
    const auto powder = powder_block(3, 3, 1, 1.0, {{1, 0, 0}, {0, 1, 0}});
    const auto turns = gravity_flows({{0, 0, -1}});
    const TurnSamples flat = turn_samples(patches, turns, turns[0], powder, kBlockRepose);
    const auto& links = flat.later_links[0];  // the sample at (0, 0, 0)
    EXPECT_EQ(std::count_if(links.begin(), links.end(), [](uint32_t c) { return c != kNoSample; }), 0);
}

TEST(TurnSamples, NoLinkCrossesIntoAnotherCavity) {
    // A 3 × 3 × 2 block: the bottom layer rests on the floor (cavity 0), the
    // top layer on the ceiling, here made a second cavity.
    auto patches = room_patches();
    patches.cavity[kCeiling] = 1;
    patches.cavity_count = 2;
    auto powder = powder_block(3, 3, 2, 1.0);
    for (size_t i = 9; i < 18; ++i) powder.rest_patch[i] = kCeiling;
    const auto turns = gravity_flows({{0, 0, -1}});
    const TurnSamples two = turn_samples(patches, turns, turns[0], powder, kBlockRepose);
    for (uint32_t a = 0; a < 18; ++a) {
        size_t linked = 0;
        for (uint32_t c : two.later_links[a]) {
            if (c == kNoSample) continue;
            ++linked;
            EXPECT_EQ(two.later_cavity[c], two.later_cavity[a]) << "sample " << a;
        }
        // Within its own 3 × 3 layer: 8 around the centre, 3 or 5 at the edge.
        const uint32_t in_layer = a % 9;
        EXPECT_EQ(linked, in_layer == 4 ? 8u : (in_layer % 2 == 0 ? 3u : 5u)) << "sample " << a;
    }
}
