//! Grid lines placed clear of a set of coordinates (see clear_grid_origin.h).
#include "surface/clear_grid_origin.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace fabvdb::surface {

double clear_grid_origin(const std::vector<double>& coordinates, double start, double step) {
    if (!(step > 0) || !std::isfinite(step) || !std::isfinite(start))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "grid lines need a finite start and a positive step");
    if (coordinates.empty()) return start;
    // The lines start − s + i·step pass through c exactly when s ≡ start − c
    // (mod step): those shifts s in [0, step) are the ones to keep away from.
    std::vector<double> blocked;
    blocked.reserve(coordinates.size());
    for (double c : coordinates) {
        if (!std::isfinite(c)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "grid lines cannot clear a non-finite coordinate");
        double shift = std::fmod(start - c, step);
        if (shift < 0) shift += step;
        blocked.push_back(shift < step ? shift : 0.0);
    }
    std::sort(blocked.begin(), blocked.end());
    // The gap that wraps around from the last blocked shift to the first.
    double widest = blocked.front() + step - blocked.back();
    double shift = blocked.back() + 0.5 * widest;
    for (size_t k = 1; k < blocked.size(); ++k) {
        const double gap = blocked[k] - blocked[k - 1];
        if (gap > widest) {
            widest = gap;
            shift = blocked[k - 1] + 0.5 * gap;
        }
    }
    if (shift >= step) shift -= step;
    return start - shift;
}

}  // namespace fabvdb::surface
