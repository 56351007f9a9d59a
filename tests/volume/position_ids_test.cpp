// Position ids: coincident vertices (also -0.0 against 0.0) share an id, ids
// number distinct positions in lexicographic order, and weld_positions
// renumbers triangles to them, keeping those that become degenerate; on a
// large random cloud with repeats, the same ids as a serial sort gives.
#include "volume/position_ids.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

namespace fabvdb::volume {
namespace {

TEST(PositionIds, CoincidentVerticesShareAnIdInPositionOrder) {
    Mesh mesh;
    mesh.vertices = {{1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {-0.0, 0, 0}};
    const PositionIds ids = position_ids(mesh);
    EXPECT_EQ(ids.count, 3u);
    EXPECT_EQ(ids.id, (std::vector<uint32_t>{2, 0, 2, 1, 0}));
}

TEST(PositionIds, WeldRenumbersTrianglesAndKeepsDegenerateOnes) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 0, 4}, {1, 3, 2}};
    const Mesh welded = weld_positions(mesh);
    EXPECT_EQ(welded.vertices, (std::vector<Vec3>{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}));
    EXPECT_EQ(welded.triangles, (std::vector<Triangle>{{0, 2, 1}, {2, 0, 1}, {2, 2, 1}}));
}

TEST(PositionIds, EmptyMesh) {
    EXPECT_EQ(position_ids(Mesh{}).count, 0u);
    EXPECT_TRUE(weld_positions(Mesh{}).vertices.empty());
}

TEST(PositionIds, LargeCloudAsASerialSort) {
    Mesh cloud;
    std::mt19937 random(3);
    std::uniform_int_distribution<int> coordinate(0, 20);
    for (int i = 0; i < 50000; ++i)
        cloud.vertices.push_back({double(coordinate(random)), double(coordinate(random)), double(coordinate(random))});
    std::vector<Vec3> distinct = cloud.vertices;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const PositionIds ids = position_ids(cloud);
    ASSERT_EQ(ids.count, distinct.size());
    for (size_t v = 0; v < cloud.vertices.size(); ++v)
        ASSERT_EQ(distinct[ids.id[v]], cloud.vertices[v]) << "vertex " << v;
}

}  // namespace
}  // namespace fabvdb::volume
