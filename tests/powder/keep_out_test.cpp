// Keep-out regions: spheres read from a JSON object or a bare array (any case
// of ".json"), each malformed file refused with BAD_INPUT (IO if missing)
// and a message naming the file; `touches` on a sphere at hand-worked
// distances (strictly inside radius + margin); a box mesh file turned into a
// region that a point touches inside, within the margin of a face, and not
// beyond it, for margins up to the reach it was read with.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/progress.h"
#include "io/mesh_io.h"
#include "powder/keep_out.h"
#include "support/shapes.h"
#include "support/temp_files.h"

namespace {

using fabvdb::Error;
using fabvdb::powder::KeepOut;
using fabvdb::powder::read_keep_out;

KeepOut read(const std::string& path) {
    fabvdb::Progress progress;
    return read_keep_out(path, 0.5, 2.0, progress);
}

//! The status and message of reading `text` as a JSON keep-out file.
Error refusal(const fabvdb::test::TempDir& dir, const std::string& text) {
    const std::string path = fabvdb::test::write_bytes(dir.file("bad.json"), text);
    try {
        read(path);
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "accepted: " << text;
    return Error(FABVDB_OK, "");
}

}  // namespace

TEST(KeepOut, ReadsSpheresFromAnObject) {
    fabvdb::test::TempDir dir;
    const std::string path = fabvdb::test::write_bytes(
        dir.file("keep.json"),
        R"({"spheres": [{"center": [1, -2.5, 3], "radius": 4}, {"center": [0, 0, 1e2], "radius": 0.25}]})");
    const KeepOut keep_out = read(path);
    ASSERT_EQ(keep_out.spheres.size(), 2u);
    EXPECT_EQ(keep_out.spheres[0].center, (fabvdb::Vec3{1, -2.5, 3}));
    EXPECT_EQ(keep_out.spheres[0].radius, 4.0);
    EXPECT_EQ(keep_out.spheres[1].center, (fabvdb::Vec3{0, 0, 100}));
    EXPECT_EQ(keep_out.spheres[1].radius, 0.25);
    EXPECT_FALSE(keep_out.region);
    EXPECT_FALSE(keep_out.empty());
}

TEST(KeepOut, ReadsABareArrayWhateverTheCaseOfTheExtension) {
    fabvdb::test::TempDir dir;
    const std::string path =
        fabvdb::test::write_bytes(dir.file("keep.JSON"), R"([{"radius": 2, "center": [5, 6, 7]}])");
    const KeepOut keep_out = read(path);
    ASSERT_EQ(keep_out.spheres.size(), 1u);
    EXPECT_EQ(keep_out.spheres[0].center, (fabvdb::Vec3{5, 6, 7}));
    EXPECT_EQ(keep_out.spheres[0].radius, 2.0);
    // An empty list is no keep-out at all.
    EXPECT_TRUE(read(fabvdb::test::write_bytes(dir.file("none.json"), "[]")).empty());
    EXPECT_TRUE(read(fabvdb::test::write_bytes(dir.file("none2.json"), R"({"spheres": []})")).empty());
    EXPECT_TRUE(KeepOut{}.empty());
}

TEST(KeepOut, RefusesMalformedFilesNamingThem) {
    fabvdb::test::TempDir dir;
    const std::string path = dir.file("bad.json");
    const char* bad[] = {
        "{\"spheres\": [",                                          // not JSON
        R"({"holes": []})",                                         // no "spheres"
        R"({"spheres": {"center": [0, 0, 0], "radius": 1}})",       // not an array
        "42",                                                       // neither object nor array
        R"([{"center": [0, 0, 0]}])",                               // no radius
        R"([{"radius": 1}])",                                       // no center
        R"([{"center": [0, 0], "radius": 1}])",                     // two coordinates
        R"([{"center": [0, 0, 0, 0], "radius": 1}])",               // four
        R"([{"center": [0, "1", 0], "radius": 1}])",                // a string coordinate
        R"([{"center": [0, 0, 0], "radius": "1"}])",                // a string radius
        R"([{"center": [0, 0, 0], "radius": 0}])",                  // zero radius
        R"([{"center": [0, 0, 0], "radius": -2}])",                 // negative radius
        R"([{"center": [0, 0, 0], "radius": 1}, [0, 0, 0]])",       // a later item not an object
    };
    for (const char* text : bad) {
        const Error e = refusal(dir, text);
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT) << text;
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << text << ": " << e.what();
    }
}

TEST(KeepOut, AMissingFileIsAnIOError) {
    fabvdb::test::TempDir dir;
    for (const std::string name : {"missing.json", "missing.stl"}) {
        const std::string path = dir.file(name);
        try {
            read(path);
            ADD_FAILURE() << "read " << path;
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_IO) << name;
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
}

TEST(KeepOut, ASphereIsTouchedStrictlyWithinRadiusPlusMargin) {
    KeepOut keep_out;
    keep_out.spheres.push_back({{1, 2, 3}, 2.0});
    // (4, 6, 3) is 5 from the centre: the sphere's edge is 3 away.
    EXPECT_FALSE(keep_out.touches({4, 6, 3}, 2.9));
    EXPECT_FALSE(keep_out.touches({4, 6, 3}, 3.0));  // exactly touching is not reaching in
    EXPECT_TRUE(keep_out.touches({4, 6, 3}, 3.1));
    // Inside the sphere, even with no margin.
    EXPECT_TRUE(keep_out.touches({1, 2, 4.5}, 0.0));
    EXPECT_TRUE(keep_out.touches({1, 2, 3}, 0.0));
    EXPECT_FALSE(keep_out.touches({1, 2, 5.5}, 0.0));
    // Any of several spheres.
    keep_out.spheres.push_back({{-20, 0, 0}, 1.0});
    EXPECT_TRUE(keep_out.touches({-22, 0, 0}, 1.5));
    EXPECT_FALSE(keep_out.touches({-10, 0, 0}, 1.5));
    EXPECT_FALSE(KeepOut{}.touches({0, 0, 0}, 100.0));
}

TEST(KeepOut, AMeshFileBecomesARegion) {
    fabvdb::test::TempDir dir;
    const std::string path = dir.file("block.stl");
    fabvdb::io::write_mesh(fabvdb::test::make_box({0, 0, 0}, {10, 8, 6}), path);
    const KeepOut keep_out = read(path);
    ASSERT_TRUE(keep_out.region);
    EXPECT_TRUE(keep_out.spheres.empty());
    EXPECT_FALSE(keep_out.empty());
    EXPECT_NEAR(keep_out.region->voxelSize()[0], 0.5, 1e-9);
    // Inside: deep (beyond the band) and near a face.
    EXPECT_TRUE(keep_out.touches({5, 4, 3}, 0.0));
    EXPECT_TRUE(keep_out.touches({9.8, 4, 3}, 0.0));
    // 0.8 above the top face (z = 6): touched by a margin of 1, not of 0.5.
    EXPECT_TRUE(keep_out.touches({5, 4, 6.8}, 1.0));
    EXPECT_FALSE(keep_out.touches({5, 4, 6.8}, 0.5));
    // 0.6 beside the face x = 10.
    EXPECT_TRUE(keep_out.touches({10.6, 4, 3}, 0.7));
    EXPECT_FALSE(keep_out.touches({10.6, 4, 3}, 0.4));
    // Far away: beyond the band, whatever the margin.
    EXPECT_FALSE(keep_out.touches({40, 4, 3}, 1.0));
    EXPECT_FALSE(keep_out.touches({40, 4, 3}, 2.0));
    EXPECT_FALSE(keep_out.touches({5, 4, -30}, 0.0));
    // Margins up to the reach it was read with (2 mm) are exact: 1.5 mm
    // above the top is within 2, 3 mm above is not within 1.6.
    EXPECT_TRUE(keep_out.touches({5, 4, 7.5}, 2.0));
    EXPECT_FALSE(keep_out.touches({5, 4, 7.5}, 1.4));
    EXPECT_FALSE(keep_out.touches({5, 4, 9}, 1.6));
    EXPECT_FALSE(keep_out.touches({5, 4, 9}, 2.0));
}
