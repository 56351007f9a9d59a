//! Inside runs of a column and the run a part keeps (see column_runs.h).
#include "volume/column_runs.h"

#include <openvdb/tools/Interpolation.h>

namespace fabvdb::volume {

std::vector<Run> inside_runs(const float* column, size_t nz) {
    std::vector<Run> runs;
    for (size_t k = 0; k < nz;) {
        if (column[k] >= 0) {
            ++k;
            continue;
        }
        const size_t start = k;
        while (k < nz && column[k] < 0) ++k;
        runs.push_back({start, k});
    }
    return runs;
}

double zero_crossing(const float* column, size_t k) {
    const double a = column[k], b = column[k + 1];
    return double(k) + a / (a - b);
}

SurfaceCrossings::SurfaceCrossings(const openvdb::math::Transform& block, const openvdb::Coord& origin,
                                   const openvdb::FloatGrid* surface)
    : block_(block),
      origin_(origin),
      surface_(surface) {
    if (surface) accessor_.emplace(surface->getConstAccessor());
}

size_t SurfaceCrossings::count(int i, int j, const Run& run) const {
    if (!surface_) return 0;
    size_t changes = 0;
    bool was_inside = false;
    for (size_t k = run.start - 1; k <= run.end; ++k) {
        const openvdb::Vec3d world =
            block_.indexToWorld(openvdb::Vec3d(origin_.x() + i, origin_.y() + j, double(origin_.z()) + double(k)));
        const bool inside = openvdb::tools::BoxSampler::sample(*accessor_, surface_->worldToIndex(world)) < 0;
        if (k > run.start - 1 && inside != was_inside) ++changes;
        was_inside = inside;
    }
    return changes;
}

size_t kept_run(const std::vector<Run>& runs, const SurfaceCrossings& crossings, int i, int j) {
    size_t best = 0, best_crossings = 0;
    for (size_t r = 0; r < runs.size(); ++r) {
        const size_t run_crossings = runs.size() > 1 ? crossings.count(i, j, runs[r]) : 0;
        const size_t length = runs[r].end - runs[r].start, best_length = runs[best].end - runs[best].start;
        if (r == 0 || run_crossings > best_crossings || (run_crossings == best_crossings && length > best_length))
            best = r, best_crossings = run_crossings;
    }
    return best;
}

}  // namespace fabvdb::volume
