//! Hand-built powder for the tests of the drainability model's parts: the
//! cells of a box [0, nx) × [0, ny) × [0, nz) but `holes`, at `spacing` from
//! the origin, each a sample of spacing³ mm³ resting on patch 0 of
//! room_patches() (one cavity); orientation flows that carry only their
//! gravity; such a block with its samples per turn (SampleBlock); and a
//! HoleReach's bits from a list of ranks.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "powder/hole_reach.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"
#include "powder/turn_samples.h"
#include "support/hand_patches.h"

namespace fabvdb::test {

using Cell = std::array<int32_t, 3>;

//! The angle of repose the blocks' samples slide at: 35°.
constexpr double kBlockRepose = 0.6108652381980153;

inline powder::PowderSamples powder_block(int nx, int ny, int nz, double spacing, const std::vector<Cell>& holes = {}) {
    powder::PowderSamples powder;
    powder.spacing = spacing;
    powder.sample_volume = spacing * spacing * spacing;
    for (int32_t z = 0; z < nz; ++z)
        for (int32_t y = 0; y < ny; ++y)
            for (int32_t x = 0; x < nx; ++x) {
                if (std::find(holes.begin(), holes.end(), Cell{x, y, z}) != holes.end()) continue;
                powder.cell.push_back({x, y, z});
                powder.position.push_back({spacing * x, spacing * y, spacing * z});
                powder.rest_patch.push_back(kFloor);
            }
    return powder;
}

inline std::vector<powder::OrientationFlow> gravity_flows(const std::vector<Vec3>& gravities) {
    std::vector<powder::OrientationFlow> flows(gravities.size());
    for (size_t k = 0; k < gravities.size(); ++k) flows[k].gravity = gravities[k];
    return flows;
}

//! A block of nx × ny × nz cells 1 mm apart but `holes`, printed with
//! `first` gravity, and its samples per turn for the `later` gravities.
struct SampleBlock {
    powder::CavityPatches patches = room_patches();
    powder::PowderSamples powder;
    std::vector<powder::OrientationFlow> first, turns;
    powder::TurnSamples samples;
    SampleBlock(int nx, int ny, int nz, const std::vector<Vec3>& later, const Vec3& first_gravity = {0, 0, -1},
                const std::vector<Cell>& holes = {})
        : powder(powder_block(nx, ny, nz, 1.0, holes)), first(gravity_flows({first_gravity})), turns(gravity_flows(later)),
          samples(powder::turn_samples(patches, turns, first[0], powder, kBlockRepose)) {}
    //! `samples` points into the block.
    SampleBlock(const SampleBlock&) = delete;
    SampleBlock& operator=(const SampleBlock&) = delete;
};

//! Bits over `count` samples with the given ranks set (empty if none).
inline std::vector<uint64_t> rank_bits(size_t count, const std::vector<uint32_t>& ranks) {
    std::vector<uint64_t> bits;
    if (ranks.empty()) return bits;
    bits.assign((count + 63) / 64, 0);
    for (uint32_t r : ranks) bits[r >> 6] |= uint64_t(1) << (r & 63);
    return bits;
}

//! Ranks from `begin` to `end` − 1.
inline std::vector<uint32_t> ranks(uint32_t begin, uint32_t end) {
    std::vector<uint32_t> result;
    for (uint32_t r = begin; r < end; ++r) result.push_back(r);
    return result;
}

}  // namespace fabvdb::test
