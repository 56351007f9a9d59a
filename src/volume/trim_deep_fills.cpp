//! Fill or trim, per column (see trim_deep_fills.h).
#include "volume/trim_deep_fills.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include "volume/column_runs.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

namespace {

using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

//! The block's part as a true signed distance out to `outside` and `inside`
//! voxels from its surface.
openvdb::FloatGrid::Ptr signed_distance(const openvdb::tools::Dense<float>& block,
                                        const openvdb::math::Transform& transform, float background, float outside,
                                        float inside, Progress& progress) {
    auto part = openvdb::FloatGrid::create(background);
    part->setTransform(transform.copy());
    part->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::tools::copyFromDense(block, *part, 0.0f);
    progress.check();
    ProgressInterrupter interrupter(progress);
    openvdb::FloatGrid::Ptr distance = openvdb::tools::levelSetRebuild(*part, 0.0f, outside, inside, nullptr, &interrupter);
    progress.check();
    return distance;
}

//! The block's columns: sizes and the world position of a column's sample.
struct Columns {
    Columns(const openvdb::tools::Dense<float>& block, const openvdb::math::Transform& transform)
        : box(block.bbox()), transform(transform) {
        const openvdb::Coord dim = box.dim();
        nx = dim.x();
        ny = dim.y();
        nz = size_t(dim.z());
        count = size_t(nx) * size_t(ny);
        voxel = transform.voxelSize()[0];
    }
    openvdb::Vec3d world(size_t c, double z) const {
        const int i = int(c / size_t(ny)) + box.min().x(), j = int(c % size_t(ny)) + box.min().y();
        return transform.indexToWorld(openvdb::Vec3d(i, j, double(box.min().z()) + z));
    }
    openvdb::CoordBBox box;
    const openvdb::math::Transform& transform;
    int nx = 0, ny = 0;
    size_t nz = 0, count = 0;
    double voxel = 0;
};

//! Calls `visit(p)` at each end p (world) of a gap between the inside runs
//! of column `c` of `original` that lies within a voxel of the input
//! surface's zero (`surface_sampler`): input surface the sweep buries there.
template <class Visit>
void for_each_buried_gap_end(const Columns& columns, const std::vector<float>& original,
                             const Sampler& surface_sampler, size_t c, Visit&& visit) {
    const float* column = original.data() + c * columns.nz;
    const std::vector<Run> runs = inside_runs(column, columns.nz);
    for (size_t r = 0; r + 1 < runs.size(); ++r)
        for (const size_t k : {runs[r].end - 1, runs[r + 1].start - 1}) {
            const openvdb::Vec3d p = columns.world(c, zero_crossing(column, k));
            if (std::abs(surface_sampler.wsSample(p)) < columns.voxel) visit(p);
        }
}

//! Phase 0. Whether the sweep buries any input surface at all (when not,
//! nothing is to be trimmed and the distance field is not needed).
bool buries_input_surface(const Columns& columns, const std::vector<float>& original,
                          const openvdb::FloatGrid& surface, Progress& progress) {
    std::atomic<bool> found{false};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns.count), [&](const tbb::blocked_range<size_t>& range) {
        if (found || progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
        const Sampler surface_sampler(surface_access, surface.transform());
        for (size_t c = range.begin(); c != range.end() && !found; ++c)
            for_each_buried_gap_end(columns, original, surface_sampler, c, [&](const openvdb::Vec3d&) { found = true; });
    });
    progress.check();
    return found;
}

//! Phase 1. Per column: how deep below the filled part's surface (`distance`,
//! its true signed distance) the input surface at the column's gaps is
//! buried (0: no gap bounded by input surface).
std::vector<float> buried_depths(const Columns& columns, const std::vector<float>& original,
                                 const openvdb::FloatGrid& surface, const openvdb::FloatGrid& distance,
                                 Progress& progress) {
    std::vector<float> depth(columns.count, 0.0f);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns.count), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
        const openvdb::FloatGrid::ConstAccessor distance_access = distance.getConstAccessor();
        const Sampler surface_sampler(surface_access, surface.transform());
        const Sampler distance_sampler(distance_access, distance.transform());
        for (size_t c = range.begin(); c != range.end(); ++c)
            for_each_buried_gap_end(columns, original, surface_sampler, c, [&](const openvdb::Vec3d& p) {
                depth[c] = std::max(depth[c], -distance_sampler.wsSample(p));
            });
    });
    progress.check();
    return depth;
}

//! Phase 2. The regions of gap columns (4-neighbours); in one whose deepest
//! column lies deeper than `min_depth`, the columns less than half as deep.
std::vector<size_t> shallow_half_of_deep_regions(const Columns& columns, const std::vector<float>& depth,
                                                 double min_depth) {
    const int nx = columns.nx, ny = columns.ny;
    std::vector<int> region(columns.count, -1);
    std::vector<size_t> trimmed;
    std::vector<size_t> members, stack;
    for (size_t seed = 0; seed < columns.count; ++seed) {
        if (!(depth[seed] > 0) || region[seed] >= 0) continue;
        members.clear();
        stack.assign(1, seed);
        region[seed] = int(seed);
        float deepest = 0;
        while (!stack.empty()) {
            const size_t c = stack.back();
            stack.pop_back();
            members.push_back(c);
            deepest = std::max(deepest, depth[c]);
            const int i = int(c / size_t(ny)), j = int(c % size_t(ny));
            const int ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
            for (int n = 0; n < 4; ++n) {
                if (ni[n] < 0 || nj[n] < 0 || ni[n] >= nx || nj[n] >= ny) continue;
                const size_t neighbour = size_t(ni[n]) * size_t(ny) + size_t(nj[n]);
                if (depth[neighbour] > 0 && region[neighbour] < 0) {
                    region[neighbour] = int(seed);
                    stack.push_back(neighbour);
                }
            }
        }
        if (deepest <= min_depth) continue;
        for (size_t c : members)
            if (depth[c] < 0.5f * deepest) trimmed.push_back(c);
    }
    return trimmed;
}

//! Phase 3, and the rounds' undo: trimmed columns keep one run each, the one
//! with the most input surface at its ends, the longer on a tie.
class Trimming {
public:
    Trimming(const Columns& columns, const std::vector<float>& original, openvdb::tools::Dense<float>& filled,
             std::vector<size_t> trimmed)
        : columns_(columns), original_(original), filled_(filled), trimmed_(std::move(trimmed)),
          kept_(trimmed_.size()), filled_columns_(trimmed_.size()) {}

    //! Chooses each column's run, keeps its filled values aside and trims it.
    void trim_all(const openvdb::FloatGrid& surface) {
        const size_t nz = columns_.nz;
        const auto is_input_surface = [&](const Sampler& sampler, size_t c, const float* column, size_t k) {
            return std::abs(sampler.wsSample(columns_.world(c, zero_crossing(column, k)))) < columns_.voxel;
        };
        tbb::parallel_for(tbb::blocked_range<size_t>(0, trimmed_.size()), [&](const tbb::blocked_range<size_t>& range) {
            const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
            const Sampler surface_sampler(surface_access, surface.transform());
            for (size_t t = range.begin(); t != range.end(); ++t) {
                const size_t c = trimmed_[t];
                const float* column = original_.data() + c * nz;
                int kept_ends = -1;
                for (const Run& run : inside_runs(column, nz)) {
                    const int ends = is_input_surface(surface_sampler, c, column, run.start - 1) +
                                     is_input_surface(surface_sampler, c, column, run.end - 1);
                    if (ends > kept_ends || (ends == kept_ends && run.end - run.start > kept_[t].end - kept_[t].start))
                        kept_[t] = run, kept_ends = ends;
                }
                filled_columns_[t].assign(filled_.data() + c * nz, filled_.data() + (c + 1) * nz);
                trim(t);
            }
        });
    }
    //! Column t back to its kept run (outside elsewhere).
    void trim(size_t t) {
        const size_t nz = columns_.nz;
        const float* column = original_.data() + trimmed_[t] * nz;
        float* out = filled_.data() + trimmed_[t] * nz;
        const float outside = float(0.5 * columns_.voxel);
        for (size_t k = 0; k < nz; ++k)
            out[k] = k + 1 >= kept_[t].start && k <= kept_[t].end ? column[k] : std::max(std::abs(column[k]), outside);
    }
    //! Column t filled again, as the sweep left it.
    void refill(size_t t) {
        std::copy(filled_columns_[t].begin(), filled_columns_[t].end(), filled_.data() + trimmed_[t] * columns_.nz);
    }
    const std::vector<size_t>& columns() const { return trimmed_; }
    const Run& kept(size_t t) const { return kept_[t]; }

private:
    const Columns& columns_;
    const std::vector<float>& original_;
    openvdb::tools::Dense<float>& filled_;
    std::vector<size_t> trimmed_;
    std::vector<Run> kept_;
    std::vector<std::vector<float>> filled_columns_;
};

//! Phase 4. A trimmed column is filled again where the input surface it gave
//! up lies farther from the trimmed part than the column's own buried depth
//! (thin edges of a given-up run, next to a filled neighbour). The next round
//! measures what that fill buried, the input surface near the column's
//! filled gap included (a slot's walls run along the column, and its depth
//! does not count them): where it is buried deeper than the given-up surface
//! lay away, the column goes back to its trimmed values for good. At most 4
//! rounds, so a fill grows over an edge column by column. The rounds measure
//! on the block's columns within `band` + 2 of a trimmed one only: the cut it
//! makes in the part lies beyond the band. Returns the columns left trimmed.
size_t refill_given_up_edges(const Columns& columns, Trimming& trimming, const openvdb::tools::Dense<float>& filled,
                             const std::vector<float>& depth, const openvdb::FloatGrid& surface,
                             const openvdb::FloatGrid* others, float background, float band, Progress& progress) {
    const std::vector<size_t>& trimmed = trimming.columns();
    const int nx = columns.nx, ny = columns.ny;
    const size_t nz = columns.nz;
    const openvdb::CoordBBox& box = columns.box;
    openvdb::CoordBBox around;
    for (const size_t c : trimmed) around.expand(openvdb::Coord(int(c / size_t(ny)), int(c % size_t(ny)), 0));
    const int reach = int(band) + 2;
    const int i0 = std::max(around.min().x() - reach, 0), i1 = std::min(around.max().x() + reach, nx - 1);
    const int j0 = std::max(around.min().y() - reach, 0), j1 = std::min(around.max().y() + reach, ny - 1);
    const auto distance_near_trimmed = [&] {
        openvdb::tools::Dense<float> part(openvdb::CoordBBox(box.min() + openvdb::Coord(i0, j0, 0),
                                                             openvdb::Coord(box.min().x() + i1, box.min().y() + j1,
                                                                            box.max().z())));
        const size_t part_ny = size_t(j1 - j0 + 1);
        for (int i = i0; i <= i1; ++i)
            for (int j = j0; j <= j1; ++j)
                std::copy_n(filled.data() + (size_t(i) * size_t(ny) + size_t(j)) * nz, nz,
                            part.data() + (size_t(i - i0) * part_ny + size_t(j - j0)) * nz);
        return signed_distance(part, columns.transform, background, band, band, progress);
    };
    enum State : char { Trimmed, Refilled, Filled, TrimmedBack };
    std::vector<State> state(trimmed.size(), Trimmed);
    std::vector<float> given_up(trimmed.size(), 0.0f);
    const int rounds = 4;
    const double voxel = columns.voxel;
    for (int round = 0; round <= rounds; ++round) {
        const openvdb::FloatGrid::Ptr distance_now = distance_near_trimmed();
        std::vector<char> refill(trimmed.size(), 0), restore(trimmed.size(), 0);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, trimmed.size()), [&](const tbb::blocked_range<size_t>& range) {
            if (progress.cancelled()) return;
            const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
            const openvdb::FloatGrid::ConstAccessor distance_access = distance_now->getConstAccessor();
            const Sampler surface_sampler(surface_access, surface.transform());
            const Sampler distance_sampler(distance_access, distance_now->transform());
            std::optional<openvdb::FloatGrid::ConstAccessor> others_access;
            if (others) others_access.emplace(others->getConstAccessor());
            for (size_t t = range.begin(); t != range.end(); ++t) {
                if (state[t] == Filled || state[t] == TrimmedBack || (state[t] == Trimmed && round == rounds)) continue;
                const size_t c = trimmed[t];
                const Run& kept = trimming.kept(t);
                float farthest = 0, deepest_buried = 0;
                for (size_t k = 0; k < nz; ++k) {
                    if (k + 1 >= kept.start && k <= kept.end) continue;
                    const openvdb::Vec3d p = columns.world(c, double(k));
                    const float to_surface = std::abs(surface_sampler.wsSample(p));
                    if (to_surface >= voxel) continue;
                    const float value = distance_sampler.wsSample(p);
                    const bool another_part_has_it =
                        others && Sampler(*others_access, others->transform()).wsSample(p) < 0.5 * voxel;
                    if (to_surface < 0.5 * voxel && !another_part_has_it) farthest = std::max(farthest, value);
                    deepest_buried = std::max(deepest_buried, -value);
                }
                if (state[t] == Refilled) restore[t] = deepest_buried > given_up[t];
                else if (farthest > depth[c]) refill[t] = 1, given_up[t] = farthest;
            }
        });
        progress.check();
        size_t changed = 0;
        for (size_t t = 0; t < trimmed.size(); ++t) {
            if (state[t] == Refilled) {
                state[t] = restore[t] ? TrimmedBack : Filled;
                if (restore[t]) trimming.trim(t);
            } else if (refill[t]) {
                trimming.refill(t);
                state[t] = Refilled;
                ++changed;
            }
        }
        if (changed == 0) break;
    }
    return trimmed.size() - size_t(std::count(state.begin(), state.end(), Filled));
}

}  // namespace

size_t trim_deep_fills(const std::vector<float>& original, openvdb::tools::Dense<float>& filled,
                       const openvdb::math::Transform& transform, const openvdb::FloatGrid& surface,
                       float background, double min_depth, const openvdb::FloatGrid* others, Progress& progress) {
    progress.stage("sweep: fill or trim");
    const Columns columns(filled, transform);
    if (!buries_input_surface(columns, original, surface, progress)) return 0;
    const float band = float(std::max(3.0, std::ceil(4.0 * min_depth / columns.voxel)));
    // Depth below the filled part's surface, as a true signed distance.
    const openvdb::FloatGrid::Ptr distance = signed_distance(filled, transform, background, 1.0f, band, progress);
    progress.update(0.5);
    const std::vector<float> depth = buried_depths(columns, original, surface, *distance, progress);
    std::vector<size_t> trimmed = shallow_half_of_deep_regions(columns, depth, min_depth);
    progress.update(0.75);
    if (trimmed.empty()) return 0;
    Trimming trimming(columns, original, filled, std::move(trimmed));
    trimming.trim_all(surface);
    progress.check();
    return refill_given_up_edges(columns, trimming, filled, depth, surface, others, background, band, progress);
}

}  // namespace fabvdb::volume
