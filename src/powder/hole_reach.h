//! What one drain hole drains alone, turn by turn (docs/design/drainability.md):
//! in each turn, the first (as printed) and every later one, only powder
//! that reaches the mouth without climbing (the ancestors, in the turn's
//! sublevel forest, of the sample nearest the hole), and of it
//! - by Crater::surface the powder above the surface of repose rising with
//!   slope θ_r from the crater through the cavity (never below a floor,
//!   plugged where it fills a passage), found on the later turns' grid (a
//!   first-turn sample drains with the later-grid sample nearest it);
//! - by Crater::cone the powder above the crater's cone (more, and far
//!   cheaper to find).
//! Nothing drains through a hole whose tunnel does not pass powder for that
//! gravity. Thread-safe; costs one walk up a chain per turn (by the cone),
//! or one Dijkstra over the chain's samples per turn (by the surface), the
//! turns in parallel.
#pragma once

#include <cstdint>
#include <vector>

#include "powder/drain_hole.h"
#include "powder/turn_samples.h"

namespace fabvdb::powder {

//! What drains: powder above the surface of repose (the prediction), or
//! above the crater's cone (the hole search's objective).
enum class Crater { surface, cone };

//! Bits over the hole's cavity's samples by rank (sample_bits.h).
struct HoleReach {
    uint32_t cavity = 0;
    //! The first-turn samples it drains (empty where it drains nothing).
    std::vector<uint64_t> first;
    //! Per later turn, the later-turn samples it drains (empty: none).
    std::vector<std::vector<uint64_t>> later;
    //! Per later turn, the samples its surface of repose reaches and
    //! buries (the crater's rim), by Crater::surface only.
    std::vector<std::vector<uint64_t>> later_rim;
};

HoleReach hole_reach(const TurnSamples& samples, const DrainHole& hole, Crater crater, double repose_radians);

}  // namespace fabvdb::powder
