// STL: binary round trip, content sniffing, a binary count left at 0, exact
// welding, ASCII variants, truncation.
#include "io/stl_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>

#include "io/io_test_files.h"
#include "support/shapes.h"

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using namespace fabvdb::test;

namespace {

Vec3 as_float(const Vec3& p) {
    Vec3 rounded;
    for (int k = 0; k < 3; ++k) {
        // volatile: GCC 12 at -O2 wrongly folds a vectorized double->float->double into nothing.
        volatile float single = static_cast<float>(p[k]);
        rounded[k] = single;
    }
    return rounded;
}

void append_float(std::string& bytes, float value) {
    unsigned char raw[4];
    std::memcpy(raw, &value, 4);
    if (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__) std::swap(raw[0], raw[3]), std::swap(raw[1], raw[2]);
    bytes.append(reinterpret_cast<const char*>(raw), 4);
}

//! A binary STL by hand: `header` padded to 80 bytes, `count` as stored, then the facets.
std::string binary_stl(std::string header, uint32_t count, const std::vector<std::array<Vec3, 3>>& facets) {
    header.resize(80, '\0');
    std::string bytes = header;
    for (int k = 0; k < 4; ++k) bytes += static_cast<char>((count >> (8 * k)) & 0xff);
    for (const auto& facet : facets) {
        for (int k = 0; k < 3; ++k) append_float(bytes, 0.0f);
        for (const Vec3& p : facet)
            for (double c : p) append_float(bytes, static_cast<float>(c));
        bytes += std::string(2, '\0');
    }
    return bytes;
}

}  // namespace

TEST(StlFormat, BinaryRoundTripKeepsEveryCornerInSinglePrecision) {
    TempDir dir;
    const Mesh mesh = make_sphere({10.1, -20.2, 30.3}, 7.77, 3);
    const std::string path = dir.file("sphere.stl");
    fabvdb::io::write_mesh(mesh, path);
    EXPECT_EQ(std::filesystem::file_size(path), 84 + 50 * mesh.triangles.size());
    const Mesh back = read(path);
    ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
    EXPECT_EQ(back.vertices.size(), mesh.vertices.size());  // all sphere vertices are distinct
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(back.vertices[back.triangles[t][k]], as_float(mesh.vertices[mesh.triangles[t][k]]));
}

TEST(StlFormat, BinaryFileWhoseHeaderSaysSolidIsReadAsBinary) {
    TempDir dir;
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
    const std::string path =
        write_bytes(dir.file("solid_header.stl"), binary_stl("solid looks like ASCII", 2, {{a, b, c}, {a, c, d}}));
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices.size(), 4u);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(mesh.vertices[3], d);
}

TEST(StlFormat, BinaryCountOfZeroBeforeWholeFacetsReadsTheFacets) {
    // Some writers never fill the count in: 0, then facets to the end.
    TempDir dir;
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
    const Mesh mesh =
        read(write_bytes(dir.file("no_count.stl"), binary_stl("", 0, {{a, b, c}, {a, c, d}, {a, d, b}})));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.triangles[2], (Triangle{0, 3, 1}));
    // A partial facet after the count of 0 is not a file of facets.
    expect_read_error(write_bytes(dir.file("ragged.stl"), binary_stl("", 0, {{a, b, c}}) + "xyz"),
                      FABVDB_ERR_BAD_INPUT, "no triangles");
}

TEST(StlFormat, OnlyBitIdenticalCornersAreWelded) {
    TempDir dir;
    const float next = std::nextafter(1.0f, 2.0f);
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, b_close{next, 0, 0};
    const std::string path =
        write_bytes(dir.file("weld.stl"), binary_stl("", 3, {{a, b, c}, {c, b, a}, {a, b_close, c}}));
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.triangles[1], (Triangle{2, 1, 0}));
    EXPECT_EQ(mesh.triangles[2], (Triangle{0, 3, 2}));
}

TEST(StlFormat, AsciiWithCrlfTwoSolidsAndUppercaseKeywords) {
    TempDir dir;
    const std::string facet = "  facet normal 0 0 1\r\n    outer loop\r\n      vertex 0 0 0\r\n"
                              "      vertex 1.5e0 0 0\r\n      vertex 0 +1 0\r\n    endloop\r\n  endfacet\r\n";
    const std::string path = write_bytes(dir.file("two.stl"),
                                         "solid first\r\n" + facet + "endsolid first\r\n"
                                         "SOLID second\r\n  FACET NORMAL 0 0 -1\r\n    OUTER LOOP\r\n"
                                         "      VERTEX 0 0 0\r\n      VERTEX 0 1 0\r\n      VERTEX -2 0 0\r\n"
                                         "    ENDLOOP\r\n  ENDFACET\r\nENDSOLID second\r\n");
    const Mesh mesh = read(path);
    EXPECT_EQ(mesh.vertices.size(), 4u);  // (0,0,0) and (0,1,0) are shared
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(mesh.vertices[1], (Vec3{1.5, 0, 0}));
    EXPECT_EQ(mesh.vertices[3], (Vec3{-2, 0, 0}));
}

TEST(StlFormat, TruncatedAndMalformedFilesAreRejected) {
    TempDir dir;
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    std::string truncated = binary_stl("", 1000, {{a, b, c}});
    expect_read_error(write_bytes(dir.file("truncated.stl"), truncated), FABVDB_ERR_BAD_INPUT,
                      "truncated binary STL: the header announces 1000 triangles");
    expect_read_error(write_bytes(dir.file("huge_count.stl"), binary_stl("solid x", 0xffffffffu, {{a, b, c}})),
                      FABVDB_ERR_BAD_INPUT, "announces 4294967295 triangles");
    expect_read_error(write_bytes(dir.file("tiny.stl"), "abc"), FABVDB_ERR_BAD_INPUT,
                      "shorter than the 84-byte header");
    expect_read_error(write_bytes(dir.file("zero.stl"), binary_stl("", 0, {})), FABVDB_ERR_BAD_INPUT,
                      "no triangles");
    expect_read_error(write_bytes(dir.file("cut.stl"), "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
                      FABVDB_ERR_BAD_INPUT, "file ends where 'vertex' or 'endloop' was expected");
    expect_read_error(write_bytes(dir.file("nan.stl"),
                                  "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n"
                                  "vertex 0 1 0\nendloop\nendfacet\nendsolid\n"),
                      FABVDB_ERR_BAD_INPUT, "non-finite coordinate");
    expect_read_error(write_bytes(dir.file("inf.stl"),
                                  binary_stl("", 1, {{a, b, Vec3{0, INFINITY, 0}}})),
                      FABVDB_ERR_BAD_INPUT, "vertex 3 has a non-finite coordinate");
}
