//! The drain heat maps from the powder a prediction leaves: per patch, the
//! powder resting on it at the start (each powder sample's volume on the
//! patch it rests on) and left on it at the end, and the share of the
//! powder resting on it that has left. A patch no powder rests on takes the
//! share of its stand-in patch (the patch its nearest sample rests on), or
//! its cavity's share if none rests there either. The per-patch powder adds
//! up to the cavity volume and to the powder left. O(samples + patches).
#pragma once

#include <cstdint>
#include <vector>

#include "powder/cavity_patches.h"
#include "powder/powder_drop.h"

namespace fabvdb::powder {

struct DrainHeatMap {
    //! Per patch: share drained (negative where a crater's rim fills up), and
    //! the powder resting on it at the start and left on it at the end (mm³).
    std::vector<double> drained_share;
    std::vector<double> initial_per_patch, left_per_patch;
};

//! `left`: per powder sample, the powder left on it (mm³); `stand_in`: per patch.
DrainHeatMap drain_heat_map(const CavityPatches& patches, const PowderSamples& powder, const std::vector<double>& left,
                            const std::vector<uint32_t>& stand_in);

}  // namespace fabvdb::powder
