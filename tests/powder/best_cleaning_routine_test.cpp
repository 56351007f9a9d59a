//! best_cleaning_routine on reaches given by hand over a 3 × 3 × 4 block of
//! 36 samples (powder_block.h), printed with gravity −z:
//! - Later turns −z (drains nothing), +x (drains everything): the first
//!   turn is +x; after it every turn leaves nothing, and the tie goes to
//!   the smallest tilt: +x again. A random routine that leaves as little
//!   does not replace it.
//! - Nothing drains anywhere: every turn ties, and the smallest tilt from
//!   as printed is to stay at −z.
//! - Turns −z (nothing), +x (the upper half) and +y (the lower half): the
//!   greedy routine of two turns takes +x (tied with +y, the first of equal
//!   tilt) then +y; worse random routines do not replace it.
//! - Cancelled: Error(CANCELLED), no routine.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <vector>

#include "core/error.h"
#include "powder/best_cleaning_routine.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::Vec3;
using fabvdb::powder::best_cleaning_routine;
using fabvdb::powder::HoleReach;
using fabvdb::powder::HoleSetDrain;
using fabvdb::powder::Routine;

struct Block : SampleBlock {
    explicit Block(const std::vector<Vec3>& gravities) : SampleBlock(3, 3, 4, gravities) {}

    //! One hole that drains, in each later turn, the samples for which `drains(turn, position)` holds.
    template <class Drains>
    HoleSetDrain drain(Drains drains) const {
        HoleReach reach;
        for (size_t k = 0; k < turns.size(); ++k) {
            std::vector<uint32_t> drained;
            const auto& by_rank = samples.later_chains[k].by_rank[0];
            for (uint32_t r = 0; r < by_rank.size(); ++r)
                if (drains(k, powder.position[by_rank[r]])) drained.push_back(r);
            reach.later.push_back(rank_bits(36, drained));
            reach.later_rim.emplace_back();
        }
        return fabvdb::powder::hole_set_drain(samples, {fabvdb::powder::DrainHole{}},
                                              {std::make_shared<const HoleReach>(reach)}, 9);
    }
};

}  // namespace

TEST(BestCleaningRoutine, TurnsToTheHoleAndStays) {
    const Block block({{0, 0, -1}, {1, 0, 0}});
    const HoleSetDrain drained = block.drain([](size_t k, const Vec3&) { return k == 1; });
    EXPECT_EQ(best_cleaning_routine(block.samples, drained, 2, {{0, 0}, {0, 1}}, fabvdb::Progress()), (Routine{1, 1}));
}

TEST(BestCleaningRoutine, NothingDrainsSoNothingTurns) {
    const Block block({{1, 0, 0}, {0, 0, -1}, {0, 0, 1}});
    const HoleSetDrain drained = block.drain([](size_t, const Vec3&) { return false; });
    EXPECT_EQ(best_cleaning_routine(block.samples, drained, 3, {}, fabvdb::Progress()), (Routine{1, 1, 1}));
}

TEST(BestCleaningRoutine, TakesTheTurnsThatDrainTheMost) {
    const Block block({{0, 0, -1}, {1, 0, 0}, {0, 1, 0}});
    const HoleSetDrain drained =
        block.drain([](size_t k, const Vec3& p) { return (k == 1 && p[2] >= 2) || (k == 2 && p[2] < 2); });
    EXPECT_EQ(best_cleaning_routine(block.samples, drained, 2, {{0, 0}, {0, 2}}, fabvdb::Progress()), (Routine{1, 2}));
}

TEST(BestCleaningRoutine, StopsWhenCancelled) {
    const Block block({{0, 0, -1}, {1, 0, 0}});
    const HoleSetDrain drained = block.drain([](size_t k, const Vec3&) { return k == 1; });
    std::atomic<bool> cancel{true};
    const fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        best_cleaning_routine(block.samples, drained, 2, {}, progress);
        ADD_FAILURE() << "no error";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
