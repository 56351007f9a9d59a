//! Exact disjointness of the cavity and outer surfaces (see surfaces_disjoint.h).
//!
//! Most pairs are ruled out by a grid first: cubic cells of twice the median
//! size of an outer triangle, the cells each outer triangle's bounding box
//! overlaps marked. Two boxes that share a point share the cell of that
//! point (the cell index, floor((x − origin) / side), never decreases with
//! x, rounding included), so a cavity triangle whose box overlaps no marked
//! cell touches no outer triangle. The others, and every cavity triangle
//! against outer triangles too large for the grid, are tested exactly.
#include "volume/surfaces_disjoint.h"

#include <algorithm>
#include <cmath>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Triangle3 triangle(const Mesh& mesh, const fabvdb::Triangle& t) {
    const auto point = [&](uint32_t v) {
        return Kernel::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
    };
    return Triangle3(point(t[0]), point(t[1]), point(t[2]));
}

//! Outer triangles spanning more cells than this are tested exactly instead.
constexpr int64_t max_cells_per_outer_triangle = 27;
//! Cavity triangles spanning more cells than this are tested exactly.
constexpr int64_t max_cells_per_cavity_triangle = 512;
constexpr int cell_bits = 21;

class CellGrid {
public:
    CellGrid(const Mesh& outer, const Mesh& cavity) {
        std::vector<double> extents(outer.triangles.size());
        for (int k = 0; k < 3; ++k) origin_[k] = HUGE_VAL;
        double top = -HUGE_VAL;
        for (const Mesh* mesh : {&outer, &cavity})
            for (const fabvdb::Triangle& t : mesh->triangles)
                for (uint32_t v : t)
                    for (int k = 0; k < 3; ++k) {
                        origin_[k] = std::min(origin_[k], mesh->vertices[v][k]);
                        top = std::max(top, mesh->vertices[v][k]);
                    }
        for (size_t t = 0; t < outer.triangles.size(); ++t) {
            double lo[3], hi[3];
            box(outer, outer.triangles[t], lo, hi);
            extents[t] = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
        }
        std::nth_element(extents.begin(), extents.begin() + ptrdiff_t(extents.size() / 2), extents.end());
        double span = 0.0;
        for (int k = 0; k < 3; ++k) span = std::max(span, top - origin_[k]);
        side_ = std::max({2.0 * extents[extents.size() / 2], 2.0 * span / double(int64_t(1) << cell_bits), 1e-300});
    }

    static void box(const Mesh& mesh, const fabvdb::Triangle& t, double* lo, double* hi) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min({mesh.vertices[t[0]][k], mesh.vertices[t[1]][k], mesh.vertices[t[2]][k]});
            hi[k] = std::max({mesh.vertices[t[0]][k], mesh.vertices[t[1]][k], mesh.vertices[t[2]][k]});
        }
    }

    //! The cell range of a triangle's box, and how many cells it holds.
    int64_t range(const Mesh& mesh, const fabvdb::Triangle& t, int64_t* lo, int64_t* hi) const {
        double box_lo[3], box_hi[3];
        box(mesh, t, box_lo, box_hi);
        int64_t count = 1;
        for (int k = 0; k < 3; ++k) {
            lo[k] = index(box_lo[k], k);
            hi[k] = index(box_hi[k], k);
            count *= hi[k] - lo[k] + 1;
        }
        return count;
    }

    template <class Visit>
    static void for_each_cell(const int64_t* lo, const int64_t* hi, const Visit& visit) {
        for (int64_t x = lo[0]; x <= hi[0]; ++x)
            for (int64_t y = lo[1]; y <= hi[1]; ++y)
                for (int64_t z = lo[2]; z <= hi[2]; ++z)
                    visit(uint64_t(x) << (2 * cell_bits) | uint64_t(y) << cell_bits | uint64_t(z));
    }

private:
    int64_t index(double x, int k) const {
        return std::clamp(int64_t(std::floor((x - origin_[k]) / side_)), int64_t(0), (int64_t(1) << cell_bits) - 1);
    }

    double origin_[3];
    double side_ = 1.0;
};

//! Counts the cavity triangles listed in `which` that touch a triangle of `tree`.
void mark_touching(const Tree& tree, const Mesh& cavity, const std::vector<uint32_t>& which, std::vector<char>& touching,
                   Progress& progress) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, which.size(), 1024), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (progress.cancelled()) return;
            if (tree.do_intersect(triangle(cavity, cavity.triangles[which[i]]))) touching[which[i]] = 1;
        }
    });
    progress.check();
}

}  // namespace

std::vector<char> cavity_triangles_touching(const Mesh& outer, const Mesh& cavity, Progress& progress) {
    progress.stage("check wall separation");
    std::vector<char> touching(cavity.triangles.size(), 0);
    if (outer.triangles.empty() || cavity.triangles.empty()) return touching;
    const CellGrid grid(outer, cavity);

    // The cells of the outer triangles that fit the grid; the others aside.
    std::vector<int64_t> cell_count(outer.triangles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, outer.triangles.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t != r.end(); ++t) {
            int64_t lo[3], hi[3];
            cell_count[t] = grid.range(outer, outer.triangles[t], lo, hi);
        }
    });
    std::vector<size_t> slot(outer.triangles.size() + 1, 0);
    std::vector<Triangle3> large;
    for (size_t t = 0; t < outer.triangles.size(); ++t) {
        const bool fits = cell_count[t] <= max_cells_per_outer_triangle;
        slot[t + 1] = slot[t] + (fits ? size_t(cell_count[t]) : 0);
        if (!fits) large.push_back(triangle(outer, outer.triangles[t]));
    }
    std::vector<uint64_t> marked(slot.back());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, outer.triangles.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t != r.end(); ++t) {
            if (cell_count[t] > max_cells_per_outer_triangle) continue;
            int64_t lo[3], hi[3];
            grid.range(outer, outer.triangles[t], lo, hi);
            uint64_t* out = &marked[slot[t]];
            CellGrid::for_each_cell(lo, hi, [&](uint64_t cell) { *out++ = cell; });
        }
    });
    tbb::parallel_sort(marked.begin(), marked.end());
    marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
    progress.update(0.3);

    // Cavity triangles in a marked cell (or too large to look) need the exact test.
    std::vector<char> near(cavity.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, cavity.triangles.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t != r.end(); ++t) {
            int64_t lo[3], hi[3];
            if (grid.range(cavity, cavity.triangles[t], lo, hi) > max_cells_per_cavity_triangle) {
                near[t] = 1;
                continue;
            }
            CellGrid::for_each_cell(lo, hi, [&](uint64_t cell) {
                near[t] |= std::binary_search(marked.begin(), marked.end(), cell);
            });
        }
    });
    progress.check();
    std::vector<uint32_t> near_cavity, far_cavity;
    for (uint32_t t = 0; t < cavity.triangles.size(); ++t) (near[t] ? near_cavity : far_cavity).push_back(t);
    progress.update(0.5);

    if (!near_cavity.empty()) {
        std::vector<Triangle3> outer_triangles;
        outer_triangles.reserve(outer.triangles.size());
        for (const fabvdb::Triangle& t : outer.triangles) outer_triangles.push_back(triangle(outer, t));
        Tree tree(outer_triangles.begin(), outer_triangles.end());
        tree.build();
        mark_touching(tree, cavity, near_cavity, touching, progress);
    }
    if (!large.empty() && !far_cavity.empty()) {
        Tree tree(large.begin(), large.end());
        tree.build();
        mark_touching(tree, cavity, far_cavity, touching, progress);
    }
    progress.update(1.0);
    return touching;
}

}  // namespace fabvdb::volume
