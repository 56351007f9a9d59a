//! Overlapping boxes of triangles (see triangle_box_pairs.h).
//!
//! Each triangle goes to the grid of its size class: level L has cells of
//! base × 2^L, and a triangle whose bounding box is at most that wide sits in
//! the (at most 8) cells its box overlaps. Pairs in one level meet in a shared
//! cell; a triangle meets the larger ones by looking up the cells its box
//! overlaps in each coarser level. A pair of overlapping boxes is visited only
//! in the cell holding the lowest corner of their common box, so once.
#include "volume/triangle_box_pairs.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

namespace fabvdb::volume {

namespace {

struct Box {
    double lo[3], hi[3];
};

constexpr int max_levels = 40;

// A triangle's place in a level: its cell key above its index, in one
// integer, so that sorting the integers groups each cell's triangles.
class Grids {
public:
    explicit Grids(const std::vector<Box>& boxes) {
        while ((uint64_t(1) << triangle_bits_) < boxes.size()) ++triangle_bits_;
        axis_bits_ = std::min(21, (64 - triangle_bits_) / 3);
        const int64_t cells_per_axis = int64_t(1) << axis_bits_;
        std::vector<double> extents(boxes.size(), 0.0);
        double top[3];
        for (int k = 0; k < 3; ++k) {
            origin_[k] = HUGE_VAL;
            top[k] = -HUGE_VAL;
        }
        for (size_t t = 0; t < boxes.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                extents[t] = std::max(extents[t], boxes[t].hi[k] - boxes[t].lo[k]);
                origin_[k] = std::min(origin_[k], boxes[t].lo[k]);
                top[k] = std::max(top[k], boxes[t].hi[k]);
            }
        double span = 0.0;
        for (int k = 0; k < 3; ++k) span = std::max(span, top[k] - origin_[k]);
        std::vector<double> sorted = extents;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        double base = 2.0 * sorted[sorted.size() / 2];
        // Cells must be few enough per axis for the key, and never empty.
        base = std::max({base, 2.0 * span / double(cells_per_axis), 1e-300});
        for (int level = 0; level < max_levels; ++level) {
            cell_size_[level] = std::ldexp(base, level);
            inverse_cell_size_[level] = 1.0 / cell_size_[level];
        }

        level_.resize(boxes.size());
        int top_level = 0;
        for (size_t t = 0; t < boxes.size(); ++t) {
            int level = 0;
            while (level + 1 < max_levels && cell_size_[level] < extents[t]) ++level;
            level_[t] = uint8_t(level);
            top_level = std::max(top_level, level);
        }
        // Each triangle's cells go to its own slots of its level, in parallel.
        low_cell_.resize(boxes.size());
        std::vector<size_t> slot(boxes.size(), 0);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                low_cell_[t] = cell_of(boxes[t].lo, level_[t]);
                for_each_cell(boxes[t], level_[t], [&](uint64_t) { ++slot[t]; });
            }
        });
        entries_.resize(size_t(top_level) + 1);
        std::vector<size_t> level_size(entries_.size(), 0);
        for (size_t t = 0; t < boxes.size(); ++t) {
            const size_t cells = slot[t];
            slot[t] = level_size[level_[t]];
            level_size[level_[t]] += cells;
        }
        for (size_t level = 0; level < entries_.size(); ++level) entries_[level].resize(level_size[level]);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                uint64_t* entry = &entries_[level_[t]][slot[t]];
                for_each_cell(boxes[t], level_[t], [&](uint64_t cell) { *entry++ = entry_of(cell, uint32_t(t)); });
            }
        });
        for (auto& level : entries_) tbb::parallel_sort(level.begin(), level.end());
    }

    int levels() const { return int(entries_.size()); }
    int level(size_t t) const { return level_[t]; }
    //! The cell of its own level that holds the lowest corner of t's box.
    uint64_t low_cell(size_t t) const { return low_cell_[t]; }
    //! The level's entries, sorted: by cell, then by triangle.
    const std::vector<uint64_t>& entries(int level) const { return entries_[level]; }
    uint64_t entry_of(uint64_t cell, uint32_t triangle) const { return cell << triangle_bits_ | triangle; }
    uint64_t cell(uint64_t entry) const { return entry >> triangle_bits_; }
    uint32_t triangle(uint64_t entry) const { return uint32_t(entry & ((uint64_t(1) << triangle_bits_) - 1)); }

    uint64_t cell_of(const double* p, int level) const {
        const int64_t last = (int64_t(1) << axis_bits_) - 1;
        uint64_t key = 0;
        for (int k = 0; k < 3; ++k)
            key = key << axis_bits_ |
                  uint64_t(std::clamp(int64_t(std::floor((p[k] - origin_[k]) * inverse_cell_size_[level])), int64_t(0), last));
        return key;
    }

    //! The cell holding the lowest corner of the common box of two boxes
    //! whose lowest corners lie in cells `a` and `b` of one level.
    uint64_t common_low_cell(uint64_t a, uint64_t b) const {
        const uint64_t mask = (uint64_t(1) << axis_bits_) - 1;
        uint64_t key = 0;
        for (int shift = 2 * axis_bits_; shift >= 0; shift -= axis_bits_)
            key |= std::max((a >> shift) & mask, (b >> shift) & mask) << shift;
        return key;
    }

    template <class Visit>
    void for_each_cell(const Box& box, int level, const Visit& visit) const {
        const uint64_t lo = cell_of(box.lo, level), hi = cell_of(box.hi, level);
        const int b = axis_bits_;
        const uint64_t mask = (uint64_t(1) << b) - 1;
        for (uint64_t x = lo >> (2 * b); x <= hi >> (2 * b); ++x)
            for (uint64_t y = (lo >> b) & mask; y <= ((hi >> b) & mask); ++y)
                for (uint64_t z = lo & mask; z <= (hi & mask); ++z) visit(x << (2 * b) | y << b | z);
    }

private:
    int triangle_bits_ = 1;
    int axis_bits_ = 21;
    double origin_[3] = {0, 0, 0};
    double cell_size_[max_levels], inverse_cell_size_[max_levels];
    std::vector<uint8_t> level_;
    std::vector<uint64_t> low_cell_;
    std::vector<std::vector<uint64_t>> entries_;
};

bool boxes_overlap(const Box& a, const Box& b) {
    for (int k = 0; k < 3; ++k)
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
}

Box box_of(const Mesh& mesh, const Triangle& t) {
    Box box;
    for (int k = 0; k < 3; ++k) {
        const double a = mesh.vertices[t[0]][k], b = mesh.vertices[t[1]][k], c = mesh.vertices[t[2]][k];
        box.lo[k] = std::min({a, b, c});
        box.hi[k] = std::max({a, b, c});
    }
    return box;
}

}  // namespace

void for_each_overlapping_box_pair(const Mesh& mesh, const std::function<void(uint32_t, uint32_t)>& visit) {
    const size_t count = mesh.triangles.size();
    if (count < 2) return;
    std::vector<Box> boxes(count);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) boxes[t] = box_of(mesh, mesh.triangles[t]);
    });
    const Grids grids(boxes);

    // Visits the pair met in `cell` unless another cell owns it; `i_low` and
    // `j_low`: the cells of that level holding their boxes' lowest corners.
    const auto visit_once = [&](uint32_t i, uint32_t j, const Box& i_box, const Box& j_box, uint64_t cell,
                                uint64_t i_low, uint64_t j_low) {
        if (boxes_overlap(i_box, j_box) && grids.common_low_cell(i_low, j_low) == cell) visit(i, j);
    };

    for (int level = 0; level < grids.levels(); ++level) {
        const std::vector<uint64_t>& entries = grids.entries(level);
        std::vector<size_t> runs;
        for (size_t e = 0; e < entries.size(); ++e)
            if (e == 0 || grids.cell(entries[e]) != grids.cell(entries[e - 1])) runs.push_back(e);
        runs.push_back(entries.size());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, runs.size() - 1), [&](const tbb::blocked_range<size_t>& range) {
            // The run's triangles, boxes and lowest cells side by side, read once.
            std::vector<uint32_t> run_triangles;
            std::vector<Box> run_boxes;
            std::vector<uint64_t> run_lows;
            for (size_t r = range.begin(); r != range.end(); ++r) {
                const size_t size = runs[r + 1] - runs[r];
                const uint64_t cell = grids.cell(entries[runs[r]]);
                run_triangles.resize(size);
                run_boxes.resize(size);
                run_lows.resize(size);
                for (size_t e = 0; e < size; ++e) {
                    run_triangles[e] = grids.triangle(entries[runs[r] + e]);
                    run_boxes[e] = boxes[run_triangles[e]];
                    run_lows[e] = grids.low_cell(run_triangles[e]);
                }
                for (size_t e = 0; e < size; ++e)
                    for (size_t f = e + 1; f < size; ++f)
                        visit_once(run_triangles[e], run_triangles[f], run_boxes[e], run_boxes[f], cell, run_lows[e],
                                   run_lows[f]);
            }
        });
    }
    if (grids.levels() > 1)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t)
                for (int level = grids.level(t) + 1; level < grids.levels(); ++level) {
                    const std::vector<uint64_t>& entries = grids.entries(level);
                    const uint64_t t_low = grids.cell_of(boxes[t].lo, level);
                    grids.for_each_cell(boxes[t], level, [&](uint64_t cell) {
                        auto it = std::lower_bound(entries.begin(), entries.end(), grids.entry_of(cell, 0));
                        for (; it != entries.end() && grids.cell(*it) == cell; ++it) {
                            const uint32_t other = grids.triangle(*it);
                            visit_once(uint32_t(t), other, boxes[t], boxes[other], cell, t_low, grids.low_cell(other));
                        }
                    });
                }
        });
}

// The marked boxes go into cubic cells as wide as the widest of them (so
// each meets at most 8); a triangle looks in the cells its own box meets.
// Two boxes that share a point share that point's cell: the cell index
// floor((x − origin) / side) never decreases with x, rounding included. A
// triangle meeting more than `max_cells` cells is compared with every marked
// box instead.
std::vector<uint32_t> triangles_near_marked(const Mesh& mesh, const std::vector<char>& marked) {
    constexpr int64_t max_cells = 64;
    constexpr int cell_bits = 21;
    std::vector<uint32_t> listed;
    for (size_t t = 0; t < marked.size(); ++t)
        if (marked[t]) listed.push_back(uint32_t(t));
    if (listed.empty()) return {};
    std::vector<Box> boxes;
    boxes.reserve(listed.size());
    double origin[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, top[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, side = 0.0;
    for (uint32_t t : listed) {
        const Box& box = boxes.emplace_back(box_of(mesh, mesh.triangles[t]));
        for (int k = 0; k < 3; ++k) {
            origin[k] = std::min(origin[k], box.lo[k]);
            top[k] = std::max(top[k], box.hi[k]);
            side = std::max(side, box.hi[k] - box.lo[k]);
        }
    }
    for (int k = 0; k < 3; ++k) side = std::max(side, (top[k] - origin[k]) / double(int64_t(1) << (cell_bits - 1)));
    side = std::max(side, 1e-300);
    int64_t last[3];
    const auto cell = [&](double x, int k) { return int64_t(std::floor((x - origin[k]) / side)); };
    for (int k = 0; k < 3; ++k) last[k] = cell(top[k], k);
    const auto key = [](int64_t x, int64_t y, int64_t z) {
        return uint64_t(x) << (2 * cell_bits) | uint64_t(y) << cell_bits | uint64_t(z);
    };
    std::vector<std::pair<uint64_t, uint32_t>> cells;  // (cell, index into listed)
    for (uint32_t c = 0; c < listed.size(); ++c) {
        const Box& box = boxes[c];
        for (int64_t x = cell(box.lo[0], 0); x <= cell(box.hi[0], 0); ++x)
            for (int64_t y = cell(box.lo[1], 1); y <= cell(box.hi[1], 1); ++y)
                for (int64_t z = cell(box.lo[2], 2); z <= cell(box.hi[2], 2); ++z) cells.emplace_back(key(x, y, z), c);
    }
    tbb::parallel_sort(cells.begin(), cells.end());

    std::vector<char> near(mesh.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) {
            if (marked[t]) {
                near[t] = 1;
                continue;
            }
            const Box box = box_of(mesh, mesh.triangles[t]);
            int64_t lo[3], hi[3], count = 1;
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::max<int64_t>(cell(box.lo[k], k), 0);
                hi[k] = std::min(cell(box.hi[k], k), last[k]);
                count *= std::max<int64_t>(hi[k] - lo[k] + 1, 0);
            }
            if (count == 0) continue;
            if (count > max_cells) {
                near[t] = std::any_of(boxes.begin(), boxes.end(), [&](const Box& other) { return boxes_overlap(box, other); });
                continue;
            }
            for (int64_t x = lo[0]; x <= hi[0] && !near[t]; ++x)
                for (int64_t y = lo[1]; y <= hi[1] && !near[t]; ++y)
                    for (int64_t z = lo[2]; z <= hi[2] && !near[t]; ++z)
                        for (auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(key(x, y, z), 0u));
                             it != cells.end() && it->first == key(x, y, z); ++it)
                            if (boxes_overlap(box, boxes[it->second])) {
                                near[t] = 1;
                                break;
                            }
        }
    });
    std::vector<uint32_t> result;
    for (size_t t = 0; t < near.size(); ++t)
        if (near[t]) result.push_back(uint32_t(t));
    return result;
}

}  // namespace fabvdb::volume
