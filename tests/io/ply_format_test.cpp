// PLY: round trip, the three encodings, all scalar types, face and strip
// lists, skipped elements and properties, header counts larger than the file.
#include "io/ply_format.h"

#include <gtest/gtest.h>

#include <cstring>

#include "io/io_test_files.h"
#include "support/shapes.h"

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using namespace fabvdb::test;

namespace {

//! Appends `value` in the given byte order, independently of the host's.
template <typename T>
void put(std::string& bytes, T value, bool big_endian) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    const bool host_big = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
    if (host_big != big_endian)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    bytes.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

const char* const every_type_header =
    "element vertex 4\n"
    "property char flag\nproperty float x\nproperty double y\nproperty short z\n"
    "property uchar red\nproperty ushort u16\nproperty int i32\nproperty uint u32\n"
    "property list uchar float normals\n"
    "element material 1\nproperty float shine\n"
    "element face 1\nproperty uchar flags\nproperty list ushort int vertex_index\n"
    "element tristrips 1\nproperty list int int vertex_indices\n"
    "end_header\n";

//! The same content in binary, in either byte order.
std::string binary_ply(bool big_endian) {
    std::string bytes = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\ncomment every scalar type\n" + every_type_header;
    const double positions[4][3] = {{0.5, -1.25, 3}, {2, 0, -7}, {0, 1e-3, 1}, {-1, 2, 0}};
    for (const auto& p : positions) {
        put<int8_t>(bytes, -5, big_endian);
        put<float>(bytes, static_cast<float>(p[0]), big_endian);
        put<double>(bytes, p[1], big_endian);
        put<int16_t>(bytes, static_cast<int16_t>(p[2]), big_endian);
        put<uint8_t>(bytes, 200, big_endian);
        put<uint16_t>(bytes, 60000, big_endian);
        put<int32_t>(bytes, -100000, big_endian);
        put<uint32_t>(bytes, 4000000000u, big_endian);
        put<uint8_t>(bytes, 2, big_endian);
        put<float>(bytes, 0.25f, big_endian);
        put<float>(bytes, 0.75f, big_endian);
    }
    put<float>(bytes, 9.5f, big_endian);
    put<uint8_t>(bytes, 7, big_endian);
    put<uint16_t>(bytes, 4, big_endian);
    for (int32_t i : {0, 1, 2, 3}) put<int32_t>(bytes, i, big_endian);
    put<int32_t>(bytes, 6, big_endian);
    for (int32_t i : {3, 2, 1, 0, -1, 1}) put<int32_t>(bytes, i, big_endian);
    return bytes;
}

void expect_every_type_content(const Mesh& mesh) {
    ASSERT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.vertices[0], (Vec3{0.5, -1.25, 3}));
    EXPECT_EQ(mesh.vertices[1], (Vec3{2, 0, -7}));
    EXPECT_EQ(mesh.vertices[2], (Vec3{0, 1e-3, 1}));
    // face (0 1 2 3) fans into two; strip (3 2 1 0) gives (3 2 1), (1 2 0); after -1 only one index.
    const std::vector<Triangle> expected = {{0, 1, 2}, {0, 2, 3}, {3, 2, 1}, {1, 2, 0}};
    EXPECT_EQ(mesh.triangles, expected);
}

}  // namespace

TEST(PlyFormat, BinaryRoundTripKeepsEveryVertexAndTriangleExactly) {
    TempDir dir;
    Mesh mesh = make_sphere({-1.0 / 7.0, 2e6, 3.5}, 0.001234, 2);
    mesh.vertices.push_back({1, 2, 3});
    const std::string path = dir.file("sphere.ply");
    fabvdb::io::write_mesh(mesh, path);
    const Mesh back = read(path);
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(PlyFormat, LittleEndianWithEveryScalarType) {
    TempDir dir;
    expect_every_type_content(read(write_bytes(dir.file("le.ply"), binary_ply(false))));
}

TEST(PlyFormat, BigEndianWithEveryScalarType) {
    TempDir dir;
    expect_every_type_content(read(write_bytes(dir.file("be.ply"), binary_ply(true))));
}

TEST(PlyFormat, AsciiWithEveryScalarTypeAndCrlfHeader) {
    TempDir dir;
    std::string header = std::string("ply\r\nformat ascii 1.0\r\n") + every_type_header;
    const std::string text = header +
                             "-5 0.5 -1.25 3 200 60000 -100000 4000000000 2 0.25 0.75\n"
                             "-5 2 0 -7 200 60000 -100000 4000000000 2 0.25 0.75\n"
                             "-5 0 1e-3 1 200 60000 -100000 4000000000 2 0.25 0.75\n"
                             "-5 -1 2 0 200 60000 -100000 4000000000 0\n"
                             "9.5\n"
                             "7 4 0 1 2 3\n"
                             "6 3 2 1 0 -1 1\n";
    expect_every_type_content(read(write_bytes(dir.file("ascii.ply"), text)));
}

TEST(PlyFormat, TriangleStripsAlternateAndDropJoiningTriangles) {
    TempDir dir;
    // Two strips joined by repeating 3 and 4 (four degenerate joints), then a restart.
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 2 0\n1 2 0\n0 3 0\n1 3 0\n"
        "13 0 1 2 3 3 4 4 5 6 -1 5 4 7\n";
    const Mesh mesh = read(write_bytes(dir.file("strips.ply"), text));
    const std::vector<Triangle> expected = {{0, 1, 2}, {2, 1, 3}, {4, 5, 6}, {5, 4, 7}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(PlyFormat, HeaderCountsLargerThanTheFileAreRejectedWithoutAllocating) {
    TempDir dir;
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\n"
                               "property float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    expect_read_error(write_bytes(dir.file("huge.ply"), header + std::string(24, '\0')), FABVDB_ERR_BAD_INPUT,
                      "truncated: the file ends while reading a property value");
    const std::string list = "ply\nformat binary_little_endian 1.0\nelement vertex 0\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uint int vertex_indices\nend_header\n";
    std::string bytes = list;
    put<uint32_t>(bytes, 4000000000u, false);
    expect_read_error(write_bytes(dir.file("long_list.ply"), bytes), FABVDB_ERR_BAD_INPUT,
                      "face 0: list longer than the rest of the file");
    expect_read_error(write_bytes(dir.file("ascii_huge.ply"),
                                  "ply\nformat ascii 1.0\nelement vertex 2147483648\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n0 0 0\n"),
                      FABVDB_ERR_BAD_INPUT, "file ends where a property value was expected");
}

TEST(PlyFormat, MalformedHeadersAndIndicesAreRejected) {
    TempDir dir;
    const std::string vertices = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    expect_read_error(write_bytes(dir.file("range.ply"), vertices + "3 0 1 3\n"), FABVDB_ERR_BAD_INPUT,
                      "uses vertex index 3 but there are 3 vertices");
    expect_read_error(write_bytes(dir.file("negative.ply"), vertices + "3 0 -1 2\n"), FABVDB_ERR_BAD_INPUT,
                      "face 0: invalid vertex index -1");
    expect_read_error(write_bytes(dir.file("magic.ply"), "plx\nformat ascii 1.0\nend_header\n"),
                      FABVDB_ERR_BAD_INPUT, "not a PLY file");
    expect_read_error(write_bytes(dir.file("no_end.ply"), "ply\nformat ascii 1.0\nelement vertex 0\n"),
                      FABVDB_ERR_BAD_INPUT, "no 'end_header'");
    expect_read_error(write_bytes(dir.file("type.ply"), "ply\nformat ascii 1.0\nelement vertex 1\n"
                                                         "property quad x\nend_header\n"),
                      FABVDB_ERR_BAD_INPUT, "unknown property type 'quad'");
    expect_read_error(write_bytes(dir.file("no_z.ply"), "ply\nformat ascii 1.0\nelement vertex 1\n"
                                                         "property float x\nproperty float y\nend_header\n0 0\n"),
                      FABVDB_ERR_BAD_INPUT, "no scalar 'z' property");
}
