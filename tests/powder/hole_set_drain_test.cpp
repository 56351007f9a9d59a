//! hole_set_drain and residual_with on reaches given by hand (bits by rank)
//! over a 3 × 3 × 4 block of 36 samples of 1 mm³ (powder_block.h), later
//! turns −z and +z, 9 of them.
//! - Two holes' first-turn samples join (ranks 0–9 and 5–14: 15 drained,
//!   21 left); a turn drains what either drains.
//! - No hole: the objective keeps all 36 mm³.
//! - Nothing drained as printed, a hole that drains the upper half (ranks
//!   18–35) in turn −z only: the pile is cut to half whenever −z comes, so
//!   R_9 = 1/2 + (1/2)^10 of 36 mm³.
//! - residual_with(drain of one hole, the other's reach) is the objective of both.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "powder/hole_set_drain.h"
#include "powder/sample_bits.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::DrainHole;
using fabvdb::powder::hole_set_drain;
using fabvdb::powder::HoleReach;
using fabvdb::powder::HoleSetDrain;
using fabvdb::powder::residual_with;
using Reaches = std::vector<std::shared_ptr<const HoleReach>>;

constexpr int kLaterTurns = 9;

struct Block : SampleBlock {
    Block() : SampleBlock(3, 3, 4, {{0, 0, -1}, {0, 0, 1}}) {}
};

std::shared_ptr<const HoleReach> reach(const std::vector<uint32_t>& first, const std::vector<uint32_t>& down,
                                       const std::vector<uint32_t>& up) {
    HoleReach result;
    result.first = rank_bits(36, first);
    result.later = {rank_bits(36, down), rank_bits(36, up)};
    result.later_rim.resize(2);
    return std::make_shared<const HoleReach>(result);
}

}  // namespace

TEST(HoleSetDrain, HolesDrainWhatEitherDrains) {
    const Block block;
    const Reaches reaches{reach(ranks(0, 10), {}, ranks(30, 36)), reach(ranks(5, 15), {}, ranks(20, 32))};
    const HoleSetDrain drain = hole_set_drain(block.samples, {DrainHole{}, DrainHole{}}, reaches, kLaterTurns);
    EXPECT_EQ(drain.first[0], rank_bits(36, ranks(0, 15)));
    EXPECT_EQ(drain.retained_first, (std::vector<uint32_t>{21}));
    EXPECT_DOUBLE_EQ(drain.drained_first_volume, 15.0);
    EXPECT_TRUE(drain.later[0][0].empty());
    EXPECT_EQ(drain.later[1][0], rank_bits(36, ranks(20, 36)));
    EXPECT_EQ(drain.later_before[1][0], fabvdb::powder::words_before(drain.later[1][0]));
    EXPECT_EQ(drain.holes.size(), 2u);
    EXPECT_EQ(drain.reaches, reaches);
}

TEST(HoleSetDrain, NoHoleKeepsEverything) {
    const Block block;
    const HoleSetDrain drain = hole_set_drain(block.samples, {}, {}, kLaterTurns);
    EXPECT_EQ(drain.retained_first, (std::vector<uint32_t>{36}));
    EXPECT_EQ(drain.drained_first_volume, 0.0);
    EXPECT_NEAR(drain.residual_per_cavity[0], 36.0, 1e-9);
}

TEST(HoleSetDrain, TheObjectiveCutsThePileWhenTheHoleOpens) {
    const Block block;
    const HoleSetDrain drain =
        hole_set_drain(block.samples, {DrainHole{}}, {reach({}, ranks(18, 36), {})}, kLaterTurns);
    EXPECT_NEAR(drain.residual_per_cavity[0], 36.0 * (0.5 + std::pow(0.5, kLaterTurns + 1)), 1e-9);
}

TEST(HoleSetDrain, ResidualWithOneMoreHoleIsTheObjectiveOfBoth) {
    const Block block;
    const auto first = reach(ranks(0, 10), ranks(30, 36), {}), second = reach(ranks(5, 15), {}, ranks(20, 32));
    const HoleSetDrain one = hole_set_drain(block.samples, {DrainHole{}}, {first}, kLaterTurns);
    const HoleSetDrain both = hole_set_drain(block.samples, {DrainHole{}, DrainHole{}}, {first, second}, kLaterTurns);
    EXPECT_DOUBLE_EQ(residual_with(block.samples, one, *second, kLaterTurns), both.residual_per_cavity[0]);
    EXPECT_LT(both.residual_per_cavity[0], one.residual_per_cavity[0]);
}
