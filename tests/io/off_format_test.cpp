// OFF: round trip, header layouts, comments, face colours, polygons.
#include "io/off_format.h"

#include <gtest/gtest.h>

#include "io/io_test_files.h"
#include "support/shapes.h"

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using namespace fabvdb::test;

TEST(OffFormat, RoundTripKeepsEveryVertexAndTriangleExactly) {
    TempDir dir;
    Mesh mesh = make_torus({-3.75, 0.1, 7e-3}, 10.0, 2.5, 24, 12);
    mesh.vertices.push_back({-1e-300, 1e300, 0.1});
    const std::string path = dir.file("torus.off");
    fabvdb::io::write_mesh(mesh, path);
    const Mesh back = read(path);
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(OffFormat, CommentsCountsOnTheKeywordLineColoursAndPolygons) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("square.off"),
                                         "# exported by hand\n"
                                         "OFF 5 2 0   # counts on the keyword line\n"
                                         "\n"
                                         "0 0 0\n1 0 0   # a comment after a vertex\n"
                                         "1 1 0\n0 1 0\n"
                                         "# a comment between vertices and faces\n"
                                         "0.5 0.5 1\n"
                                         "4 0 1 2 3 255 0 0\n"
                                         "3 0 1 4 0.5 0.5 0.5 1.0\n");
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices.size(), 5u);
    EXPECT_EQ(mesh.vertices[4], (Vec3{0.5, 0.5, 1}));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(mesh.triangles[2], (Triangle{0, 1, 4}));
}

TEST(OffFormat, ColouredVerticesOfCoffAreIgnored) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("coloured.off"),
                                         "COFF\r\n3 1 0\r\n0 0 0 255 0 0 255\r\n1 0 0 0 255 0 255\r\n"
                                         "0 1 0 0 0 255 255\r\n3 2 1 0\r\n");
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices[1], (Vec3{1, 0, 0}));
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{2, 1, 0}));
}

TEST(OffFormat, MalformedFilesAreRejected) {
    TempDir dir;
    expect_read_error(write_bytes(dir.file("keyword.off"), "PLY\n3 1 0\n"), FABVDB_ERR_BAD_INPUT,
                      "expected the 'OFF' keyword");
    expect_read_error(write_bytes(dir.file("few.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n"), FABVDB_ERR_BAD_INPUT,
                      "file ends after 2 of 3 vertices");
    expect_read_error(write_bytes(dir.file("index.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
                      FABVDB_ERR_BAD_INPUT, "line 6: face corner 3 is out of range (3 vertices)");
    expect_read_error(write_bytes(dir.file("huge.off"), "OFF\n2000000000 2000000000 0\n0 0 0\n"),
                      FABVDB_ERR_BAD_INPUT, "file ends after 1 of 2000000000 vertices");
}
