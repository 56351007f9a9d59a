//! find_cups: the solid sampled on a grid aligned with the build direction
//! (one voxel read, a trilinear sample only near the surface),
//! then one sweep from the plate up: each layer's empty cells are split into
//! regions (face-connected within the layer), each region a node of a
//! union-find joined to the regions under it; a node whose set does not
//! reach the outside once its layer is added holds cup cells. A second
//! union-find joins the cup nodes into cups (see resin_cups.h).
#include "check/resin_cups.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <openvdb/tools/Interpolation.h>
#include <tbb/parallel_for.h>

#include "check/print_frame.h"
#include "core/disjoint_sets.h"

namespace fabvdb::check {

namespace {

//! What a region node carries: its cells (print-frame index sums and box)
//! and its opening cells.
struct Region {
    int64_t cells = 0;
    double sum[3] = {0, 0, 0};
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int64_t opening_cells = 0;
    double opening_sum[3] = {0, 0, 0};
};

}  // namespace

CupSearch find_cups(const openvdb::FloatGrid& grid, const std::vector<Vec3>& surface_points, const Vec3& up,
                    uint64_t max_cells, double min_volume, Progress& progress) {
    progress.stage("cups");
    CupSearch result;
    // turn: part frame to print frame (up to +z); its transpose turns back.
    const Eigen::Matrix3d turn = print_frame_turn(up);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& p : surface_points) {
        const Eigen::Vector3d q = turn * Eigen::Vector3d(p[0], p[1], p[2]);
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    double cell = grid.voxelSize()[0];
    result.cell = cell;
    if (surface_points.empty()) return result;
    const Eigen::Vector3d extent = hi - lo;
    const double box_volume = (extent[0] + 2 * cell) * (extent[1] + 2 * cell) * (extent[2] + 2 * cell);
    cell = std::max(cell, std::cbrt(box_volume / double(std::max<uint64_t>(max_cells, 1))));
    result.cell = cell;
    // One empty cell of padding on every side: the padding is the outside.
    int n[3];
    for (int k = 0; k < 3; ++k) n[k] = int(std::ceil(extent[k] / cell)) + 3;
    const size_t layer_size = size_t(n[0]) * size_t(n[1]);
    const auto centre = [&](int i, int j, int k) {
        return Eigen::Vector3d(lo[0] + (i - 0.5) * cell, lo[1] + (j - 0.5) * cell, lo[2] + (k - 0.5) * cell);
    };

    // The trilinear sample's sign; where the nearest voxel lies farther than
    // a cell diagonal from the surface (most cells: the value is a distance,
    // and beyond the band ± the background), all eight corners share its
    // sign, so that one read decides.
    const double h = grid.voxelSize()[0];
    const float certain = float(std::sqrt(3.0) * h);
    std::vector<uint8_t> solid(layer_size * size_t(n[2]), 0);
    tbb::parallel_for(tbb::blocked_range<int>(1, n[2] - 1), [&](const tbb::blocked_range<int>& range) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor accessor = grid.getConstAccessor();
        openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, grid.transform());
        for (int k = range.begin(); k != range.end(); ++k)
            for (int j = 1; j < n[1] - 1; ++j)
                for (int i = 1; i < n[0] - 1; ++i) {
                    const Eigen::Vector3d p = turn.transpose() * centre(i, j, k);
                    const openvdb::Vec3d world(p[0], p[1], p[2]);
                    float value = accessor.getValue(grid.transform().worldToIndexNodeCentered(world));
                    if (std::abs(value) <= certain) value = sampler.wsSample(world);
                    if (value < 0.0f) solid[size_t(k) * layer_size + size_t(j) * n[0] + i] = 1;
                }
    });
    progress.check();

    DisjointSets sets;            // regions, joined through the layers
    std::vector<uint8_t> outside; // per root of `sets`: reaches the outside
    DisjointSets cups;            // cup regions, joined into cups
    std::vector<uint8_t> is_cup;  // per region: sealed when its layer was added
    std::vector<Region> regions;
    std::vector<int32_t> below(layer_size, -1), here(layer_size, -1);
    std::vector<size_t> stack;
    std::vector<std::pair<int32_t, int32_t>> joins;  // (region here, region below)
    for (int k = 0; k < n[2]; ++k) {
        if (k % 16 == 0) progress.update(double(k) / n[2]);
        const uint8_t* layer = solid.data() + size_t(k) * layer_size;
        std::fill(here.begin(), here.end(), -1);
        joins.clear();
        const int32_t first = int32_t(regions.size());
        for (size_t start = 0; start < layer_size; ++start) {
            if (layer[start] || here[start] >= 0) continue;
            const int32_t id = int32_t(sets.add());
            cups.add();
            outside.push_back(0);
            is_cup.push_back(0);
            regions.emplace_back();
            here[start] = id;
            stack.assign(1, start);
            while (!stack.empty()) {
                const size_t c = stack.back();
                stack.pop_back();
                const int i = int(c % n[0]), j = int(c / n[0]);
                if (i == 0 || j == 0 || i == n[0] - 1 || j == n[1] - 1) outside[id] = 1;  // layer 0, empty padding, touches it too
                // Neighbouring cells mostly sit over the same region: keep one pair.
                if (k > 0 && below[c] >= 0 && (joins.empty() || joins.back() != std::make_pair(id, below[c])))
                    joins.emplace_back(id, below[c]);
                const size_t next[4] = {c - 1, c + 1, c - n[0], c + n[0]};
                const bool inside[4] = {i > 0, i < n[0] - 1, j > 0, j < n[1] - 1};
                for (int a = 0; a < 4; ++a)
                    if (inside[a] && !layer[next[a]] && here[next[a]] < 0) {
                        here[next[a]] = id;
                        stack.push_back(next[a]);
                    }
            }
        }
        std::sort(joins.begin(), joins.end());
        joins.erase(std::unique(joins.begin(), joins.end()), joins.end());
        for (const auto& [a, b] : joins) {
            const int32_t ra = sets.find(a), rb = sets.find(b);
            const uint8_t reach = outside[ra] | outside[rb];
            outside[sets.unite(ra, rb)] = reach;
        }
        bool any_cup = false;
        for (int32_t id = first; id < int32_t(regions.size()); ++id) {
            is_cup[id] = !outside[sets.find(id)];
            any_cup = any_cup || is_cup[id];
        }
        for (const auto& [a, b] : joins) {
            if (is_cup[a]) cups.unite(a, b);  // b is a cup region too: it lies in a's sealed set
        }
        // The cup regions' cells, and the opening cells: cup cells under
        // open space that is no cup.
        for (size_t c = 0; c < layer_size; ++c) {
            if (here[c] < 0) continue;
            const int index[3] = {int(c % n[0]), int(c / n[0]), k};
            if (any_cup && is_cup[here[c]]) {
                Region& r = regions[here[c]];
                if (r.cells++ == 0)
                    for (int a = 0; a < 3; ++a) r.lo[a] = r.hi[a] = index[a];
                for (int a = 0; a < 3; ++a) {
                    r.sum[a] += index[a];
                    r.lo[a] = std::min(r.lo[a], index[a]);
                    r.hi[a] = std::max(r.hi[a], index[a]);
                }
            } else if (k > 0 && below[c] >= 0 && is_cup[below[c]]) {
                Region& r = regions[below[c]];
                ++r.opening_cells;
                for (int a = 0; a < 3; ++a) r.opening_sum[a] += index[a] - (a == 2 ? 1 : 0);
            }
        }
        std::swap(below, here);
    }
    progress.check();

    // Cups: cup regions whose set reached the outside in the end (the rest
    // are sealed cavities), gathered by their cup root.
    std::vector<int32_t> slot(regions.size(), -1);
    std::vector<Region> gathered;
    for (int32_t id = 0; id < int32_t(regions.size()); ++id) {
        if (!is_cup[id] || !outside[sets.find(id)]) continue;
        const int32_t root = cups.find(id);
        if (slot[root] < 0) {
            slot[root] = int32_t(gathered.size());
            gathered.emplace_back();
            Region& g = gathered.back();
            g.lo[0] = g.lo[1] = g.lo[2] = std::numeric_limits<int>::max();
            g.hi[0] = g.hi[1] = g.hi[2] = std::numeric_limits<int>::min();
        }
        Region& g = gathered[slot[root]];
        const Region& r = regions[id];
        g.cells += r.cells;
        g.opening_cells += r.opening_cells;
        for (int a = 0; a < 3; ++a) {
            g.sum[a] += r.sum[a];
            g.opening_sum[a] += r.opening_sum[a];
            g.lo[a] = std::min(g.lo[a], r.lo[a]);
            g.hi[a] = std::max(g.hi[a], r.hi[a]);
        }
    }
    const auto part_frame = [&](const Eigen::Vector3d& p) {
        const Eigen::Vector3d q = turn.transpose() * p;
        return Vec3{q[0], q[1], q[2]};
    };
    for (const Region& g : gathered) {
        Cup cup;
        cup.volume = double(g.cells) * cell * cell * cell;
        if (g.cells < 8 || cup.volume < min_volume) continue;
        cup.center = part_frame(centre(0, 0, 0) + cell * Eigen::Vector3d(g.sum[0], g.sum[1], g.sum[2]) / double(g.cells));
        for (int corner = 0; corner < 8; ++corner) {
            Eigen::Vector3d p = centre(corner & 1 ? g.hi[0] : g.lo[0], corner & 2 ? g.hi[1] : g.lo[1],
                                       corner & 4 ? g.hi[2] : g.lo[2]);
            for (int a = 0; a < 3; ++a) p[a] += (corner >> a & 1 ? 0.5 : -0.5) * cell;
            const Vec3 q = part_frame(p);
            if (corner == 0) cup.box.min = cup.box.max = q;
            cup.box.add(q);
        }
        cup.opening_area = double(g.opening_cells) * cell * cell;
        if (g.opening_cells > 0)
            cup.opening_center =
                part_frame(centre(0, 0, 0) + cell * Eigen::Vector3d(g.opening_sum[0], g.opening_sum[1], g.opening_sum[2]) /
                                                 double(g.opening_cells));
        result.cups.push_back(cup);
    }
    std::sort(result.cups.begin(), result.cups.end(), [](const Cup& a, const Cup& b) { return a.volume > b.volume; });
    return result;
}

}  // namespace fabvdb::check
