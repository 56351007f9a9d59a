// Tests of the icosphere and the thesis' 162 directions: counts, unit length,
// closed-manifold topology (Euler characteristic 2), antipodal pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "core/icosphere.h"
#include "support/shapes.h"

TEST(Icosphere, CountsAndTopology) {
    for (int splits = 0; splits <= 3; ++splits) {
        const fabvdb::Mesh mesh = fabvdb::unit_icosphere(splits);
        const size_t faces = 20u << (2 * splits);
        EXPECT_EQ(mesh.triangles.size(), faces);
        EXPECT_EQ(mesh.vertices.size(), faces / 2 + 2);
        std::map<std::pair<uint32_t, uint32_t>, int> directed;
        for (const auto& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
        for (const auto& [edge, count] : directed) {
            EXPECT_EQ(count, 1);
            EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);  // every edge has its twin
        }
        EXPECT_GT(fabvdb::test::mesh_volume(mesh), 0.0);  // outward
        EXPECT_LT(fabvdb::test::mesh_volume(mesh), 4.0 / 3.0 * M_PI);
    }
}

TEST(Icosphere, ThesisDirections) {
    const fabvdb::SphereDirections d = fabvdb::thesis_directions();
    ASSERT_EQ(d.directions.size(), 162u);
    for (size_t i = 0; i < d.directions.size(); ++i) {
        const auto& p = d.directions[i];
        EXPECT_NEAR(p[0] * p[0] + p[1] * p[1] + p[2] * p[2], 1.0, 1e-12);
        const auto& q = d.directions[size_t(d.opposite[i])];
        EXPECT_NEAR(p[0] + q[0], 0.0, 1e-12);
        EXPECT_NEAR(p[1] + q[1], 0.0, 1e-12);
        EXPECT_NEAR(p[2] + q[2], 0.0, 1e-12);
        EXPECT_EQ(d.opposite[size_t(d.opposite[i])], int(i));
    }
}
