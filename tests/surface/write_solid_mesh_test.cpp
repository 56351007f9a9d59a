// Writing outputs that must be clean solids: a clean mesh is written as it
// is; one that the float coordinates of STL would make degenerate is written
// rounded so that it stays valid; an open, crossing or inverted mesh is not
// written at all and the error names the file and the defect. The files are
// read back and checked with the test support's own checkers.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "io/io_test_files.h"
#include "support/ray_cast.h"
#include "support/defect_shapes.h"
#include "support/shapes.h"
#include "surface/write_solid_mesh.h"

namespace {

using fabvdb::Mesh;

void expect_refused(const Mesh& mesh, const std::string& name, const std::string& defect,
                    fabvdb_status status = FABVDB_ERR_INTERNAL) {
    SCOPED_TRACE(name);
    fabvdb::test::TempDir dir;
    const std::string path = dir.file(name);
    fabvdb::Progress progress;
    try {
        fabvdb::surface::write_solid_mesh(mesh, path, progress, status);
        ADD_FAILURE() << "written";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), status);
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find(defect), std::string::npos) << message;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "a file was left behind";
}

TEST(WriteSolidMesh, CleanMeshIsWrittenAsItIs) {
    const Mesh sphere = fabvdb::test::make_sphere({1.1, 2.2, 3.3}, 20.0, 3);
    fabvdb::test::TempDir dir;
    fabvdb::Progress progress;
    fabvdb::surface::write_solid_mesh(sphere, dir.file("sphere.obj"), progress);
    const Mesh back = fabvdb::test::read(dir.file("sphere.obj"));
    EXPECT_EQ(back.vertices, sphere.vertices);
    EXPECT_EQ(back.triangles, sphere.triangles);
}

TEST(WriteSolidMesh, FloatRoundingThatBreaksTheMeshIsRedone) {
    const Mesh box = fabvdb::test::make_box_with_close_pair();
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(box));
    ASSERT_GT(fabvdb::test::degenerate_triangle_count(fabvdb::test::stored_as_float(box)), 0u);
    for (const char* name : {"box.stl", "box.3mf"}) {
        SCOPED_TRACE(name);
        fabvdb::test::TempDir dir;
        fabvdb::Progress progress;
        fabvdb::surface::write_solid_mesh(box, dir.file(name), progress);
        const Mesh back = fabvdb::test::read(dir.file(name));
        EXPECT_TRUE(fabvdb::test::closed_two_manifold(back));
        EXPECT_FALSE(fabvdb::test::self_intersects(back));
        EXPECT_EQ(fabvdb::test::degenerate_triangle_count(back), 0u);
        EXPECT_NEAR(fabvdb::test::mesh_volume(back), 1000.0, 1e-3);
    }
}

TEST(WriteSolidMesh, InvalidMeshesAreNotWritten) {
    Mesh open = fabvdb::test::make_box({0, 0, 0}, {10, 10, 10});
    open.triangles.pop_back();
    expect_refused(open, "open.stl", "3 boundary edges");
    expect_refused(open, "open.obj", "boundary edges", FABVDB_ERR_BAD_INPUT);

    const Mesh crossing = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}),
                                               fabvdb::test::make_box({5, 5, 5}, {15, 15, 15}));
    expect_refused(crossing, "crossing.ply", "self-intersecting triangle pairs");

    expect_refused(fabvdb::test::flipped(fabvdb::test::make_sphere({0, 0, 0}, 5.0, 2)), "inside_out.off",
                   "do not bound a volume");

    Mesh degenerate = fabvdb::test::make_box({0, 0, 0}, {10, 10, 10});
    degenerate.vertices.push_back({5, 5, 10});  // on the top face's diagonal
    const fabvdb::Triangle top = degenerate.triangles[2];
    degenerate.triangles[2] = {top[0], top[1], 8};
    degenerate.triangles.push_back({top[1], top[2], 8});
    degenerate.triangles.push_back({top[2], top[0], 8});
    expect_refused(degenerate, "degenerate.obj", "degenerate triangles");
}

}  // namespace
