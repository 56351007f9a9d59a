//! hole_reach on hand-built powder (powder_block.h): a 9 × 9 × 6 block of
//! cells 1 mm apart (x, y in 0 … 8, z in 0 … 5), a hole of diameter 2 under
//! its corner (centre (0, 0, −0.5)) drilled straight down, θ_r = 45°
//! (tan θ_r = 1). All the powder reaches the mouth's sample, the first of
//! the bottom layer, going down or level, so what drains is what lies above
//! the crater's cone: with the mouth's radius 1, a sample at height z drains
//! when its distance across from the axis is at most z + 1.5: per layer 4,
//! 8, 13, 22, 30, 41 samples.
//! - As printed (gravity −z), and in a later turn −z by the cone, exactly those.
//! - A later turn +z (the hole points up) drains nothing.
//! - By the surface of repose: never more than by the cone, everything over
//!   the mouth; the rim it buries does not drain; as printed (the same
//!   gravity as the later turn −z) the same samples.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "powder/hole_reach.h"
#include "powder/sample_bits.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::Crater;
using fabvdb::powder::DrainHole;
using fabvdb::powder::hole_reach;
using fabvdb::powder::HoleReach;

constexpr double kRepose = M_PI / 4;

//! The powder samples (indices) a turn's bits name.
std::set<uint32_t> named(const std::vector<uint64_t>& bits, const std::vector<uint32_t>& by_rank) {
    std::set<uint32_t> samples;
    for (size_t r = 0; r < by_rank.size(); ++r)
        if (!bits.empty() && fabvdb::powder::bit(bits, r)) samples.insert(by_rank[r]);
    return samples;
}

struct Block : SampleBlock {
    DrainHole hole;
    Block() : SampleBlock(9, 9, 6, {{0, 0, -1}, {0, 0, 1}}) {
        hole.center = {0, 0, -0.5};
        hole.axis = {0, 0, -1};
        hole.diameter = 2.0;
        hole.through = 2.0;
        hole.depth = 4.0;
    }
    //! The samples above the cone, by hand.
    std::set<uint32_t> above_cone() const {
        std::set<uint32_t> result;
        for (uint32_t a = 0; a < powder.position.size(); ++a) {
            const auto& p = powder.position[a];
            if (std::hypot(p[0], p[1]) <= p[2] + 1.5) result.insert(a);
        }
        return result;
    }
};

}  // namespace

TEST(HoleReach, ByTheConeDrainsWhatLiesAboveIt) {
    const Block block;
    const HoleReach reach = hole_reach(block.samples, block.hole, Crater::cone, kRepose);
    const std::set<uint32_t> expected = block.above_cone();
    ASSERT_EQ(expected.size(), 4u + 8u + 13u + 22u + 30u + 41u);
    EXPECT_EQ(reach.cavity, 0u);
    EXPECT_EQ(named(reach.first, block.samples.first_chains.by_rank[0]), expected);
    ASSERT_EQ(reach.later.size(), 2u);
    EXPECT_EQ(named(reach.later[0], block.samples.later_chains[0].by_rank[0]), expected);
    EXPECT_TRUE(reach.later[1].empty());
    EXPECT_TRUE(reach.later_rim[0].empty());
}

TEST(HoleReach, BySurfaceNeverMoreThanByTheCone) {
    const Block block;
    const HoleReach reach = hole_reach(block.samples, block.hole, Crater::surface, kRepose);
    const auto& by_rank = block.samples.later_chains[0].by_rank[0];
    const std::set<uint32_t> surface = named(reach.later[0], by_rank), cone = block.above_cone();
    EXPECT_FALSE(surface.empty());
    for (uint32_t a : surface) EXPECT_TRUE(cone.count(a)) << a;
    // Straight over the mouth (across ≤ 1) everything drains.
    for (uint32_t a = 0; a < block.powder.position.size(); ++a) {
        const auto& p = block.powder.position[a];
        if (std::hypot(p[0], p[1]) <= 1.0) EXPECT_TRUE(surface.count(a)) << a;
    }
    for (uint32_t a : named(reach.later_rim[0], by_rank)) EXPECT_FALSE(surface.count(a)) << a;
    EXPECT_TRUE(reach.later[1].empty());
    // As printed, gravity −z as in later turn 0: the same surface.
    EXPECT_EQ(named(reach.first, block.samples.first_chains.by_rank[0]), surface);
}
