//! The hole search's objective on one cavity (docs/design/drainability.md):
//! the powder left after the first turn is gathered into one pile filling the
//! lowest part of the cavity (by the samples' heights along the next
//! gravity), and the pile's samples that a turn drains leave. So a turn to
//! gravity g maps the pile's share x to F_g(x) ≤ x, and the expected residual
//! share after T turns drawn uniformly from the set is R_T(x), with
//! R_0(x) = x and R_t(x) = mean_g R_{t−1}(F_g(x)), solved on a grid of
//! kPileLevels + 1 pile shares (linear between them).
//! pile_turn costs O(kPileLevels); expected_pile_residual
//! O(T × kPileLevels × turns). Pure functions.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fabvdb::powder {

constexpr int kPileLevels = 48;

//! One turn that drains something: per pile level b = 0 … kPileLevels
//! (the pile of b / kPileLevels of the start), the pile after the turn, in levels.
using PileTurn = std::array<double, kPileLevels + 1>;

//! The turn on a cavity of `count` samples that drains the samples `drained`
//! (bits by rank, lowest first; `before` = words_before(drained)), for piles
//! of up to `start` × count samples.
PileTurn pile_turn(double start, size_t count, const std::vector<uint64_t>& drained,
                   const std::vector<uint32_t>& before);

//! R_T(start) for T = `later_turns`, the turns drawn uniformly from
//! `moving` and `still` more turns that drain nothing (`moving` built with
//! the same `start`).
double expected_pile_residual(double start, const std::vector<PileTurn>& moving, size_t still, int later_turns);

}  // namespace fabvdb::powder
