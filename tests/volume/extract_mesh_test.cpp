// Extraction of a level set's surface: an analytic sphere level set gives a
// closed, outward-oriented mesh of the sphere's volume with shared vertices.
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
