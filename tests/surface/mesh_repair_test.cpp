// Repair at mesh level keeps the input's triangles: a clean solid comes back
// untouched; an unwelded, partly flipped sphere with duplicate and
// degenerate triangles comes back closed, clean and made of input triangles
// only; a small hole is filled with a faired patch; two crossing boxes come
// back as their union; a zero-area cap is flipped away, not re-meshed; an
// open box is left to the volumetric path. Checked with the test support's own checkers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "support/defect_shapes.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/mesh_repair.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using Corners = std::array<Vec3, 3>;

// A triangle by its corner positions, rotated to start at the smallest.
Corners corners(const Mesh& mesh, const fabvdb::Triangle& t) {
    Corners c{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}

// Every triangle of `out` is a triangle of `in`, in either orientation.
void expect_input_triangles(const Mesh& out, const Mesh& in) {
    std::set<Corners> known;
    for (const auto& t : in.triangles) {
        known.insert(corners(in, t));
        known.insert(corners(in, {t[0], t[2], t[1]}));
    }
    for (const auto& t : out.triangles) EXPECT_TRUE(known.count(corners(out, t))) << "a new triangle";
}

void expect_clean_solid(const Mesh& mesh) {
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(mesh));
    EXPECT_FALSE(fabvdb::test::self_intersects(mesh));
    EXPECT_EQ(fabvdb::test::degenerate_triangle_count(mesh), 0u);
}

TEST(MeshRepair, CleanSolidPassesUntouched) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 3);
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(sphere, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "input");
    EXPECT_TRUE(repaired->fixes.empty());
    EXPECT_EQ(repaired->mesh.vertices, sphere.vertices);
    EXPECT_EQ(repaired->mesh.triangles, sphere.triangles);
}

TEST(MeshRepair, SoupDefectsAreFixedWithTheInputTriangles) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 3);
    // Unwelded (three points per triangle), every third triangle flipped,
    // one duplicated, one degenerate added.
    Mesh soup;
    for (size_t i = 0; i < sphere.triangles.size(); ++i) {
        const auto& t = sphere.triangles[i];
        const uint32_t base = uint32_t(soup.vertices.size());
        for (uint32_t v : t) soup.vertices.push_back(sphere.vertices[v]);
        soup.triangles.push_back(i % 3 == 0 ? fabvdb::Triangle{base, base + 2, base + 1}
                                            : fabvdb::Triangle{base, base + 1, base + 2});
    }
    soup.triangles.push_back(soup.triangles[5]);
    soup.triangles.push_back({0, 1, 0});
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(soup, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "mesh");
    EXPECT_FALSE(repaired->fixes.empty());
    expect_clean_solid(repaired->mesh);
    EXPECT_EQ(repaired->mesh.triangles.size(), sphere.triangles.size());
    EXPECT_NEAR(fabvdb::test::mesh_volume(repaired->mesh), fabvdb::test::mesh_volume(sphere),
                1e-9 * fabvdb::test::mesh_volume(sphere));
    expect_input_triangles(repaired->mesh, sphere);
}

TEST(MeshRepair, InsideOutSolidIsTurned) {
    const Mesh inverted = fabvdb::test::flipped(fabvdb::test::make_sphere({0, 0, 0}, 5.0, 2));
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(inverted, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "mesh");
    expect_clean_solid(repaired->mesh);
    EXPECT_GT(fabvdb::test::mesh_volume(repaired->mesh), 0.0);
}

TEST(MeshRepair, CrossingShellsBecomeTheirUnion) {
    const Mesh boxes = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}),
                                            fabvdb::test::make_box({5.5, 5.25, 5.125}, {15.5, 15.25, 15.125}));
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(boxes, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "mesh");
    expect_clean_solid(repaired->mesh);
    const double overlap = 4.5 * 4.75 * 4.875;
    EXPECT_NEAR(fabvdb::test::mesh_volume(repaired->mesh), 2000.0 - overlap, 1e-9);
}

TEST(MeshRepair, SmallHoleIsFilledKeepingEveryTriangle) {
    // A hole one triangle wide (0.7 mm), under 5% of the diagonal.
    const Mesh sphere = fabvdb::test::make_sphere({0, 0, 0}, 10.0, 4);
    Mesh holed = sphere;
    holed.triangles.erase(holed.triangles.begin() + 40);
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(holed, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "mesh");
    expect_clean_solid(repaired->mesh);
    EXPECT_GE(repaired->mesh.triangles.size(), sphere.triangles.size());
    EXPECT_NE(repaired->fixes.back().find("filled 1 small holes"), std::string::npos) << repaired->fixes.back();
    expect_input_triangles(holed, repaired->mesh);  // every input triangle is still there
}

TEST(MeshRepair, ZeroAreaCapIsFlippedAway) {
    const Mesh capped = fabvdb::test::make_box_with_cap({0, 0, 0}, {10, 10, 10});
    fabvdb::Progress progress;
    const auto repaired = fabvdb::surface::repair_at_mesh_level(capped, progress);
    ASSERT_TRUE(repaired);
    EXPECT_EQ(repaired->path, "mesh");
    ASSERT_EQ(repaired->fixes.size(), 1u);
    EXPECT_NE(repaired->fixes[0].find("1 degenerate triangles"), std::string::npos) << repaired->fixes[0];
    expect_clean_solid(repaired->mesh);
    EXPECT_LE(repaired->mesh.triangles.size(), capped.triangles.size());
    EXPECT_NEAR(fabvdb::test::mesh_volume(repaired->mesh), 1000.0, 1e-9);
}

TEST(MeshRepair, LargeHolesAreLeftToTheVolumetricPath) {
    Mesh open = fabvdb::test::make_box({0, 0, 0}, {10, 10, 10});
    open.triangles.resize(10);
    fabvdb::Progress progress;
    EXPECT_FALSE(fabvdb::surface::repair_at_mesh_level(open, progress));
}

}  // namespace
