//! The drainability model (see drainability_model.h).
#include "powder/drainability_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <random>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

//! Later-turn samples aimed at by the automatic stride, and the pile shares
//! the expected residual is solved on.
constexpr double kLaterSamples = 2500.0;
constexpr int kPileLevels = 48;
//! The prediction's operator routines (later turns) and their seed: 64 rank
//! hole sets as well as 128 (bench_drain --sets 16; docs/design/drainability.md).
constexpr size_t kRoutines = 64;
constexpr uint64_t kRoutineSeed = 2026;
//! The steps to the 26 cells around a sample, and each sample's sample
//! there (kNoSample if none, or if no path of face steps leads there:
//! a diagonal step never cuts through a wall's edge or corner).
constexpr int kLinkOffsets[26][3] = {
    {1, 0, 0},   {-1, 0, 0},  {0, 1, 0},   {0, -1, 0},  {0, 0, 1},   {0, 0, -1},  {1, 1, 0},
    {1, -1, 0},  {-1, 1, 0},  {-1, -1, 0}, {1, 0, 1},   {1, 0, -1},  {-1, 0, 1},  {-1, 0, -1},
    {0, 1, 1},   {0, 1, -1},  {0, -1, 1},  {0, -1, -1}, {1, 1, 1},   {1, 1, -1},  {1, -1, 1},
    {1, -1, -1}, {-1, 1, 1},  {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}};

std::vector<std::array<uint32_t, 26>> sample_links(const SampleGrid& grid) {
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
                for (size_t k = 0; k < count && at != kNoSample; ++k) at = grid.neighbours[at][faces[k]];
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

}  // namespace

//! Heights and floors of the later-turn samples (see drainability_model.h):
//! the floor lies halfway to the empty cell around the sample that is
//! lowest along gravity.
DrainabilityModel::Relief DrainabilityModel::later_relief(const Vec3& gravity) const {
    const SampleGrid& grid = later_grid_;
    const double step = grid.stride * powder_.spacing;
    std::array<float, 26> drop;
    for (size_t d = 0; d < 26; ++d)
        drop[d] = float(0.5 * step *
                        (kLinkOffsets[d][0] * gravity[0] + kLinkOffsets[d][1] * gravity[1] + kLinkOffsets[d][2] * gravity[2]));
    Relief result;
    result.height = heights(grid, powder_, gravity);
    result.floor.resize(grid.size());
    for (size_t a = 0; a < grid.size(); ++a) {
        float below = 0.0f;
        for (size_t d = 0; d < 26; ++d)
            if (later_links_[a][d] == kNoSample) below = std::max(below, drop[d]);
        result.floor[a] = below > 0.0f ? result.height[a] - below : -std::numeric_limits<float>::infinity();
    }
    return result;
}

DrainabilityModel::DrainabilityModel(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                                     const OrientationFlow& first, const PowderSamples& powder,
                                     const DrainabilityOptions& options)
    : patches_(patches), turns_(turns), first_(first), powder_(powder), options_(options) {
    if (!(options.effort >= 0.0 && options.effort < 1.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the effort rho must be in [0, 1)");
    if (turns.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the orientation set is empty");
    tan_repose_ = std::tan(options.repose_radians);
    sin_repose_ = std::sin(options.repose_radians);
    later_turns_ = int(std::lround(options.effort / (1.0 - options.effort)));

    const int stride = std::max(1, int(std::lround(std::cbrt(double(powder.position.size()) / kLaterSamples))));
    first_grid_ = sample_grid(powder, 1);
    later_grid_ = sample_grid(powder, stride);
    auto cavities = [&](const SampleGrid& grid, std::vector<uint32_t>& cavity, std::vector<uint32_t>& count) {
        cavity.resize(grid.size());
        count.assign(patches.cavity_count, 0);
        for (size_t a = 0; a < grid.size(); ++a) {
            cavity[a] = patches.cavity[powder.rest_patch[grid.sample[a]]];
            ++count[cavity[a]];
        }
    };
    cavities(first_grid_, first_cavity_, first_count_);
    cavities(later_grid_, later_cavity_, later_count_);
    later_links_ = sample_links(later_grid_);
    first_chains_ = chains(first_grid_, sublevel_forest(first_grid_.neighbours, heights(first_grid_, powder, first.gravity)),
                           first_cavity_);
    later_forests_.resize(turns.size());
    later_relief_.resize(turns.size());
    later_chains_.resize(turns.size());
    tbb::parallel_for(size_t(0), turns.size(), [&](size_t k) {
        later_relief_[k] = later_relief(turns[k].gravity);
        later_forests_[k] = sublevel_forest(later_grid_.neighbours, later_relief_[k].height);
        later_chains_[k] = chains(later_grid_, later_forests_[k], later_cavity_);
    });
    // The prediction's routines: later turns drawn uniformly from the set
    // (a fixed 64-bit Mersenne twister, no library distribution: the same on
    // every machine).
    std::mt19937_64 generator(kRoutineSeed);
    routines_.resize(kRoutines);
    for (std::vector<uint32_t>& routine : routines_)
        for (int t = 0; t < later_turns_; ++t) routine.push_back(uint32_t(generator() % turns.size()));
    // Each powder sample's rank among its cavity's first-turn samples (the
    // first-turn grid holds every sample).
    first_rank_.resize(powder.position.size());
    for (size_t a = 0; a < first_grid_.size(); ++a) first_rank_[first_grid_.sample[a]] = first_chains_.rank[a];
    later_local_.assign(powder.position.size(), kNoSample);
    for (const std::vector<uint32_t>& samples : later_chains_[0].by_rank)
        for (size_t i = 0; i < samples.size(); ++i) later_local_[samples[i]] = uint32_t(i);
    patch_sample_.resize(patches.size());
    tbb::parallel_for(size_t(0), patches.size(), [&](size_t j) { patch_sample_[j] = later_grid_.nearest(patches.site[j]); });
}

DrainabilityModel::~DrainabilityModel() = default;

bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance) {
    for (const DrainHole& hole : holes) {
        const Vec3 v{candidate.center[0] - hole.center[0], candidate.center[1] - hole.center[1],
                     candidate.center[2] - hole.center[2]};
        if (std::sqrt(dot(v, v)) < min_center_distance) return false;
    }
    return true;
}

namespace {

//! Height of `point` along −gravity above `from`, and its horizontal distance from it.
std::pair<double, double> rise_and_across(const Vec3& point, const Vec3& from, const Vec3& gravity) {
    const Vec3 v{point[0] - from[0], point[1] - from[1], point[2] - from[2]};
    const double rise = -dot(v, gravity);
    return {rise, std::sqrt(std::max(0.0, dot(v, v) - rise * rise))};
}

//! Unit direction down the plane of the hole's mouth (gravity less its part
//! along the axis); zero when the axis is vertical.
Vec3 down_the_mouth(const DrainHole& hole, const Vec3& gravity) {
    const double along = dot(hole.axis, gravity);
    const Vec3 down{gravity[0] - along * hole.axis[0], gravity[1] - along * hole.axis[1],
                    gravity[2] - along * hole.axis[2]};
    const double length = std::sqrt(dot(down, down));
    if (!(length > 1e-12)) return {0, 0, 0};
    return {down[0] / length, down[1] / length, down[2] / length};
}

}  // namespace

bool DrainabilityModel::steep(const DrainHole& hole, const Vec3& gravity) const {
    return dot(hole.axis, gravity) > sin_repose_;
}

Vec3 DrainabilityModel::outer_lip(const DrainHole& hole, const Vec3& gravity) const {
    const Vec3 down = down_the_mouth(hole, gravity);
    const double radius = 0.5 * hole.diameter;
    Vec3 lip;
    for (int k = 0; k < 3; ++k) lip[k] = hole.center[k] + radius * down[k] + hole.through * hole.axis[k];
    return lip;
}

bool DrainabilityModel::absorbing(const DrainHole& hole, const Vec3& gravity) const {
    if (steep(hole, gravity)) return true;
    // The slope of repose from the outer lip must meet the inner mouth below its top.
    const Vec3 down = down_the_mouth(hole, gravity);
    const double radius = 0.5 * hole.diameter;
    const Vec3 top{hole.center[0] - radius * down[0], hole.center[1] - radius * down[1],
                   hole.center[2] - radius * down[2]};
    const auto [rise, across] = rise_and_across(top, outer_lip(hole, gravity), gravity);
    return rise > tan_repose_ * across;
}

DrainabilityModel::Cone DrainabilityModel::cone(const DrainHole& hole, const Vec3& gravity) const {
    Cone result;
    result.gravity = gravity;
    result.tan_repose = tan_repose_;
    if (steep(hole, gravity)) {
        // The crater's cone of repose rises from the rim of the mouth, not its centre.
        result.apex = hole.center;
        result.mouth = 0.5 * hole.diameter;
    } else {
        result.apex = outer_lip(hole, gravity);
    }
    return result;
}

// Inline: the walks up the chains call it for every sample.
inline bool DrainabilityModel::Cone::below(const Vec3& point) const {
    const Vec3 v{point[0] - apex[0], point[1] - apex[1], point[2] - apex[2]};
    const double rise = -dot(v, gravity);
    const double across_squared = std::max(0.0, dot(v, v) - rise * rise);
    if (across_squared <= mouth * mouth) return rise < -mouth;
    if (rise < 0.0) return true;
    const double reach = rise / tan_repose + mouth;  // the cone's radius at this height
    return reach * reach < across_squared;
}

double DrainabilityModel::total_volume() const { return powder_.total_volume(); }

DrainabilityModel::Chains DrainabilityModel::chains(const SampleGrid& grid, const SublevelForest& forest,
                                                    const std::vector<uint32_t>& cavity) const {
    const size_t n = grid.size();
    Chains result;
    result.rank.resize(n);
    result.run_end.resize(n);
    result.after_run.resize(n);
    result.by_rank.resize(patches_.cavity_count);
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

std::vector<uint64_t> DrainabilityModel::above_cone(const DrainHole& hole, uint32_t source, const Chains& chains,
                                                    const std::vector<uint32_t>& cavity, const Vec3& gravity) const {
    std::vector<uint64_t> bits;
    if (source == kNoSample || cavity[source] != hole.cavity || !absorbing(hole, gravity)) return bits;
    const std::vector<uint32_t>& sample = chains.by_rank[hole.cavity];
    bits.assign((sample.size() + 63) / 64, 0);
    const Cone crater = cone(hole, gravity);
    uint64_t any = 0;
    for (uint32_t a = source; a != kNoSample; a = chains.after_run[a])
        for (uint32_t r = chains.rank[a], end = chains.run_end[a]; r < end;) {
            // A word at a time, in a register: the tests of a run do not wait on each other.
            const uint32_t word_end = std::min(end, (r | 63) + 1);
            uint64_t word = 0;
            for (; r < word_end; ++r) word |= uint64_t(!crater.below(powder_.position[sample[r]])) << (r & 63);
            bits[(r - 1) >> 6] |= word;
            any |= word;
        }
    if (!any) bits.clear();
    return bits;
}

template <class Visit, class Under>
void DrainabilityModel::walk_above_surface(const DrainHole& hole, uint32_t source, size_t turn, Visit visit, Under under) const {
    const Vec3& gravity = turns_[turn].gravity;
    const SublevelForest& forest = later_forests_[turn];
    const Relief& relief = later_relief_[turn];
    // A source in another cavity (the hole's nearest sample across a thin
    // wall) drains nothing of this one.
    if (source == kNoSample || later_cavity_[source] != hole.cavity || !absorbing(hole, gravity)) return;
    // Powder can drain only if it reaches the mouth without climbing (the
    // source's ancestors) and lies above the crater's cone; past the highest
    // such sample nothing more drains.
    constexpr float kUnreached = std::numeric_limits<float>::infinity();
    // Samples that are not the source's ancestors are marked −∞ (levels are
    // heights, of either sign); the ancestors start unreached.
    std::vector<float> surface(later_grid_.size(), -kUnreached);
    const Cone crater = cone(hole, gravity);
    float top = -kUnreached;
    // The walk stays in the hole's cavity: the sample grid's neighbours may
    // reach across a wall thinner than its stride into another cavity, whose
    // samples count as walls here.
    for (uint32_t a = source; later_cavity_[a] == hole.cavity; a = forest.parent[a]) {
        surface[a] = kUnreached;
        if (!crater.below(powder_.position[later_grid_.sample[a]])) top = std::max(top, relief.height[a]);
        if (forest.parent[a] == a) break;
    }
    // The surface the powder keeps, found from the crater outwards (Dijkstra
    // over the ancestors): rising with slope θ_r by the horizontal length of
    // each step along paths through the cavity (steps to the 26 cells
    // around, so the surface is nearly round), never below a floor. Powder
    // above it drains. It never lies below the crater's cone.
    const double step = later_grid_.stride * powder_.spacing;
    std::array<float, 26> climb;
    for (size_t d = 0; d < 26; ++d) {
        const Vec3 v{step * kLinkOffsets[d][0], step * kLinkOffsets[d][1], step * kLinkOffsets[d][2]};
        climb[d] = float(tan_repose_ * rise_and_across(v, {0, 0, 0}, gravity).second);
    }
    const double across = rise_and_across(powder_.position[later_grid_.sample[source]], crater.apex, gravity).second;
    const double apex = -dot(crater.apex, gravity);
    surface[source] = float(across <= crater.mouth ? apex - crater.mouth : apex + tan_repose_ * (across - crater.mouth));
    using Entry = std::pair<float, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.push({surface[source], source});
    while (!queue.empty()) {
        const auto [level, b] = queue.top();
        queue.pop();
        if (level > surface[b]) continue;
        if (level >= top) break;
        // Powder passes only where the surface leaves room above it: past a
        // sample it buries (a flat passage filled to its top by the slope,
        // in a tube longer than its height / tan θ_r) the way is plugged.
        // The mouth itself is open (absorbing), whatever its height.
        if (relief.height[b] > level)
            visit(b);
        else {
            under(b);
            if (b != source) continue;
        }
        for (size_t d = 0; d < 26; ++d) {
            const uint32_t c = later_links_[b][d];
            if (c == kNoSample || surface[c] == -kUnreached) continue;
            const float next = std::max(level + climb[d], relief.floor[c]);
            if (next < surface[c]) {
                surface[c] = next;
                queue.push({next, c});
            }
        }
    }
}

namespace {

void set_bit(std::vector<uint64_t>& bits, size_t i) { bits[i >> 6] |= uint64_t(1) << (i & 63); }
bool bit(const std::vector<uint64_t>& bits, size_t i) { return (bits[i >> 6] >> (i & 63)) & 1u; }

//! Set bits below position `i` (fractional: the bit at floor(i) counts in part),
//! given `before[w]` = set bits in the words before w.
double count_below(const std::vector<uint64_t>& bits, const std::vector<uint32_t>& before, double i, size_t size) {
    const size_t whole = std::min(size_t(i), size);
    const size_t w = whole >> 6;
    double count = before[w];
    if (whole & 63) count += __builtin_popcountll(bits[w] & ((uint64_t(1) << (whole & 63)) - 1));
    if (whole < size && bit(bits, whole)) count += i - double(whole);
    return count;
}

std::vector<uint32_t> words_before(const std::vector<uint64_t>& bits) {
    std::vector<uint32_t> before(bits.size() + 1, 0);
    for (size_t w = 0; w < bits.size(); ++w) before[w + 1] = before[w] + uint32_t(__builtin_popcountll(bits[w]));
    return before;
}

}  // namespace

DrainabilityModel::Reach DrainabilityModel::reach(const DrainHole& hole, Crater crater) const {
    Reach result;
    result.cavity = hole.cavity;
    result.first = above_cone(hole, first_grid_.nearest(hole.center), first_chains_, first_cavity_, first_.gravity);
    result.later.resize(turns_.size());
    result.later_rim.resize(turns_.size());
    const uint32_t source = later_grid_.nearest(hole.center);
    const size_t words = (size_t(later_count_[hole.cavity]) + 63) / 64;
    tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
        if (crater == Crater::cone)
            result.later[k] = above_cone(hole, source, later_chains_[k], later_cavity_, turns_[k].gravity);
        else {
            auto mark = [&](std::vector<uint64_t>& bits, uint32_t a) {
                if (bits.empty()) bits.assign(words, 0);
                set_bit(bits, later_chains_[k].rank[a]);
            };
            walk_above_surface(
                hole, source, k, [&](uint32_t a) { mark(result.later[k], a); },
                [&](uint32_t a) { mark(result.later_rim[k], a); });
        }
    });
    return result;
}

DrainabilityModel::Drain DrainabilityModel::drain(const std::vector<DrainHole>& holes, Crater crater) const {
    std::vector<std::shared_ptr<const Reach>> reaches(holes.size());
    tbb::parallel_for(size_t(0), holes.size(),
                      [&](size_t h) { reaches[h] = std::make_shared<const Reach>(reach(holes[h], crater)); });
    return drain(holes, reaches);
}

DrainabilityModel::Drain DrainabilityModel::drain(const std::vector<DrainHole>& holes,
                                                  const std::vector<std::shared_ptr<const Reach>>& reaches) const {
    Drain result;
    result.holes = holes;
    result.first.resize(patches_.cavity_count);
    for (uint32_t c = 0; c < patches_.cavity_count; ++c) result.first[c].assign((first_count_[c] + 63) / 64, 0);
    result.later.assign(turns_.size(), std::vector<std::vector<uint64_t>>(patches_.cavity_count));
    result.reaches = reaches;
    for (const auto& r : reaches) {
        for (size_t w = 0; w < r->first.size(); ++w) result.first[r->cavity][w] |= r->first[w];
        for (size_t k = 0; k < turns_.size(); ++k) {
            if (r->later[k].empty()) continue;
            std::vector<uint64_t>& bits = result.later[k][r->cavity];
            if (bits.empty()) bits.assign(r->later[k].size(), 0);
            for (size_t w = 0; w < bits.size(); ++w) bits[w] |= r->later[k][w];
        }
    }
    result.later_before.resize(turns_.size());
    for (size_t k = 0; k < turns_.size(); ++k) {
        result.later_before[k].resize(patches_.cavity_count);
        for (uint32_t c = 0; c < patches_.cavity_count; ++c)
            if (!result.later[k][c].empty()) result.later_before[k][c] = words_before(result.later[k][c]);
    }
    result.retained_first.assign(patches_.cavity_count, 0);
    result.residual_per_cavity.assign(patches_.cavity_count, 0.0);
    for (uint32_t c = 0; c < patches_.cavity_count; ++c) {
        const uint32_t drained = words_before(result.first[c]).back();
        result.drained_first_volume += double(drained) * powder_.sample_volume;
        result.retained_first[c] = first_count_[c] - drained;
        if (first_count_[c] > 0)
            result.residual_per_cavity[c] =
                later_residual_share(c, double(result.retained_first[c]) / double(first_count_[c]), result, nullptr) *
                double(first_count_[c]) * powder_.sample_volume;
    }
    return result;
}

double DrainabilityModel::residual_with(const Drain& drain, const Reach& extra) const {
    const uint32_t c = extra.cavity;
    double others = 0.0;
    for (uint32_t other = 0; other < patches_.cavity_count; ++other)
        if (other != c) others += drain.residual_per_cavity[other];
    if (first_count_[c] == 0) return others;
    size_t fresh = 0;
    for (size_t w = 0; w < extra.first.size(); ++w)
        fresh += size_t(__builtin_popcountll(extra.first[w] & ~drain.first[c][w]));
    const double share = double(drain.retained_first[c] - fresh) / double(first_count_[c]);
    return others + later_residual_share(c, share, drain, &extra) * double(first_count_[c]) * powder_.sample_volume;
}

double DrainabilityModel::later_residual_share(uint32_t cavity, double start, const Drain& drain,
                                               const Reach* extra) const {
    const size_t count = later_count_[cavity];
    if (!(start > 0.0)) return 0.0;
    if (count == 0) return start;
    // Per turn that drains anything, the pile after the turn (in level steps)
    // for each pile level before it; the other turns leave the pile as it is.
    std::vector<double> after;
    size_t still = 0;
    std::vector<uint64_t> bits;
    std::vector<uint32_t> before;
    for (size_t k = 0; k < turns_.size(); ++k) {
        const std::vector<uint64_t>& base = drain.later[k][cavity];
        const bool more = extra && !extra->later[k].empty();
        if (base.empty() && !more) {
            ++still;
            continue;
        }
        if (more) {
            bits = extra->later[k];
            for (size_t w = 0; w < base.size(); ++w) bits[w] |= base[w];
            before = words_before(bits);
        }
        const std::vector<uint64_t>& drained = more ? bits : base;
        const std::vector<uint32_t>& drained_before = more ? before : drain.later_before[k][cavity];
        for (int b = 0; b <= kPileLevels; ++b) {
            const double pile = start * double(b) / kPileLevels * double(count);  // samples in the pile
            const double left = pile - count_below(drained, drained_before, pile, count);
            after.push_back(std::clamp(left / (start * double(count)) * kPileLevels, 0.0, double(b)));
        }
    }
    const size_t moving = after.size() / (kPileLevels + 1);
    // Each pile after a turn as the level below it and its fraction of the
    // step above, by level before the turn, then turn.
    std::vector<int> low(after.size());
    std::vector<double> fraction(after.size());
    for (size_t k = 0; k < moving; ++k)
        for (size_t b = 0; b <= kPileLevels; ++b) {
            const double u = after[k * (kPileLevels + 1) + b];
            const size_t i = b * moving + k;
            low[i] = std::min(int(u), kPileLevels - 1);
            fraction[i] = u - low[i];
        }
    const double turns = double(turns_.size());
    std::vector<double> residual(kPileLevels + 1), next(kPileLevels + 1);
    for (int b = 0; b <= kPileLevels; ++b) residual[size_t(b)] = start * double(b) / kPileLevels;
    for (int t = 0; t < later_turns_; ++t) {
        for (int b = 0; b <= kPileLevels; ++b) {
            double sum = double(still) * residual[size_t(b)];
            for (size_t i = size_t(b) * moving; i < size_t(b + 1) * moving; ++i) {
                const double f = fraction[i];
                sum += (1.0 - f) * residual[size_t(low[i])] + f * residual[size_t(low[i] + 1)];
            }
            next[size_t(b)] = sum / turns;
        }
        residual.swap(next);
    }
    return residual[kPileLevels];
}

DrainEvaluation DrainabilityModel::evaluate(const std::vector<DrainHole>& holes) const { return evaluate(drain(holes)); }

DrainabilityModel::Later DrainabilityModel::later_powder(const Drain& drained, uint32_t c) const {
    Later later;
    later.retained = double(drained.retained_first[c]) * powder_.sample_volume;
    later.samples = &later_chains_[0].by_rank[c];
    later.start.reserve(later.samples->size());
    for (uint32_t a : *later.samples) {
        later.start.push_back(bit(drained.first[c], first_rank_[a]) ? 0.0 : 1.0);
        later.count += later.start.back();
    }
    later.open.resize(turns_.size());
    for (size_t k = 0; k < turns_.size(); ++k) {
        for (size_t h = 0; h < drained.reaches.size(); ++h)
            if (drained.reaches[h]->cavity == c && !drained.reaches[h]->later[k].empty()) later.open[k].push_back(h);
        const Vec3& gravity = turns_[k].gravity;
        std::sort(later.open[k].begin(), later.open[k].end(), [&](size_t x, size_t y) {
            return dot(drained.holes[x].center, gravity) > dot(drained.holes[y].center, gravity);
        });
    }
    later.cavity = c;
    return later;
}

void DrainabilityModel::later_turn(const Drain& drained, const Later& later, uint32_t k, std::vector<double>& fill) const {
    const std::vector<size_t>& open = later.open[k];
    const std::vector<uint32_t>& by_rank = later_chains_[k].by_rank[later.cavity];
    auto powder_at = [&](size_t rank) -> double& { return fill[later_local_[by_rank[rank]]]; };
    // Each hole takes the powder above its surface of repose (a sample two
    // holes drain goes to the lower), then the powder it took fills its
    // crater's rim, lowest first, before leaving.
    std::vector<double> out(open.size(), 0.0);
    for (size_t o = 0; o < open.size(); ++o) {
        const std::vector<uint64_t>& bits = drained.reaches[open[o]]->later[k];
        for (size_t w = 0; w < bits.size(); ++w)
            for (uint64_t word = bits[w]; word != 0; word &= word - 1) {
                double& powder = powder_at((w << 6) + size_t(__builtin_ctzll(word)));
                out[o] += powder;
                powder = 0.0;
            }
    }
    const std::vector<uint64_t>& all = drained.later[k][later.cavity];
    for (size_t o = 0; o < open.size(); ++o) {
        const std::vector<uint64_t>& rim = drained.reaches[open[o]]->later_rim[k];
        for (size_t w = 0; w < rim.size() && out[o] > 0.0; ++w)
            for (uint64_t word = rim[w] & ~all[w]; word != 0 && out[o] > 0.0; word &= word - 1) {
                double& powder = powder_at((w << 6) + size_t(__builtin_ctzll(word)));
                const double added = std::min(out[o], 1.0 - powder);
                powder += added;
                out[o] -= added;
            }
    }
}

double DrainabilityModel::Later::left(const std::vector<double>& fill) const {
    if (count == 0.0) return retained;
    double sum = 0.0;
    for (double v : fill) sum += v;
    return retained * sum / count;
}

std::vector<double> DrainabilityModel::kept_in_place(const Drain& drained, const std::vector<Routine>& routines,
                                                     std::vector<double>* left, std::vector<double>* per_routine) const {
    std::vector<double> residual(patches_.cavity_count, 0.0);
    if (left) left->assign(powder_.position.size(), 0.0);
    if (per_routine) per_routine->assign(routines.size(), 0.0);
    for (uint32_t c = 0; c < patches_.cavity_count; ++c) {
        const Later later = later_powder(drained, c);
        if (later.count == 0.0) {
            // Only the first-turn grid keeps some: it stays where it lies.
            residual[c] = later.retained;
            if (left)
                for (uint32_t a : first_chains_.by_rank[c])
                    if (!bit(drained.first[c], first_rank_[a])) (*left)[a] = powder_.sample_volume;
            if (per_routine)
                for (double& v : *per_routine) v += later.retained;
            continue;
        }
        // Per routine: the powder left on each later-turn sample at the end.
        std::vector<std::vector<double>> ends(routines.size());
        tbb::parallel_for(size_t(0), routines.size(), [&](size_t r) {
            ends[r] = later.start;
            for (uint32_t k : routines[r]) later_turn(drained, later, k, ends[r]);
        });
        // Each later-turn sample left stands for retained / count of the
        // powder the first turn leaves.
        const double scale = later.retained / (later.count * double(routines.size()));
        for (size_t i = 0; i < later.samples->size(); ++i) {
            double sum = 0.0;
            for (const std::vector<double>& end : ends) sum += end[i];
            residual[c] += scale * sum;
            if (left) (*left)[(*later.samples)[i]] = scale * sum;
        }
        if (per_routine)
            for (size_t r = 0; r < routines.size(); ++r) (*per_routine)[r] += later.left(ends[r]);
    }
    return residual;
}

double DrainabilityModel::predicted_residual(const Drain& drained) const {
    double residual = 0.0;
    for (double v : kept_in_place(drained, routines_, nullptr, nullptr)) residual += v;
    return residual;
}

double DrainabilityModel::routine_residual(const Drain& drained, const Routine& routine) const {
    double residual = 0.0;
    for (double v : kept_in_place(drained, {routine}, nullptr, nullptr)) residual += v;
    return residual;
}

std::vector<double> DrainabilityModel::random_routine_residuals(const Drain& drained) const {
    std::vector<double> per_routine;
    kept_in_place(drained, routines_, nullptr, &per_routine);
    return per_routine;
}

DrainabilityModel::Routine DrainabilityModel::best_routine(const Drain& drained, int length) const {
    std::vector<Later> later;
    for (uint32_t c = 0; c < patches_.cavity_count; ++c) later.push_back(later_powder(drained, c));
    using Fill = std::vector<std::vector<double>>;  // per cavity
    auto left_of = [&](const Fill& fill) {
        double sum = 0.0;
        for (size_t c = 0; c < later.size(); ++c) sum += later[c].left(fill[c]);
        return sum;
    };
    auto turn = [&](Fill& fill, uint32_t k) {
        for (size_t c = 0; c < later.size(); ++c) later_turn(drained, later[c], k, fill[c]);
    };
    Fill start;
    for (const Later& cavity : later) start.push_back(cavity.start);
    const double tie = 1e-6 * total_volume();
    auto gravity_before = [&](const Routine& routine, size_t t) {
        return t == 0 ? first_.gravity : turns_[routine[t - 1]].gravity;
    };
    // Of the turns whose `left` is within `tie` of the least, the one with
    // the smallest tilt from `previous`.
    auto pick = [&](const std::vector<double>& left, const Vec3& previous) {
        const double least = *std::min_element(left.begin(), left.end());
        uint32_t best = 0;
        double best_tilt = -2.0;
        for (size_t k = 0; k < left.size(); ++k) {
            const double cosine = dot(turns_[k].gravity, previous);  // larger: a smaller tilt
            if (left[k] <= least + tie && cosine > best_tilt) {
                best_tilt = cosine;
                best = uint32_t(k);
            }
        }
        return best;
    };
    // Greedy: each turn the one that leaves the least after it.
    Routine routine;
    Fill fill = start;
    for (int t = 0; t < length; ++t) {
        std::vector<double> left(turns_.size(), 0.0);
        tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
            Fill next = fill;
            turn(next, uint32_t(k));
            left[k] = left_of(next);
        });
        routine.push_back(pick(left, gravity_before(routine, routine.size())));
        turn(fill, routine.back());
    }
    auto residual_of = [&](const Routine& candidate) {
        Fill end = start;
        for (uint32_t k : candidate) turn(end, k);
        return left_of(end);
    };
    // The greedy routine can be short-sighted: start from the best of it and
    // the prediction's random routines (so it never leaves more than their
    // mean), then change one turn at a time while that leaves less.
    double best = residual_of(routine);
    for (const Routine& random : routines_) {
        if (int(random.size()) != length) continue;
        const double residual = residual_of(random);
        if (residual < best - tie) {
            best = residual;
            routine = random;
        }
    }
    for (int pass = 0; pass < 2; ++pass) {
        bool improved = false;
        Fill before = start;  // the powder before turn t
        for (size_t t = 0; t < routine.size(); ++t) {
            std::vector<double> left(turns_.size(), 0.0);
            tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
                Fill end = before;
                turn(end, uint32_t(k));
                for (size_t u = t + 1; u < routine.size(); ++u) turn(end, routine[u]);
                left[k] = left_of(end);
            });
            const uint32_t k = pick(left, gravity_before(routine, t));
            if (left[k] < best - tie) {
                routine[t] = k;
                best = left[k];
                improved = true;
            }
            turn(before, routine[t]);
        }
        if (!improved) break;
    }
    return routine;
}

DrainEvaluation DrainabilityModel::evaluate(const Drain& drained) const { return evaluate(drained, routines_); }

DrainEvaluation DrainabilityModel::evaluate(const Drain& drained, const std::vector<Routine>& routines) const {
    DrainEvaluation result;
    result.total_volume = powder_.total_volume();
    result.drained_first_volume = drained.drained_first_volume;
    std::vector<double> left;
    result.residual_per_cavity = kept_in_place(drained, routines, &left, nullptr);
    for (double v : result.residual_per_cavity) result.residual_volume += v;

    // Per patch: the powder resting on it at the start and at the end.
    const size_t n = patches_.size();
    result.initial_per_patch.assign(n, 0.0);
    result.left_per_patch.assign(n, 0.0);
    for (size_t a = 0; a < powder_.position.size(); ++a) {
        result.initial_per_patch[powder_.rest_patch[a]] += powder_.sample_volume;
        result.left_per_patch[powder_.rest_patch[a]] += left[a];
    }
    std::vector<double> cavity_initial(patches_.cavity_count, 0.0), cavity_left(patches_.cavity_count, 0.0);
    for (size_t j = 0; j < n; ++j) {
        cavity_initial[patches_.cavity[j]] += result.initial_per_patch[j];
        cavity_left[patches_.cavity[j]] += result.left_per_patch[j];
    }
    auto share = [](double initial, double left) { return initial > 0.0 ? 1.0 - left / initial : 1.0; };
    result.drained_share.resize(n);
    for (size_t j = 0; j < n; ++j) {
        if (result.initial_per_patch[j] > 0.0) {
            result.drained_share[j] = share(result.initial_per_patch[j], result.left_per_patch[j]);
            continue;
        }
        // No powder rests on it: the share of the patch its nearest sample rests on.
        const uint32_t a = patch_sample_[j];
        const uint32_t p = a == kNoSample ? uint32_t(j) : powder_.rest_patch[later_grid_.sample[a]];
        result.drained_share[j] = result.initial_per_patch[p] > 0.0
                                      ? share(result.initial_per_patch[p], result.left_per_patch[p])
                                      : share(cavity_initial[patches_.cavity[j]], cavity_left[patches_.cavity[j]]);
    }
    return result;
}

}  // namespace fabvdb::powder
