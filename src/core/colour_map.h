//! The viridis colour map (perceptually uniform, readable in grey and by
//! colour-blind readers): a value in [0, 1] (clamped) to 8-bit RGB, by
//! linear interpolation between the map's eleven stops at steps of 0.1.
#pragma once

#include <array>
#include <cstdint>

namespace fabvdb {

std::array<uint8_t, 3> viridis(double value);

}  // namespace fabvdb
