// The bound on the winding number's gradient counts only the edges that do not
// cancel, is 0 for closed shells, and is never under the gradient measured by
// central differences of the exact winding number.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/shapes.h"
#include "volume/edge_table.h"
#include "volume/position_ids.h"
#include "volume/winding_gradient_bound.h"
#include "volume/winding_number.h"

namespace {

using fabvdb::BoundingBox;
using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::volume::WindingGradientBound;
using fabvdb::volume::WindingNumber;

BoundingBox cube_at(const Vec3& c, double half) {
    return {{c[0] - half, c[1] - half, c[2] - half}, {c[0] + half, c[1] + half, c[2] + half}};
}

WindingGradientBound bound_of(const Mesh& mesh) {
    const Mesh welded = fabvdb::volume::weld_positions(mesh);
    return WindingGradientBound(welded, fabvdb::volume::build_edge_table(welded));
}

Mesh open_box() { return fabvdb::test::make_open_box({0, 0, 0}, {10, 10, 10}); }

TEST(WindingGradientBound, ClosedShellsHaveNoBoundary) {
    const Mesh shells = fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 5.0, 3),
                                             fabvdb::test::unwelded(fabvdb::test::make_box({2, 2, 2}, {9, 9, 9})));
    const WindingGradientBound bound = bound_of(shells);
    EXPECT_EQ(bound.boundary_edge_count(), 0u);
    EXPECT_EQ(bound(cube_at({1, 1, 1}, 0.5), 1e9), 0.0);
}

TEST(WindingGradientBound, SharedEdgesCancelOnlyWhenConsistent) {
    Mesh square;
    square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(bound_of(square).boundary_edge_count(), 4u);
    square.triangles[1] = {0, 3, 2};  // the diagonal now runs the same way twice
    EXPECT_EQ(bound_of(square).boundary_edge_count(), 5u);
    square.triangles.push_back({1, 1, 2});  // zero area: skipped, as the winding number skips it
    EXPECT_EQ(bound_of(square).boundary_edge_count(), 5u);
}

TEST(WindingGradientBound, IsInfiniteOnAnEdgeAndStopsAtTheCap) {
    const WindingGradientBound bound = bound_of(open_box());
    EXPECT_EQ(bound.boundary_edge_count(), 4u);
    EXPECT_TRUE(std::isinf(bound(cube_at({5, 0, 10}, 0.1), 1e9)));
    const double near = bound(cube_at({5, -0.01, 10.01}, 0.001), 1.0);
    EXPECT_GE(near, 1.0);
    EXPECT_LT(bound(cube_at({5, 5, 40}, 1.0), 1e9), near);
}

TEST(WindingGradientBound, NeverUnderTheMeasuredGradient) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-6.0, 16.0), offset(-1.0, 1.0);
    Mesh soup = open_box();
    // A few loose triangles, each all boundary.
    soup = fabvdb::test::merged(soup, fabvdb::test::loose_triangles({{Vec3{12, 0, 0}, Vec3{14, 1, 0}, Vec3{12, 3, 2}},
                                                                     {Vec3{-3, 5, 5}, Vec3{-3, 8, 5}, Vec3{-4, 6, 9}}}));
    const WindingNumber winding(soup);
    const WindingGradientBound bound = bound_of(soup);
    const double h = 1e-5;
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 centre{coordinate(random), coordinate(random), coordinate(random)};
        const BoundingBox box = cube_at(centre, 0.5);
        const double limit = bound(box, 1e9);
        for (int j = 0; j < 5; ++j) {
            const Vec3 q{centre[0] + 0.5 * offset(random), centre[1] + 0.5 * offset(random),
                         centre[2] + 0.5 * offset(random)};
            double squared = 0.0;
            for (int axis = 0; axis < 3; ++axis) {
                Vec3 a = q, b = q;
                a[axis] -= h;
                b[axis] += h;
                const double g = (winding.exact(b) - winding.exact(a)) / (2 * h);
                squared += g * g;
            }
            // A difference across a face jumps by 1/2h: such a point lies on the surface.
            if (squared > 1e6) continue;
            EXPECT_LE(std::sqrt(squared), limit * (1 + 1e-6) + 1e-6) << q[0] << " " << q[1] << " " << q[2];
            ++checked;
        }
    }
    EXPECT_GT(checked, 1400);
}

}  // namespace
