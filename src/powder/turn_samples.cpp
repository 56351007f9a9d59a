//! The powder samples per turn (see turn_samples.h).
#include "powder/turn_samples.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::powder {

namespace {

//! Later-turn samples aimed at by the automatic stride.
constexpr double kLaterSamples = 2500.0;

//! Per sample, the sample of each of the 26 cells around it reached by face
//! steps within its own cavity (a coarse grid can put samples of two
//! cavities side by side across a thin wall; powder does not pass).
std::vector<std::array<uint32_t, 26>> sample_links(const SampleGrid& grid, const std::vector<uint32_t>& cavity) {
    std::vector<std::array<uint32_t, 26>> links(grid.size());
    tbb::parallel_for(size_t(0), grid.size(), [&](size_t a) {
        for (size_t d = 0; d < 26; ++d) {
            // The face steps of this offset (neighbours' order: +x −x +y −y +z −z), tried in every order.
            std::array<size_t, 3> faces{};
            size_t count = 0;
            for (size_t axis = 0; axis < 3; ++axis)
                if (kLinkOffsets[d][axis] != 0) faces[count++] = 2 * axis + (kLinkOffsets[d][axis] < 0 ? 1 : 0);
            std::sort(faces.begin(), faces.begin() + long(count));
            uint32_t found = kNoSample;
            do {
                uint32_t at = uint32_t(a);
                for (size_t k = 0; k < count && at != kNoSample; ++k) {
                    at = grid.neighbours[at][faces[k]];
                    if (at != kNoSample && cavity[at] != cavity[a]) at = kNoSample;
                }
                found = at;
            } while (found == kNoSample && std::next_permutation(faces.begin(), faces.begin() + long(count)));
            links[a][d] = found;
        }
    });
    return links;
}

//! Each sample's height along −gravity (what the sublevel forests order by).
std::vector<float> heights(const SampleGrid& grid, const PowderSamples& powder, const Vec3& gravity) {
    std::vector<float> height(grid.size());
    for (size_t a = 0; a < grid.size(); ++a) height[a] = float(-dot(powder.position[grid.sample[a]], gravity));
    return height;
}

//! The floor lies halfway to the empty cell around the sample that is
//! lowest along gravity.
SampleRelief later_relief(const TurnSamples& samples, const Vec3& gravity) {
    const SampleGrid& grid = samples.later_grid;
    const double step = grid.stride * samples.powder->spacing;
    std::array<float, 26> drop;
    for (size_t d = 0; d < 26; ++d)
        drop[d] = float(0.5 * step *
                        (kLinkOffsets[d][0] * gravity[0] + kLinkOffsets[d][1] * gravity[1] + kLinkOffsets[d][2] * gravity[2]));
    SampleRelief result;
    result.height = heights(grid, *samples.powder, gravity);
    result.floor.resize(grid.size());
    for (size_t a = 0; a < grid.size(); ++a) {
        float below = 0.0f;
        for (size_t d = 0; d < 26; ++d)
            if (samples.later_links[a][d] == kNoSample) below = std::max(below, drop[d]);
        result.floor[a] = below > 0.0f ? result.height[a] - below : -std::numeric_limits<float>::infinity();
    }
    return result;
}

//! The slides of turn `k` (its chains already built).
SampleSlides later_slides(const TurnSamples& samples, size_t k, double repose_radians) {
    const double steep = std::sin(repose_radians);
    const Vec3& gravity = samples.later_gravity[k];
    std::vector<std::pair<double, uint8_t>> steps;  // (drop, link)
    for (uint8_t d = 0; d < 26; ++d) {
        const Vec3 step{double(kLinkOffsets[d][0]), double(kLinkOffsets[d][1]), double(kLinkOffsets[d][2])};
        const double drop = dot(step, gravity);
        if (drop >= steep * std::sqrt(dot(step, step))) steps.push_back({drop, d});
    }
    std::sort(steps.begin(), steps.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    SampleSlides result;
    for (const auto& step : steps) result.steps.push_back(step.second);
    result.order.resize(samples.cavity_count);
    for (uint32_t c = 0; c < samples.cavity_count; ++c)
        for (uint32_t sample : samples.later_chains[k].by_rank[c]) result.order[c].push_back(samples.later_local[sample]);
    return result;
}

//! later_links by place in the cavity (TurnSamples::later_local_links).
std::vector<std::vector<std::array<uint32_t, 26>>> local_links(const TurnSamples& samples) {
    const SampleGrid& grid = samples.later_grid;
    auto place = [&](uint32_t a) { return a == kNoSample ? kNoSample : samples.later_local[grid.sample[a]]; };
    std::vector<std::vector<std::array<uint32_t, 26>>> result(samples.cavity_count);
    for (uint32_t c = 0; c < samples.cavity_count; ++c) result[c].resize(samples.later_count[c]);
    for (uint32_t a = 0; a < grid.size(); ++a) {
        std::array<uint32_t, 26>& links = result[samples.later_cavity[a]][place(a)];
        for (size_t d = 0; d < 26; ++d) links[d] = place(samples.later_links[a][d]);
    }
    return result;
}

SampleChains chains(const SampleGrid& grid, const SublevelForest& forest, const std::vector<uint32_t>& cavity,
                    uint32_t cavity_count) {
    const size_t n = grid.size();
    SampleChains result;
    result.rank.resize(n);
    result.run_end.resize(n);
    result.after_run.resize(n);
    result.by_rank.resize(cavity_count);
    for (uint32_t a : forest.order) {
        result.rank[a] = uint32_t(result.by_rank[cavity[a]].size());
        result.by_rank[cavity[a]].push_back(grid.sample[a]);
    }
    // From the highest down, so a parent's run is known before its child's.
    for (auto at = forest.order.rbegin(); at != forest.order.rend(); ++at) {
        const uint32_t a = *at, parent = forest.parent[a];
        const bool inside = parent != a && cavity[parent] == cavity[a];
        if (inside && result.rank[parent] == result.rank[a] + 1) {
            result.run_end[a] = result.run_end[parent];
            result.after_run[a] = result.after_run[parent];
        } else {
            result.run_end[a] = result.rank[a] + 1;
            result.after_run[a] = inside ? parent : kNoSample;
        }
    }
    return result;
}

}  // namespace

TurnSamples turn_samples(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                         const OrientationFlow& first, const PowderSamples& powder, double repose_radians) {
    TurnSamples result;
    result.powder = &powder;
    result.cavity_count = patches.cavity_count;
    result.first_gravity = first.gravity;
    for (const OrientationFlow& turn : turns) result.later_gravity.push_back(turn.gravity);
    const int stride = std::max(1, int(std::lround(std::cbrt(double(powder.position.size()) / kLaterSamples))));
    result.first_grid = sample_grid(powder, 1);
    result.later_grid = sample_grid(powder, stride);
    auto cavities = [&](const SampleGrid& grid, std::vector<uint32_t>& cavity, std::vector<uint32_t>& count) {
        cavity.resize(grid.size());
        count.assign(patches.cavity_count, 0);
        for (size_t a = 0; a < grid.size(); ++a) {
            cavity[a] = patches.cavity[powder.rest_patch[grid.sample[a]]];
            ++count[cavity[a]];
        }
    };
    cavities(result.first_grid, result.first_cavity, result.first_count);
    cavities(result.later_grid, result.later_cavity, result.later_count);
    result.later_links = sample_links(result.later_grid, result.later_cavity);
    result.first_chains =
        chains(result.first_grid,
               sublevel_forest(result.first_grid.neighbours, heights(result.first_grid, powder, first.gravity)),
               result.first_cavity, patches.cavity_count);
    result.later_forests.resize(turns.size());
    result.later_relief.resize(turns.size());
    result.later_chains.resize(turns.size());
    result.later_slides.resize(turns.size());
    tbb::parallel_for(size_t(0), turns.size(), [&](size_t k) {
        result.later_relief[k] = later_relief(result, turns[k].gravity);
        result.later_forests[k] = sublevel_forest(result.later_grid.neighbours, result.later_relief[k].height);
        result.later_chains[k] = chains(result.later_grid, result.later_forests[k], result.later_cavity, patches.cavity_count);
    });
    result.first_later_relief = later_relief(result, first.gravity);
    result.first_later_forest = sublevel_forest(result.later_grid.neighbours, result.first_later_relief.height);
    result.later_of_first.resize(result.first_grid.size());
    tbb::parallel_for(size_t(0), result.first_grid.size(), [&](size_t a) {
        result.later_of_first[a] = result.later_grid.nearest(powder.position[result.first_grid.sample[a]]);
    });
    // Each powder sample's rank among its cavity's first-turn samples (the
    // first-turn grid holds every sample).
    result.first_rank.resize(powder.position.size());
    for (size_t a = 0; a < result.first_grid.size(); ++a)
        result.first_rank[result.first_grid.sample[a]] = result.first_chains.rank[a];
    result.later_local.assign(powder.position.size(), kNoSample);
    for (const std::vector<uint32_t>& samples : result.later_chains[0].by_rank)
        for (size_t i = 0; i < samples.size(); ++i) result.later_local[samples[i]] = uint32_t(i);
    tbb::parallel_for(size_t(0), turns.size(),
                      [&](size_t k) { result.later_slides[k] = later_slides(result, k, repose_radians); });
    result.later_local_links = local_links(result);
    return result;
}

}  // namespace fabvdb::powder
