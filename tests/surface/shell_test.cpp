// make_shell on hand-built surfaces: a box's normals, unit-cube areas and
// edge neighbours are those of its faces; an open, non-manifold or
// inconsistently oriented surface, mismatched inner vertices or thin labels,
// an empty or flat surface are refused with BAD_INPUT naming the input.
#include "surface/shell.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

Shell box_shell(const Mesh& outer) {
    return make_shell(outer, outer.vertices, std::vector<int>(outer.triangles.size(), -1), 1.0, "box.stl");
}

void expect_refused(const Mesh& outer, std::vector<Vec3> inner, std::vector<int> thin, const std::string& defect) {
    SCOPED_TRACE(defect);
    try {
        make_shell(outer, std::move(inner), std::move(thin), 1.0, "box.stl");
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        const std::string message = e.what();
        EXPECT_NE(message.find("box.stl"), std::string::npos) << message;
        EXPECT_NE(message.find(defect), std::string::npos) << message;
    }
}

TEST(Shell, ABoxHasItsFacesNormalsAreasAndNeighbours) {
    // 4 × 2 × 1 mm: the longest side is 4, so unit-cube areas are mm² / 16.
    const Mesh outer = test::make_box({0, 0, 0}, {4, 2, 1});
    const Shell shell = box_shell(outer);
    EXPECT_DOUBLE_EQ(shell.unit_scale, 0.25);
    ASSERT_EQ(shell.triangle_count(), 12u);
    double area = 0;
    for (size_t t = 0; t < 12; ++t) {
        const Vec3& n = shell.normal[t];
        // Axis-aligned unit normal pointing away from the box's centre.
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
        EXPECT_NEAR(std::abs(n[axis]), 1.0, 1e-12) << t;
        const Triangle& f = outer.triangles[t];
        const double centre[3] = {2, 1, 0.5};
        double side = 0;
        for (uint32_t v : f) side += (outer.vertices[v][axis] - centre[axis]) / 3.0;
        EXPECT_GT(side * n[axis], 0.0) << t;
        area += shell.area[t];
        // The neighbour across each edge holds that edge the other way round.
        for (int k = 0; k < 3; ++k) {
            const int other = shell.neighbor[t][k];
            ASSERT_GE(other, 0);
            const Triangle& g = outer.triangles[size_t(other)];
            bool twin = false;
            for (int j = 0; j < 3; ++j) twin = twin || (g[j] == f[(k + 1) % 3] && g[(j + 1) % 3] == f[k]);
            EXPECT_TRUE(twin) << t << " edge " << k;
        }
    }
    EXPECT_NEAR(area, 2.0 * (8 + 4 + 2) / 16.0, 1e-12);
    EXPECT_EQ(shell.thickness, 1.0);
    EXPECT_FALSE(shell.solid);
}

TEST(Shell, RefusesWhatIsNotAClosedOrientedSurface) {
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    const std::vector<int> thin(12, -1);
    Mesh open = box;
    open.triangles.pop_back();
    expect_refused(open, open.vertices, std::vector<int>(11, -1), "not closed");
    Mesh flipped = box;
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    expect_refused(flipped, flipped.vertices, thin, "inconsistently oriented");
    Mesh doubled = box;
    doubled.triangles.push_back(box.triangles[0]);
    expect_refused(doubled, doubled.vertices, std::vector<int>(13, -1), "non-manifold");
    expect_refused(box, std::vector<Vec3>(3), thin, "do not match");
    expect_refused(box, box.vertices, std::vector<int>(5, -1), "do not match");
    expect_refused(Mesh{}, {}, {}, "empty");
    Mesh point = box;
    for (Vec3& p : point.vertices) p = {1, 1, 1};
    expect_refused(point, point.vertices, thin, "no extent");
}

}  // namespace
}  // namespace fabvdb::surface
