//! The prediction on reaches given by hand (bits by rank) over a 3 × 3 × 4
//! block of 36 samples of 1 mm³ (powder_block.h), printed with gravity −z,
//! later turns −z and +z (ranks: layer by layer up, resp. down, the block).
//! - A hole that drains the upper half in turn −z: routine (−z) leaves
//!   18 mm³, the lower half; routine (+z) all 36; both routines, their mean
//!   27, 18 and 36 each, and 1 mm³ left on each lower sample, 0.5 on each
//!   upper one.
//! - Powder left slides when the part turns: the first turn drains the
//!   bottom layer; turned −z again, the 27 mm³ left fall a layer and the
//!   hole takes the bottom layer once more (18 stay, in the two layers
//!   above it); turned +z, they fall to the top.
//! - The first turn leaves the lower two layers; a later turn −z takes the
//!   second (9 mm³), which first refills its rim, the empty third layer, so
//!   18 mm³ stay, in the first and third layers.
//! - A rim sample another hole drains is not refilled.
//! - The routines: 64 of the asked length over the set, the same each call.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <vector>

#include "powder/drain_prediction.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::DrainHole;
using fabvdb::powder::hole_set_drain;
using fabvdb::powder::HoleReach;
using fabvdb::powder::HoleSetDrain;
using fabvdb::powder::residual_after_routines;
using fabvdb::powder::Routine;

struct Block : SampleBlock {
    Block() : SampleBlock(3, 3, 4, {{0, 0, -1}, {0, 0, 1}}) {}

    //! What holes that drain these ranks (first turn; later turn −z, and its rim) drain together.
    HoleSetDrain drain(const std::vector<std::vector<uint32_t>>& first, const std::vector<std::vector<uint32_t>>& down,
                       const std::vector<std::vector<uint32_t>>& rim) const {
        std::vector<std::shared_ptr<const HoleReach>> reaches;
        std::vector<DrainHole> holes(first.size());
        for (size_t h = 0; h < first.size(); ++h) {
            HoleReach reach;
            reach.first = rank_bits(36, first[h]);
            reach.later = {rank_bits(36, down[h]), {}};
            reach.later_rim = {rank_bits(36, rim[h]), {}};
            reaches.push_back(std::make_shared<const HoleReach>(reach));
            holes[h].center = {1, 1, -0.5 - double(h)};
        }
        return hole_set_drain(samples, holes, reaches, 9);
    }
    //! The z of the powder samples with powder left on them.
    std::multiset<double> layers(const std::vector<double>& left) const {
        std::multiset<double> z;
        for (size_t a = 0; a < left.size(); ++a)
            if (left[a] > 0) z.insert(powder.position[a][2]);
        return z;
    }
};

}  // namespace

TEST(DrainPrediction, UpperHalfDrainsWhenTheHoleOpens) {
    const Block block;
    const HoleSetDrain drained = block.drain({{}}, {ranks(18, 36)}, {{}});
    std::vector<double> left, per_routine;
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{0}}, nullptr, nullptr)[0], 18.0);
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{1}}, nullptr, nullptr)[0], 36.0);
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{0}, {1}}, &left, &per_routine)[0], 27.0);
    EXPECT_EQ(per_routine, (std::vector<double>{18.0, 36.0}));
    for (size_t a = 0; a < left.size(); ++a)
        EXPECT_DOUBLE_EQ(left[a], block.powder.position[a][2] < 2 ? 1.0 : 0.5) << a;
}

TEST(DrainPrediction, PowderLeftSlidesDownToTheHoleWhenTurned) {
    const Block block;
    // The first turn drains the bottom layer; turned −z again, the 27 left
    // fall a layer, and the hole takes the bottom layer once more.
    const HoleSetDrain drained = block.drain({ranks(0, 9)}, {ranks(0, 9)}, {{}});
    std::vector<double> left;
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{0}}, &left, nullptr)[0], 18.0);
    EXPECT_EQ(block.layers(left), (std::multiset<double>{1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2}));
    // Turned +z, which drains nothing, they fall to the top.
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{1}}, &left, nullptr)[0], 27.0);
    EXPECT_EQ(block.layers(left).count(0.0), 0u);
}

TEST(DrainPrediction, DrainedPowderRefillsTheCratersRimFirst) {
    const Block block;
    // The first turn leaves the lower two layers; turn −z drains the second,
    // whose powder first fills its rim, the empty third layer.
    const HoleSetDrain drained = block.drain({ranks(18, 36)}, {ranks(9, 18)}, {ranks(18, 27)});
    std::vector<double> left;
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{0}}, &left, nullptr)[0], 18.0);
    EXPECT_EQ(block.layers(left), (std::multiset<double>{0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 2, 2, 2, 2, 2, 2, 2, 2}));
}

TEST(DrainPrediction, ARimAnotherHoleDrainsIsNotRefilled) {
    const Block block;
    // The second hole (lower) drains the third layer in turn −z.
    const HoleSetDrain drained =
        block.drain({ranks(18, 36), {}}, {ranks(9, 18), ranks(18, 27)}, {ranks(18, 27), {}});
    EXPECT_DOUBLE_EQ(residual_after_routines(block.samples, drained, {{0}}, nullptr, nullptr)[0], 9.0);
}

TEST(DrainPrediction, RoutinesAreFixed) {
    const std::vector<Routine> routines = fabvdb::powder::prediction_routines(5, 9);
    ASSERT_EQ(routines.size(), 64u);
    std::set<Routine> distinct;
    for (const Routine& routine : routines) {
        ASSERT_EQ(routine.size(), 9u);
        for (uint32_t k : routine) EXPECT_LT(k, 5u);
        distinct.insert(routine);
    }
    EXPECT_GT(distinct.size(), 60u);
    EXPECT_EQ(fabvdb::powder::prediction_routines(5, 9), routines);
}
