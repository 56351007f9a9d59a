// The decomposition's volume pre-computation on boxes whose medial surface
// and depths are known: a 40 × 40 × 8 mm slab is 4 mm deep at most. As a
// shell of ω = 1 mm every inner vertex lies about ω inside, with ω kept; cast
// solid, the inner vertices reach the mid-plane and ω becomes the deepest
// point (4 mm) plus two voxels, not half the longest side (20 mm). A plate
// thinner than the automatic voxel is sampled finer, so voxels lie inside.
#include "volume/low_res_shell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// Distance from p to the surface of the box [lo, hi] when p is inside it.
double depth_in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    double depth = 1e300;
    for (int k = 0; k < 3; ++k) depth = std::min({depth, p[k] - lo[k], hi[k] - p[k]});
    return depth;
}

const Vec3 lo{-20, -20, -4}, hi{20, 20, 4};

TEST(LowResShell, ShellInnerVerticesLieOmegaInside) {
    LowResShellOptions options;
    options.target_triangles = 3000;
    options.thickness = 1.0;
    Progress progress;
    const LowResShell shell = low_res_shell(test::make_box(lo, hi), options, progress);
    EXPECT_EQ(shell.thickness, 1.0);
    ASSERT_EQ(shell.inner.size(), shell.outer.vertices.size());
    ASSERT_EQ(shell.depth.size(), shell.outer.vertices.size());
    EXPECT_GT(shell.outer.triangles.size(), 1000u);
    // Away from the edges (where −∇φ bends) an inner vertex is ω deep.
    size_t checked = 0;
    for (size_t v = 0; v < shell.inner.size(); ++v) {
        const Vec3& p = shell.outer.vertices[v];
        if (std::abs(p[0]) > 15 || std::abs(p[1]) > 15) continue;
        EXPECT_NEAR(depth_in_box(shell.inner[v], lo, hi), 1.0, 0.5 * shell.voxel_size) << v;
        ++checked;
    }
    EXPECT_GT(checked, 100u);
}

TEST(LowResShell, SolidReachesTheMidPlaneAndOmegaIsTheDeepestPoint) {
    LowResShellOptions options;
    options.target_triangles = 3000;
    options.solid = true;
    Progress progress;
    const LowResShell shell = low_res_shell(test::make_box(lo, hi), options, progress);
    EXPECT_NEAR(shell.thickness, 4.0 + 2.0 * shell.voxel_size, 0.5 * shell.voxel_size);
    size_t checked = 0;
    for (size_t v = 0; v < shell.inner.size(); ++v) {
        const Vec3& p = shell.outer.vertices[v];
        if (std::abs(p[0]) > 15 || std::abs(p[1]) > 15) continue;
        EXPECT_NEAR(shell.inner[v][2], 0.0, shell.voxel_size) << v;
        EXPECT_NEAR(shell.depth[v], 4.0, shell.voxel_size) << v;
        ++checked;
    }
    EXPECT_GT(checked, 100u);
}

TEST(LowResShell, PlateThinnerThanTheAutomaticVoxelIsSampledInside) {
    // A 60 × 60 × 0.5 mm plate: at 3000 triangles the automatic voxel
    // (half an edge, about 0.9 mm) would leave no voxel inside it.
    const Vec3 plate_lo{-30, -30, 0}, plate_hi{30, 30, 0.5};
    Progress progress;
    for (bool solid : {false, true}) {
        LowResShellOptions options;
        options.target_triangles = 3000;
        options.thickness = 1.8;
        options.solid = solid;
        options.solid_depth = solid ? 3.6 : 0.0;
        const LowResShell shell = low_res_shell(test::make_box(plate_lo, plate_hi), options, progress);
        EXPECT_LE(shell.voxel_size, 0.5 / 2.0 + 1e-12) << "solid " << solid;
        EXPECT_GT(shell.outer.triangles.size(), 1000u) << "solid " << solid;
        // Each inner vertex lies in the plate, at most half its thickness deep.
        for (size_t v = 0; v < shell.inner.size(); ++v) {
            const Vec3& p = shell.inner[v];
            EXPECT_GE(p[2], -shell.voxel_size) << v;
            EXPECT_LE(p[2], 0.5 + shell.voxel_size) << v;
        }
        if (solid) EXPECT_LT(shell.thickness, 0.25 + 3.0 * shell.voxel_size);
    }
}

TEST(LowResShell, RefusesAnEmptyMeshAndAShellWithoutThickness) {
    Progress progress;
    LowResShellOptions options;
    options.input_name = "empty.stl";
    try {
        low_res_shell(Mesh{}, options, progress);
        ADD_FAILURE() << "an empty mesh was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find("empty.stl"), std::string::npos) << e.what();
    }
    try {
        low_res_shell(test::make_box(lo, hi), options, progress);
        ADD_FAILURE() << "a shell without thickness was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
    }
}

}  // namespace
}  // namespace fabvdb::volume
