// Shells of a mesh: components of triangles sharing vertex indices, numbered
// by their first triangle, with signed volumes by hand; sub_mesh keeps only
// the vertices used; dropping small shells removes solids and voids under the
// threshold in magnitude, and flat sheets, and leaves the mesh as it is when
// none is.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "volume/mesh_shells.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using fabvdb::test::flipped;
using fabvdb::test::make_box;
using fabvdb::test::merged;
using fabvdb::volume::split_shells;

std::vector<uint32_t> range(uint32_t begin, uint32_t end) {
    std::vector<uint32_t> out;
    for (uint32_t i = begin; i < end; ++i) out.push_back(i);
    return out;
}

TEST(MeshShells, BoxesWithTheirSignedVolumes) {
    // 2 x 3 x 4 facing out, then 1 x 1 x 1 facing in, inside it.
    const Mesh mesh = merged(make_box({0, 0, 0}, {2, 3, 4}), flipped(make_box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5})));
    const auto shells = split_shells(mesh);
    ASSERT_EQ(shells.size(), 2u);
    EXPECT_EQ(shells[0].triangles, range(0, 12));
    EXPECT_NEAR(shells[0].volume, 24.0, 1e-12);
    EXPECT_EQ(shells[1].triangles, range(12, 24));
    EXPECT_NEAR(shells[1].volume, -1.0, 1e-12);
}

TEST(MeshShells, NumberedByTheirFirstTriangle) {
    // Triangles of a (volume 1) and b (volume 8) alternate, b's first.
    const Mesh both = merged(make_box({0, 0, 0}, {1, 1, 1}), make_box({5, 5, 5}, {7, 7, 7}));
    Mesh mesh;
    mesh.vertices = both.vertices;
    for (size_t t = 0; t < 12; ++t) {
        mesh.triangles.push_back(both.triangles[12 + t]);
        mesh.triangles.push_back(both.triangles[t]);
    }
    const auto shells = split_shells(mesh);
    ASSERT_EQ(shells.size(), 2u);
    std::vector<uint32_t> even, odd;
    for (uint32_t t = 0; t < 24; ++t) (t % 2 ? odd : even).push_back(t);
    EXPECT_EQ(shells[0].triangles, even);
    EXPECT_NEAR(shells[0].volume, 8.0, 1e-12);
    EXPECT_EQ(shells[1].triangles, odd);
    EXPECT_NEAR(shells[1].volume, 1.0, 1e-12);
}

TEST(MeshShells, ASharedVertexJoinsAnEqualPositionDoesNot) {
    const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
    const Mesh b = make_box({1, 1, 1}, {2, 2, 2});  // b's vertex 0 is at a's vertex 7
    EXPECT_EQ(split_shells(merged(a, b)).size(), 2u);
    Mesh joined = merged(a, b);
    for (Triangle& t : joined.triangles)
        for (uint32_t& v : t)
            if (v == 8) v = 7;
    const auto shells = split_shells(joined);
    ASSERT_EQ(shells.size(), 1u);
    EXPECT_EQ(shells[0].triangles, range(0, 24));
    EXPECT_NEAR(shells[0].volume, 2.0, 1e-12);
}

TEST(MeshShells, UnusedVerticesAndEmptyMesh) {
    EXPECT_TRUE(split_shells(Mesh{}).empty());
    Mesh mesh = make_box({0, 0, 0}, {1, 1, 1});
    mesh.vertices.insert(mesh.vertices.begin(), Vec3{9, 9, 9});
    for (Triangle& t : mesh.triangles)
        for (uint32_t& v : t) ++v;
    mesh.vertices.push_back({-9, -9, -9});
    EXPECT_EQ(split_shells(mesh).size(), 1u);
    Mesh only_points;
    only_points.vertices = {{0, 0, 0}, {1, 1, 1}};
    EXPECT_TRUE(split_shells(only_points).empty());
}

TEST(SubMesh, KeepsOnlyTheUsedVerticesInOrderOfUse) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}};
    mesh.triangles = {{0, 1, 2}, {5, 3, 1}, {2, 3, 4}, {3, 5, 4}};
    const Mesh sub = fabvdb::volume::sub_mesh(mesh, {3, 1});
    EXPECT_EQ(sub.vertices, (std::vector<Vec3>{{3, 0, 0}, {5, 0, 0}, {4, 0, 0}, {1, 0, 0}}));
    EXPECT_EQ(sub.triangles, (std::vector<Triangle>{{0, 1, 2}, {1, 0, 3}}));
    const Mesh none = fabvdb::volume::sub_mesh(mesh, {});
    EXPECT_TRUE(none.vertices.empty());
    EXPECT_TRUE(none.triangles.empty());
}

TEST(DropSmallOrFlatShells, SolidsAndVoidsUnderTheThresholdGo) {
    // A 4 x 4 x 4 solid (64) with a 2 x 2 x 2 void (-8) and a 0.5³ void
    // (-0.125) inside, and a separate 0.5 x 0.5 x 1 solid (0.25).
    Mesh mesh = merged(make_box({0, 0, 0}, {4, 4, 4}), flipped(make_box({1, 1, 1}, {3, 3, 3})));
    mesh = merged(mesh, flipped(make_box({3.25, 3.25, 3.25}, {3.75, 3.75, 3.75})));
    mesh = merged(mesh, make_box({10, 0, 0}, {10.5, 0.5, 1}));
    Mesh dropped = mesh;
    const auto counts = fabvdb::volume::drop_small_or_flat_shells(dropped, 0.5);
    EXPECT_EQ(counts.kept, 2u);
    EXPECT_EQ(counts.dropped, 2u);
    EXPECT_EQ(dropped.triangles.size(), 24u);
    EXPECT_EQ(dropped.vertices.size(), 16u);
    EXPECT_NEAR(fabvdb::test::mesh_volume(dropped), 64.0 - 8.0, 1e-12);
    // What is left is the first two boxes' triangles, in order, on the same positions.
    for (size_t t = 0; t < 24; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(dropped.vertices[dropped.triangles[t][k]], mesh.vertices[mesh.triangles[t][k]]);
}

TEST(DropSmallOrFlatShells, MagnitudeAgainstTheThreshold) {
    // Unit boxes, one facing out (+1) and one in (-1): both just above 0.999,
    // both just under 1.001.
    const Mesh pair = merged(make_box({0, 0, 0}, {1, 1, 1}), flipped(make_box({3, 0, 0}, {4, 1, 1})));
    Mesh mesh = pair;
    auto counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 0.999);
    EXPECT_EQ(counts.kept, 2u);
    EXPECT_EQ(counts.dropped, 0u);
    EXPECT_EQ(mesh.triangles.size(), 24u);
    counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 1.001);
    EXPECT_EQ(counts.kept, 0u);
    EXPECT_EQ(counts.dropped, 2u);
    EXPECT_TRUE(mesh.triangles.empty());
    // A threshold of 0 keeps everything.
    mesh = pair;
    counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 0.0);
    EXPECT_EQ(counts.kept, 2u);
    EXPECT_EQ(counts.dropped, 0u);
}

TEST(DropSmallOrFlatShells, NothingDroppedLeavesTheMeshAsItIs) {
    Mesh mesh = make_box({0, 0, 0}, {2, 2, 2});
    mesh.vertices.push_back({100, 100, 100});  // unused: sub_mesh would drop it
    const Mesh before = mesh;
    const auto counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 1.0);
    EXPECT_EQ(counts.kept, 1u);
    EXPECT_EQ(counts.dropped, 0u);
    EXPECT_EQ(mesh.vertices, before.vertices);
    EXPECT_EQ(mesh.triangles, before.triangles);
}

TEST(DropSmallOrFlatShells, EverythingCanGo) {
    Mesh mesh = merged(make_box({0, 0, 0}, {1, 1, 1}), make_box({2, 0, 0}, {3, 1, 1}));
    const auto counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 10.0);
    EXPECT_EQ(counts.kept, 0u);
    EXPECT_EQ(counts.dropped, 2u);
    EXPECT_TRUE(mesh.triangles.empty());
    EXPECT_TRUE(mesh.vertices.empty());
}

TEST(DropSmallOrFlatShells, FlatSheetsGoCrumbsAndSlabsStay) {
    // Beside a 100 mm box (diagonal 173 mm, so flat is under 0.0173 mm thick):
    // a 5 x 5 x 0.005 mm sheet (2V/A about 0.005 mm) is flat; a 5 x 5 x 0.05
    // mm slab is not; a 0.001 mm cube is thinner still but no sheet (its
    // thickness is not under 1% of its own size).
    const Mesh box = make_box({0, 0, 0}, {100, 100, 100});
    const Mesh sheet = make_box({120, 0, 0}, {125, 5, 0.005});
    const Mesh slab = make_box({130, 0, 0}, {135, 5, 0.05});
    const Mesh crumb = make_box({140, 0, 0}, {140.001, 0.001, 0.001});
    Mesh mesh = merged(merged(box, sheet), merged(slab, crumb));
    const double diagonal = fabvdb::bounding_box(mesh).diagonal();
    const auto shells = split_shells(mesh);
    ASSERT_EQ(shells.size(), 4u);
    EXPECT_FALSE(fabvdb::volume::is_flat_shell(mesh, shells[0], diagonal));
    EXPECT_TRUE(fabvdb::volume::is_flat_shell(mesh, shells[1], diagonal));
    EXPECT_FALSE(fabvdb::volume::is_flat_shell(mesh, shells[2], diagonal));
    EXPECT_FALSE(fabvdb::volume::is_flat_shell(mesh, shells[3], diagonal));
    const auto counts = fabvdb::volume::drop_small_or_flat_shells(mesh, 0.0);
    EXPECT_EQ(counts.kept, 3u);
    EXPECT_EQ(counts.dropped, 1u);
    EXPECT_NEAR(fabvdb::test::mesh_volume(mesh), 1e6 + 5 * 5 * 0.05 + 1e-9, 1e-6);
}

}  // namespace
