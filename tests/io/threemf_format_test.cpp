// 3MF: round trip, build-item and component transforms, units, non-zip input.
#include "io/threemf_format.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/io_test_files.h"
#include "support/shapes.h"

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using namespace fabvdb::test;

TEST(ThreemfFormat, RoundTripKeepsTrianglesAndVerticesToAMicrometreThousandth) {
    TempDir dir;
    const Mesh mesh = make_torus({5.5, -3.25, 40.0}, 12.0, 3.0, 32, 16);
    const std::string path = dir.file("torus.3mf");
    fabvdb::io::write_mesh(mesh, path);
    const Mesh back = read(path);
    ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
    EXPECT_EQ(back.triangles, mesh.triangles);
    // lib3mf 1.8 stores single precision printed with 6 decimals (in mm).
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const double x = mesh.vertices[i][k];
            EXPECT_NEAR(back.vertices[i][k], x, 1.1e-6 + 1.2e-7 * std::abs(x));
        }
}

TEST(ThreemfFormat, BuildItemAndComponentTransformsAndUnitAreApplied) {
    // The fixture (centimetres) holds a tetrahedron corner mesh, used once through a
    // components object (component: +10 x; item: 90 degrees about z, then +5 z) and
    // once directly. 3MF transforms act on row vectors: p' = [x y z 1] M.
    const Mesh mesh = read(FABVDB_TEST_DATA_DIR "/io/transformed_components.3mf");
    const std::vector<Vec3> expected_vertices = {{0, 100, 50}, {0, 110, 50}, {-10, 100, 50}, {0, 100, 60},
                                                 {0, 0, 0},    {10, 0, 0},   {0, 10, 0},     {0, 0, 10}};
    ASSERT_EQ(mesh.vertices.size(), expected_vertices.size());
    for (size_t i = 0; i < expected_vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(mesh.vertices[i][k], expected_vertices[i][k], 1e-9) << i;
    const std::vector<Triangle> expected_triangles = {{0, 2, 1}, {0, 1, 3}, {4, 6, 5}, {4, 5, 7}};
    EXPECT_EQ(mesh.triangles, expected_triangles);
}

TEST(ThreemfFormat, AFileThatIsNotAZipIsBadInput) {
    TempDir dir;
    expect_read_error(write_bytes(dir.file("text.3mf"), "solid this is not a zip\n"), FABVDB_ERR_BAD_INPUT,
                      "not a valid 3MF package");
    expect_read_error(write_bytes(dir.file("cut.3mf"), std::string("PK\3\4", 4) + std::string(40, 'x')),
                      FABVDB_ERR_BAD_INPUT, "not a valid 3MF package");
}
