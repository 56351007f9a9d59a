// OBJ: round trip, relative indices, corner forms, continuations, ignored records.
#include "io/obj_format.h"

#include <gtest/gtest.h>

#include "io/io_test_files.h"
#include "support/shapes.h"

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using namespace fabvdb::test;

TEST(ObjFormat, RoundTripKeepsEveryVertexAndTriangleExactly) {
    TempDir dir;
    Mesh mesh = make_sphere({1.0 / 3.0, -2.5e-7, 1e5}, 12.345678901234567, 2);
    mesh.vertices.push_back({0.1, 0.2, 0.3});  // unreferenced: must survive
    const std::string path = dir.file("sphere.obj");
    fabvdb::io::write_mesh(mesh, path);
    const Mesh back = read(path);
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(ObjFormat, NegativeIndicesCountBackFromTheLastVertex) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("relative.obj"),
                                         "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                                         "v 0 0 1\nf -4 -1 -3\n");
    const Mesh mesh = read(path);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (Triangle{0, 3, 1}));
}

TEST(ObjFormat, CornerFormsPolygonsContinuationsAndIgnoredRecords) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("forms.OBJ"),
                                         "# a comment\r\n"
                                         "mtllib missing.mtl\r\n"
                                         "o thing\r\ng part\r\ns 1\r\nusemtl red\r\n"
                                         "v 0 0 0 1\r\nv 2 0 0\r\nv 2 2 0\r\nv 0 2 0\r\nv 9 9 9\r\n"
                                         "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\n"
                                         "f 1/1/1 2/2/1 3//1 \\\r\n  4/1\r\n"
                                         "f 1 2 \\\n3   # comment after a face\n"
                                         "l 1 2\n");
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices.size(), 5u);
    EXPECT_EQ(mesh.vertices[2], (Vec3{2, 2, 0}));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(mesh.triangles[2], (Triangle{0, 1, 2}));
}

TEST(ObjFormat, BadIndicesAreRejectedWithTheLine) {
    TempDir dir;
    expect_read_error(write_bytes(dir.file("zero.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
                      FABVDB_ERR_BAD_INPUT, "line 4: face vertex index 0");
    expect_read_error(write_bytes(dir.file("before.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"),
                      FABVDB_ERR_BAD_INPUT, "face vertex index -4 is out of range");
    expect_read_error(write_bytes(dir.file("after.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nf 3 2 1\n"),
                      FABVDB_ERR_BAD_INPUT, "line 4: face vertex index 4 is out of range (the file has 3 vertices)");
    const Mesh forward = read(write_bytes(dir.file("forward.obj"), "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"));
    EXPECT_EQ(forward.triangles, (std::vector<Triangle>{{0, 1, 2}}));
    expect_read_error(write_bytes(dir.file("two.obj"), "v 0 0 0\nv 1 0 0\nf 1 2\n"), FABVDB_ERR_BAD_INPUT,
                      "a face with 2 vertices");
    expect_read_error(write_bytes(dir.file("word.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n"),
                      FABVDB_ERR_BAD_INPUT, "not an integer: 'two'");
    expect_read_error(write_bytes(dir.file("short.obj"), "v 0 0\n"), FABVDB_ERR_BAD_INPUT,
                      "line 1: line ends where a vertex coordinate was expected");
}
