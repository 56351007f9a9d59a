//! The coarse sample grid (see sample_grid.h).
#include "powder/sample_grid.h"

#include <cmath>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

uint64_t key(int64_t x, int64_t y, int64_t z) {
    const uint64_t offset = uint64_t(1) << 20;
    return ((uint64_t(x) + offset) << 42) | ((uint64_t(y) + offset) << 21) | (uint64_t(z) + offset);
}

}  // namespace

SampleGrid sample_grid(const PowderSamples& powder, int stride) {
    if (stride < 1) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the sample grid stride must be at least 1");
    SampleGrid grid;
    grid.stride = stride;
    grid.powder_ = &powder;
    for (uint32_t s = 0; s < powder.cell.size(); ++s) {
        const auto& c = powder.cell[s];
        if (c[0] % stride || c[1] % stride || c[2] % stride) continue;
        grid.index_.emplace(key(c[0], c[1], c[2]), uint32_t(grid.sample.size()));
        grid.sample.push_back(s);
    }
    const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    grid.neighbours.resize(grid.sample.size());
    for (size_t k = 0; k < grid.sample.size(); ++k) {
        const auto& c = powder.cell[grid.sample[k]];
        for (int d = 0; d < 6; ++d) {
            const auto found =
                grid.index_.find(key(c[0] + stride * step[d][0], c[1] + stride * step[d][1], c[2] + stride * step[d][2]));
            grid.neighbours[k][size_t(d)] = found == grid.index_.end() ? kNoSample : found->second;
        }
    }
    return grid;
}

uint32_t SampleGrid::nearest(const Vec3& point) const {
    const double h = powder_->spacing;
    int64_t cell[3];
    for (int k = 0; k < 3; ++k) {
        const double q = (point[k] - powder_->origin[k]) / h;
        cell[k] = int64_t(std::llround(q / stride)) * stride;
    }
    uint32_t best = kNoSample;
    double best_distance = HUGE_VAL;
    for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz) {
                const auto found = index_.find(key(cell[0] + dx * stride, cell[1] + dy * stride, cell[2] + dz * stride));
                if (found == index_.end()) continue;
                const Vec3& p = powder_->position[sample[found->second]];
                const double d = (p[0] - point[0]) * (p[0] - point[0]) + (p[1] - point[1]) * (p[1] - point[1]) +
                                 (p[2] - point[2]) * (p[2] - point[2]);
                if (d < best_distance) {
                    best_distance = d;
                    best = found->second;
                }
            }
    return best;
}

}  // namespace fabvdb::powder
