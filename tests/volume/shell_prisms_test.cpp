// shell_prisms on level sets whose medial axis is known: a sphere (the
// inner ends lie on the radius, ω below the surface; the medial depth is the
// radius, reached at the centre) and a slab 2 mm thick (the medial surface
// is its mid-plane, depth 1). Checked: thick and thin (ω beyond the medial
// depth) prisms, the cap at max_depth, a vertex outside the band, an empty
// input and cancellation.
#include "volume/shell_prisms.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <openvdb/tools/LevelSetSphere.h>

#include "core/error.h"
#include "support/check_vec3.h"
#include "support/plain_level_set.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

const Vec3 centre = {0.3, -0.2, 0.1};
constexpr double radius = 5.0;
constexpr double voxel = 0.5;

// The sphere's level set with its band over the whole inside (and 6 mm out).
openvdb::FloatGrid::Ptr sphere_grid() {
    openvdb::initialize();
    return openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        float(radius), openvdb::Vec3f(float(centre[0]), float(centre[1]), float(centre[2])), float(voxel), 12.0f);
}

double distance(const Vec3& a, const Vec3& b) { return std::sqrt(squared_distance(a, b)); }

// How far p lies off the line through the centre and q.
double off_radius(const Vec3& p, const Vec3& q) {
    return test::norm(test::cross(test::sub(p, centre), test::sub(q, centre))) / distance(q, centre);
}

TEST(ShellPrisms, SphereInnerEndsLieThicknessBelowAlongTheRadius) {
    const auto grid = sphere_grid();
    const Mesh sphere = test::make_sphere(centre, radius, 2);
    Progress progress;
    const ShellPrisms prisms = shell_prisms(*grid, sphere.vertices, 1.0, 10.0, progress);
    ASSERT_EQ(prisms.inner.size(), sphere.vertices.size());
    ASSERT_EQ(prisms.depth.size(), sphere.vertices.size());
    for (size_t v = 0; v < sphere.vertices.size(); ++v) {
        // The first quarter-voxel step at φ <= −1: radius 4, a step under at most.
        const double r = distance(prisms.inner[v], centre);
        EXPECT_LE(r, radius - 1.0 + 0.02) << "vertex " << v;
        EXPECT_GE(r, radius - 1.0 - 0.25 * voxel - 0.02) << "vertex " << v;
        EXPECT_LT(off_radius(prisms.inner[v], sphere.vertices[v]), 0.05) << "vertex " << v;
        // The descent goes on to the centre: the depth is the radius, less
        // what trilinear sampling loses within a voxel of the centre.
        EXPECT_LE(prisms.depth[v], radius + 1e-4) << "vertex " << v;
        EXPECT_GE(prisms.depth[v], radius - voxel) << "vertex " << v;
    }
}

TEST(ShellPrisms, ThinnerThanTwiceTheThicknessStopsAtTheCentre) {
    const auto grid = sphere_grid();
    const Mesh sphere = test::make_sphere(centre, radius, 1);
    Progress progress;
    const ShellPrisms prisms = shell_prisms(*grid, sphere.vertices, 7.0, 10.0, progress);
    for (size_t v = 0; v < sphere.vertices.size(); ++v) {
        EXPECT_LT(distance(prisms.inner[v], centre), voxel) << "vertex " << v;
        EXPECT_GE(prisms.depth[v], radius - voxel) << "vertex " << v;
        EXPECT_LE(prisms.depth[v], radius + 1e-4) << "vertex " << v;
    }
}

TEST(ShellPrisms, DepthIsCappedAtMaxDepth) {
    const auto grid = sphere_grid();
    const Mesh sphere = test::make_sphere(centre, radius, 1);
    Progress progress;
    const ShellPrisms prisms = shell_prisms(*grid, sphere.vertices, 1.0, 2.0, progress);
    for (size_t v = 0; v < sphere.vertices.size(); ++v) {
        EXPECT_EQ(prisms.depth[v], 2.0) << "vertex " << v;
        // The inner end is still the one at φ = −1, found on the way.
        EXPECT_NEAR(distance(prisms.inner[v], centre), radius - 1.0, 0.25 * voxel + 0.02) << "vertex " << v;
    }
    // Deeper than the cap is asked for but the prism ends first: the descent
    // stops at the cap, before φ = −3, so the inner end is where it stopped.
    const ShellPrisms shallow = shell_prisms(*grid, sphere.vertices, 3.0, 2.0, progress);
    for (size_t v = 0; v < sphere.vertices.size(); ++v) {
        EXPECT_EQ(shallow.depth[v], 2.0) << "vertex " << v;
        EXPECT_NEAR(distance(shallow.inner[v], centre), radius - 2.0, 0.25 * voxel + 0.02) << "vertex " << v;
    }
}

TEST(ShellPrisms, VertexOutsideTheBandStaysWithNoDepth) {
    const auto grid = sphere_grid();
    const std::vector<Vec3> far = {{centre[0] + 20.0, centre[1], centre[2]}, {-30.0, 40.0, 5.0}};
    Progress progress;
    const ShellPrisms prisms = shell_prisms(*grid, far, 1.0, 10.0, progress);
    for (size_t v = 0; v < far.size(); ++v) {
        EXPECT_EQ(prisms.inner[v], far[v]);
        EXPECT_EQ(prisms.depth[v], 0.0);
    }
    EXPECT_TRUE(shell_prisms(*grid, {}, 1.0, 10.0, progress).inner.empty());
}

TEST(ShellPrisms, SlabPrismsMeetAtTheMidPlane) {
    // A slab 2 mm thick (z in [0, 2]) with a 3-voxel band of 0.5 mm voxels:
    // the band covers its inside. Far from its rim the gradient is ±z.
    const auto grid = test::plain_level_set(test::make_box({0, 0, 0}, {20, 20, 2}), voxel);
    const std::vector<Vec3> faces = {{10, 10, 2}, {7.3, 11.1, 2}, {9, 8, 0}};
    Progress progress;
    // ω = 1.5 > 1: thin, so the prisms end on the mid-plane z = 1.
    const ShellPrisms thin = shell_prisms(*grid, faces, 1.5, 5.0, progress);
    // ω = 0.5: the inner ends lie 0.5 below the face; the depth is still 1.
    const ShellPrisms thick = shell_prisms(*grid, faces, 0.5, 5.0, progress);
    for (size_t v = 0; v < faces.size(); ++v) {
        const double inward = faces[v][2] > 1.0 ? -1.0 : 1.0;
        EXPECT_NEAR(thin.inner[v][2], 1.0, 0.25 * voxel) << "vertex " << v;
        EXPECT_NEAR(thin.depth[v], 1.0, 0.05) << "vertex " << v;
        EXPECT_LE(inward * (thick.inner[v][2] - (faces[v][2] + inward * 0.5)), 0.25 * voxel + 1e-6) << "vertex " << v;
        EXPECT_GE(inward * (thick.inner[v][2] - (faces[v][2] + inward * 0.5)), -1e-6) << "vertex " << v;
        EXPECT_NEAR(thick.depth[v], 1.0, 0.05) << "vertex " << v;
        for (const ShellPrisms* p : {&thin, &thick}) {
            EXPECT_NEAR(p->inner[v][0], faces[v][0], 1e-3) << "vertex " << v;
            EXPECT_NEAR(p->inner[v][1], faces[v][1], 1e-3) << "vertex " << v;
        }
    }
}

TEST(ShellPrisms, CancelledThrows) {
    const auto grid = sphere_grid();
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        shell_prisms(*grid, test::make_sphere(centre, radius, 2).vertices, 1.0, 10.0, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
