// Two-piece molds for the synthetic parts of the acceptance list: a sphere
// split at the equator (two hemispherical shells, cast along +Z and −Z), a
// tilted shell, a flat torus, and both halves in one common mold. Every
// check measures the output itself (support/mold_checks.h): topology by edge
// pairing, self-intersection by CGAL predicates, height fields and insideness
// by the test support's own ray casting, volumes by the divergence theorem
// and by integrating along sampled lines.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/mold_checks.h"
#include "support/mold_shapes.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/mold_assembly.h"
#include "volume/aligned_frame.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

Mesh mirrored_z(Mesh mesh) {
    for (Vec3& p : mesh.vertices) p[2] = -p[2];
    return fabvdb::test::flipped(mesh);
}

void check_mold(const Mesh& part, const Vec3& d, const fabvdb::surface::MoldPair& mold) {
    fabvdb::test::check_two_piece_mold(part, d, {mold.top, mold.bottom, mold.channels});
}

// Rotation taking +Z to the unit vector `axis` (Rodrigues), applied to the mesh.
Mesh rotated_to(Mesh mesh, const Vec3& axis) {
    const Vec3 k{-axis[1], axis[0], 0.0};
    const double s = std::hypot(k[0], k[1]), c = axis[2];
    const Vec3 u{k[0] / s, k[1] / s, 0.0};
    for (Vec3& p : mesh.vertices) {
        const double dot = u[0] * p[0] + u[1] * p[1];
        const Vec3 cross{u[1] * p[2], -u[0] * p[2], u[0] * p[1] - u[1] * p[0]};
        Vec3 q;
        for (int i = 0; i < 3; ++i) q[i] = p[i] * c + cross[i] * s + u[i] * dot * (1 - c);
        p = q;
    }
    return mesh;
}

// The test parts are ~30 mm: an 8 mm margin on a 1.6 mm grid.
fabvdb::surface::MoldOptions small_mold_options() {
    fabvdb::surface::MoldOptions options;
    options.margin = 8.0;
    options.grid_step = 1.6;
    return options;
}

TEST(MoldAssembly, SphereSplitAtTheEquator) {
    const Mesh upper = fabvdb::test::make_dome_shell(15.0, 12.0, 12, 48);
    const Mesh lower = mirrored_z(upper);
    fabvdb::Progress progress;
    const fabvdb::surface::MoldOptions options = small_mold_options();
    {
        SCOPED_TRACE("upper shell along +Z");
        check_mold(upper, {0, 0, 1}, fabvdb::surface::assemble_mold(upper, {0, 0, 1}, options, progress));
    }
    {
        SCOPED_TRACE("lower shell along -Z");
        check_mold(lower, {0, 0, -1}, fabvdb::surface::assemble_mold(lower, {0, 0, -1}, options, progress));
    }
}

TEST(MoldAssembly, TiltedShell) {
    const Vec3 axis{0.48, -0.6, 0.64};
    const Mesh shell = rotated_to(fabvdb::test::make_dome_shell(15.0, 12.0, 10, 40), axis);
    fabvdb::Progress progress;
    const fabvdb::surface::MoldOptions options = small_mold_options();
    check_mold(shell, axis, fabvdb::surface::assemble_mold(shell, axis, options, progress));
}

TEST(MoldAssembly, FlatTorus) {
    const Mesh torus = fabvdb::test::make_torus({1, 2, 3}, 14.0, 4.0, 48, 16);
    fabvdb::Progress progress;
    const fabvdb::surface::MoldOptions options = small_mold_options();
    check_mold(torus, {0, 0, 1}, fabvdb::surface::assemble_mold(torus, {0, 0, 1}, options, progress));
}

TEST(MoldAssembly, CommonMoldForTheTwoHalvesOfASphere) {
    const Mesh upper = fabvdb::test::make_dome_shell(15.0, 12.0, 12, 48);
    const Mesh lower = mirrored_z(upper);
    fabvdb::Progress progress;
    const fabvdb::surface::MoldOptions options = small_mold_options();
    std::vector<Vec3> offsets;
    const auto mold =
        fabvdb::surface::assemble_common_mold({upper, lower}, {{0, 0, 1}, {0, 0, -1}}, options, progress, offsets);
    ASSERT_EQ(offsets.size(), 2u);
    ASSERT_EQ(mold.gates.size(), 2u);
    // The parts where the mold says they are: turned to +Z, then moved.
    Mesh row;
    const Vec3 directions[2] = {{0, 0, 1}, {0, 0, -1}};
    for (int p = 0; p < 2; ++p) {
        Mesh placed = fabvdb::volume::rotate_mesh(p == 0 ? upper : lower, fabvdb::volume::aligned_frame(directions[p]),
                                                  false);
        for (Vec3& v : placed.vertices) v = {v[0] + offsets[p][0], v[1] + offsets[p][1], v[2] + offsets[p][2]};
        row = fabvdb::test::merged(row, placed);
    }
    fabvdb::test::check_two_piece_mold(row, {0, 0, 1}, {mold.top, mold.bottom, mold.channels});
}

// A lens (a ring of 96 vertices between two apexes, 20 mm across) whose
// silhouette is flattened at its extreme −x onto the plane x = −10, every
// other vertex of the flat a float step off it, as the contour vertices of
// a part meshed on a voxel grid the mold frame keeps (fertility at
// --voxel 0.4295mm). With the block grid lines a whole number of steps
// from the part's bounding box, one line lay in that plane and the exact
// booleans left slivers an ulp wide: the top piece could not be rounded to
// float coordinates (an INTERNAL error).
Mesh lens_with_a_flat_an_ulp_thick() {
    const int n = 96;
    const double x_flat = -10.0;
    const double ulp = std::nextafter(x_flat, 0.0) - x_flat;
    Mesh lens;
    for (int k = 0; k < n; ++k) {
        const double angle = 2 * M_PI * k / n;
        double x = 10 * std::cos(angle);
        if (x < -10 * std::cos(0.3)) x = x_flat + (k % 2 ? ulp : 0.0);
        lens.vertices.push_back({x, 10 * std::sin(angle), 0.3 * std::sin(5 * angle)});
    }
    lens.vertices.push_back({0.3, 0.2, 6.0});
    lens.vertices.push_back({-0.2, 0.1, -6.0});
    const uint32_t top = n, bottom = n + 1;
    for (uint32_t k = 0; k < uint32_t(n); ++k) {
        const uint32_t next = (k + 1) % n;
        lens.triangles.push_back({k, next, top});
        lens.triangles.push_back({next, k, bottom});
    }
    return lens;
}

TEST(MoldAssembly, SilhouetteInAPlaneWithinAFloatStep) {
    const Mesh lens = lens_with_a_flat_an_ulp_thick();
    fabvdb::Progress progress;
    for (const double step : {1.6, 1.0}) {
        SCOPED_TRACE("grid step " + std::to_string(step));
        fabvdb::surface::MoldOptions options = small_mold_options();
        options.grid_step = step;
        check_mold(lens, {0, 0, 1}, fabvdb::surface::assemble_mold(lens, {0, 0, 1}, options, progress));
    }
}

TEST(MoldAssembly, PartThatIsNotAHeightFieldIsRefused) {
    const Mesh ring = fabvdb::test::make_standing_torus(14.0, 4.0, 32, 12);
    fabvdb::Progress progress;
    try {
        fabvdb::surface::assemble_mold(ring, {0, 0, 1}, {}, progress);
        FAIL() << "expected a bad-input error";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find("swept"), std::string::npos) << e.what();
    }
}

TEST(MoldAssembly, CancelledAssemblyThrowsCancelled) {
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::surface::assemble_mold(fabvdb::test::make_dome_shell(15, 12, 6, 24), {0, 0, 1}, {}, progress);
        FAIL() << "expected cancellation";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
