//! The viridis colour map (see colour_map.h).
#include "core/colour_map.h"

#include <algorithm>
#include <cmath>

namespace fabvdb {

namespace {

//! Viridis (van der Walt and Smith, matplotlib, CC0) at 0, 0.1, …, 1.
constexpr double kStops[11][3] = {
    {0.267004, 0.004874, 0.329415}, {0.282623, 0.140926, 0.457517}, {0.253935, 0.265254, 0.529983},
    {0.206756, 0.371758, 0.553117}, {0.163625, 0.471133, 0.558148}, {0.127568, 0.566949, 0.550556},
    {0.134692, 0.658636, 0.517649}, {0.266941, 0.748751, 0.440573}, {0.477504, 0.821444, 0.318195},
    {0.741388, 0.873449, 0.149561}, {0.993248, 0.906157, 0.143936}};

}  // namespace

std::array<uint8_t, 3> viridis(double value) {
    const double t = std::isnan(value) ? 0.0 : 10.0 * std::clamp(value, 0.0, 1.0);
    const int low = std::min(int(t), 9);
    const double f = t - low;
    std::array<uint8_t, 3> rgb{};
    for (int k = 0; k < 3; ++k)
        rgb[size_t(k)] = uint8_t(std::lround(255.0 * ((1.0 - f) * kStops[low][k] + f * kStops[low + 1][k])));
    return rgb;
}

}  // namespace fabvdb
