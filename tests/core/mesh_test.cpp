// The mesh value type's helpers on hand-built cases whose answers are known:
// a unit right tetrahedron (volume 1/6, faces of area 1/2 and √3/2), boxes,
// unused vertices, appended meshes, and the checks of validate_mesh.
#include "core/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb {
namespace {

// Origin and the three unit points, faces outward.
Mesh unit_tetrahedron() {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

TEST(Mesh, BoundingBoxCountsOnlyUsedVerticesUnlessAsked) {
    Mesh mesh = unit_tetrahedron();
    mesh.vertices.push_back({5, -7, 2});  // used by no triangle
    const BoundingBox used = bounding_box(mesh);
    EXPECT_EQ(used.min, (Vec3{0, 0, 0}));
    EXPECT_EQ(used.max, (Vec3{1, 1, 1}));
    EXPECT_DOUBLE_EQ(used.diagonal(), std::sqrt(3.0));
    const BoundingBox all = bounding_box(mesh, false);
    EXPECT_EQ(all.min, (Vec3{0, -7, 0}));
    EXPECT_EQ(all.max, (Vec3{5, 1, 2}));
    EXPECT_DOUBLE_EQ(bounding_box(Mesh{}).diagonal(), 0.0);
}

TEST(Mesh, NormalsAreasAndVolumeOfTheUnitTetrahedron) {
    const Mesh mesh = unit_tetrahedron();
    EXPECT_EQ(triangle_normal(mesh, mesh.triangles[0]), (Vec3{0, 0, -1}));
    EXPECT_DOUBLE_EQ(triangle_area(mesh, mesh.triangles[0]), 0.5);
    EXPECT_NEAR(triangle_area(mesh, mesh.triangles[3]), std::sqrt(3.0) / 2.0, 1e-15);
    EXPECT_NEAR(signed_volume(mesh), 1.0 / 6.0, 1e-15);
    EXPECT_DOUBLE_EQ(six_signed_tetrahedron_volume({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1.0);
    EXPECT_DOUBLE_EQ(squared_distance({1, 2, 3}, {4, 6, 3}), 25.0);
    // The origin's normal sums the cross products of the three faces at it,
    // each twice the face's area long: (−1, −1, −1).
    const std::vector<Vec3> normals = area_weighted_vertex_normals(mesh);
    ASSERT_EQ(normals.size(), 4u);
    EXPECT_EQ(normals[0], (Vec3{-1, -1, -1}));
}

TEST(Mesh, VolumeIsTheSameAboutAnyOriginAndNegativeTurnedInward) {
    Mesh box = test::make_box({10, 20, 30}, {12, 23, 34});
    EXPECT_NEAR(signed_volume(box), 24.0, 1e-12);
    for (Triangle& t : box.triangles) std::swap(t[1], t[2]);
    EXPECT_NEAR(signed_volume(box), -24.0, 1e-12);
}

TEST(Mesh, AppendShiftsTheIndicesOfTheAddedMesh) {
    Mesh to = unit_tetrahedron();
    const Mesh box = test::make_box({2, 0, 0}, {3, 1, 1});
    append(to, box);
    ASSERT_EQ(to.vertices.size(), 4 + box.vertices.size());
    ASSERT_EQ(to.triangles.size(), 4 + box.triangles.size());
    for (size_t i = 0; i < box.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(to.triangles[4 + i][k], box.triangles[i][k] + 4);
    EXPECT_NEAR(signed_volume(to), 1.0 / 6.0 + 1.0, 1e-12);
    Mesh empty;
    append(empty, box);
    EXPECT_EQ(empty.triangles, box.triangles);
}

TEST(Mesh, ValidateNamesTheFileAndTheDefect) {
    validate_mesh(unit_tetrahedron(), "tet.stl");
    const auto expect_defect = [](const Mesh& mesh, const std::string& defect) {
        try {
            validate_mesh(mesh, "tet.stl");
            ADD_FAILURE() << "no error for " << defect;
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
            const std::string message = e.what();
            EXPECT_NE(message.find("tet.stl"), std::string::npos) << message;
            EXPECT_NE(message.find(defect), std::string::npos) << message;
        }
    };
    Mesh not_finite = unit_tetrahedron();
    not_finite.vertices[2][1] = std::numeric_limits<double>::quiet_NaN();
    expect_defect(not_finite, "vertex 3");
    Mesh out_of_range = unit_tetrahedron();
    out_of_range.triangles[1][2] = 4;
    expect_defect(out_of_range, "triangle 2 uses vertex index 4");
}

}  // namespace
}  // namespace fabvdb
