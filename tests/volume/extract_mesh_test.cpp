// Extraction of a level set's surface: an analytic sphere level set gives a
// closed, outward-oriented mesh of the sphere's volume with shared vertices;
// a one-voxel speck beside it is dropped and counted.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include <openvdb/tools/LevelSetSphere.h>

#include "core/error.h"
#include "support/shapes.h"
#include "volume/extract_mesh.h"

namespace {

// Every directed edge appears once and its reverse once: closed, 2-manifold
// along edges and consistently oriented.
bool every_edge_paired(const fabvdb::Mesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        if (count != 1) return false;
        auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end() || reverse->second != 1) return false;
    }
    return true;
}

TEST(ExtractMesh, SphereIsClosedOutwardWithItsVolume) {
    openvdb::initialize();
    const double radius = 10.0, voxel = 0.5;
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(radius), openvdb::Vec3f(1, 2, 3),
                                                                         float(voxel));
    for (double adaptivity : {0.0, 0.5}) {
        fabvdb::Progress progress;
        fabvdb::Mesh mesh = fabvdb::volume::extract_mesh(*grid, adaptivity, progress);
        ASSERT_GT(mesh.triangles.size(), 100u);
        EXPECT_TRUE(every_edge_paired(mesh)) << "adaptivity " << adaptivity;
        // Adaptive meshing trades volume for fewer triangles; uniform keeps it.
        const double exact = 4.0 / 3.0 * M_PI * radius * radius * radius;
        EXPECT_NEAR(fabvdb::test::mesh_volume(mesh), exact, (adaptivity == 0.0 ? 0.01 : 0.15) * exact)
            << "adaptivity " << adaptivity;
        for (const auto& v : mesh.vertices) {
            const double r = std::sqrt((v[0] - 1) * (v[0] - 1) + (v[1] - 2) * (v[1] - 2) + (v[2] - 3) * (v[2] - 3));
            EXPECT_NEAR(r, radius, 0.5 * voxel);
        }
    }
}

TEST(ExtractMesh, ASpeckOfOneVoxelIsDroppedAndCounted) {
    openvdb::initialize();
    // A sphere, and far from it one voxel barely inside (−0.01 voxel) among
    // outside neighbours: its surface is a speck about a hundredth of a
    // voxel across, noise no solid could be.
    const double voxel = 0.5;
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(5.0f, openvdb::Vec3f(0, 0, 0),
                                                                         float(voxel));
    auto access = grid->getAccessor();
    const openvdb::Coord speck(40, 0, 0);
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) access.setValueOn(speck.offsetBy(dx, dy, dz), float(voxel));
    access.setValueOn(speck, float(-0.01 * voxel));
    fabvdb::Progress progress;
    uint64_t dropped = 0;
    const fabvdb::Mesh mesh = fabvdb::volume::extract_mesh(*grid, 0.0, progress, &dropped);
    EXPECT_EQ(dropped, 1u);
    EXPECT_TRUE(every_edge_paired(mesh));
    for (const auto& v : mesh.vertices) EXPECT_LT(v[0], 10.0);
    EXPECT_NEAR(fabvdb::test::mesh_volume(mesh), 4.0 / 3.0 * M_PI * 125.0, 0.02 * 4.0 / 3.0 * M_PI * 125.0);
}

TEST(ExtractMesh, EmptyGridGivesEmptyMesh) {
    openvdb::FloatGrid grid(1.5f);
    fabvdb::Progress progress;
    EXPECT_TRUE(fabvdb::volume::extract_mesh(grid, 0.0, progress).triangles.empty());
}

TEST(ExtractMesh, RejectsAdaptivityOutOfRange) {
    openvdb::FloatGrid grid(1.5f);
    fabvdb::Progress progress;
    EXPECT_THROW(fabvdb::volume::extract_mesh(grid, 1.5, progress), fabvdb::Error);
}

}  // namespace
