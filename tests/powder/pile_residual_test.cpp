//! pile_residual against a hand-worked chain: a cavity of 4 samples whose
//! one moving turn drains the upper two (ranks 2 and 3), so the pile's
//! share maps as F(x) = min(x, 1/2).
//! - The turn leaves piles up to half as they are and cuts the rest to half.
//! - With that turn alone, after any number of turns half is left.
//! - With a still turn beside it (each drawn with probability 1/2), from a
//!   full pile R_T(1) = 1/2 + (1/2)^(T+1): the pile stays full until the
//!   moving turn comes, then half.
//! - A pile of half never reaches the drained samples: it stays.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "powder/pile_residual.h"
#include "powder/sample_bits.h"

namespace {

using fabvdb::powder::expected_pile_residual;
using fabvdb::powder::kPileLevels;
using fabvdb::powder::pile_turn;
using fabvdb::powder::PileTurn;

const std::vector<uint64_t> kUpperTwo{0b1100};

PileTurn upper_two(double start) {
    return pile_turn(start, 4, kUpperTwo, fabvdb::powder::words_before(kUpperTwo));
}

}  // namespace

TEST(PileResidual, TurnCutsThePileAboveTheDrainedSamples) {
    const PileTurn after = upper_two(1.0);
    for (int b = 0; b <= kPileLevels; ++b)
        EXPECT_NEAR(after[size_t(b)], std::min(b, kPileLevels / 2), 1e-12) << "level " << b;
}

TEST(PileResidual, OneMovingTurnLeavesHalf) {
    for (int turns : {1, 2, 9}) EXPECT_NEAR(expected_pile_residual(1.0, {upper_two(1.0)}, 0, turns), 0.5, 1e-12);
}

TEST(PileResidual, StillTurnsDelayTheMovingOne) {
    for (int turns : {0, 1, 2, 5, 9})
        EXPECT_NEAR(expected_pile_residual(1.0, {upper_two(1.0)}, 1, turns), 0.5 + std::pow(0.5, turns + 1), 1e-12)
            << turns << " turns";
}

TEST(PileResidual, ALowPileStays) {
    EXPECT_NEAR(expected_pile_residual(0.5, {upper_two(0.5)}, 3, 9), 0.5, 1e-12);
    EXPECT_NEAR(expected_pile_residual(0.5, {}, 3, 9), 0.5, 1e-12);
}
