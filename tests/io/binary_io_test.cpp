// Binary numbers in mesh files: BinaryReader reads little- and big-endian
// values from hand-written bytes, tracks its position, and reading or skipping
// past the end is Error(BAD_INPUT) naming the file and the field without moving;
// the writers store little-endian bytes whatever the host.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <sstream>
#include <string>

#include "core/error.h"
#include "io/binary_io.h"

namespace {

using fabvdb::io::BinaryReader;

std::string bytes(std::initializer_list<unsigned> values) {
    std::string out;
    for (unsigned v : values) out.push_back(static_cast<char>(v));
    return out;
}

TEST(ReverseBytes, SwapsEndsOfEachWidth) {
    EXPECT_EQ(fabvdb::io::reverse_bytes<uint8_t>(0xab), 0xab);
    EXPECT_EQ(fabvdb::io::reverse_bytes<uint16_t>(0x1234), 0x3412);
    EXPECT_EQ(fabvdb::io::reverse_bytes<uint32_t>(0x01020304u), 0x04030201u);
    EXPECT_EQ(fabvdb::io::reverse_bytes<uint64_t>(0x0102030405060708ull), 0x0807060504030201ull);
    EXPECT_EQ(fabvdb::io::reverse_bytes<int16_t>(int16_t(0x00ff)), int16_t(-256));  // 0xff00
}

TEST(BinaryReader, LittleEndianValues) {
    // uint32 0x04030201, int16 -2 (0xfffe), float 1.0f (0x3f800000), double -2.5 (0xc004000000000000).
    const std::string data = bytes({0x01, 0x02, 0x03, 0x04, 0xfe, 0xff, 0x00, 0x00, 0x80, 0x3f, 0, 0, 0, 0, 0, 0,
                                    0x04, 0xc0});
    BinaryReader reader(data, "part.stl", false);
    EXPECT_EQ(reader.size(), 18u);
    EXPECT_EQ(reader.read<uint32_t>("count"), 0x04030201u);
    EXPECT_EQ(reader.position(), 4u);
    EXPECT_EQ(reader.read<int16_t>("attribute"), -2);
    EXPECT_EQ(reader.read<float>("x"), 1.0f);
    EXPECT_EQ(reader.read<double>("y"), -2.5);
    EXPECT_EQ(reader.position(), 18u);
    EXPECT_EQ(reader.remaining(), 0u);
}

TEST(BinaryReader, BigEndianValues) {
    const std::string data = bytes({0x01, 0x02, 0x03, 0x04, 0xff, 0xfe, 0x3f, 0x80, 0x00, 0x00, 0xc0, 0x04, 0, 0, 0, 0,
                                    0, 0});
    BinaryReader reader(data, "part.ply", true);
    EXPECT_EQ(reader.read<uint32_t>("count"), 0x01020304u);
    EXPECT_EQ(reader.read<int16_t>("attribute"), -2);
    EXPECT_EQ(reader.read<float>("x"), 1.0f);
    EXPECT_EQ(reader.read<double>("y"), -2.5);
    EXPECT_EQ(reader.remaining(), 0u);
}

TEST(BinaryReader, SkipMovesThePosition) {
    const std::string data = bytes({9, 9, 9, 9, 9, 0x2a, 0x00});
    BinaryReader reader(data, "f", false);
    reader.skip(5, "header");
    EXPECT_EQ(reader.position(), 5u);
    EXPECT_EQ(reader.remaining(), 2u);
    EXPECT_EQ(reader.read<uint16_t>("value"), 42);
    reader.skip(0, "nothing");
    EXPECT_EQ(reader.position(), 7u);
}

void expect_truncated(const std::function<void()>& action, const std::string& what,
                      const std::string& path = "model.stl") {
    try {
        action();
        ADD_FAILURE() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_EQ(std::string(error.what()), path + ": truncated: the file ends while reading " + what);
    }
}

TEST(BinaryReader, ReadingPastTheEndIsBadInputAndDoesNotMove) {
    const std::string data = bytes({1, 2, 3});
    BinaryReader reader(data, "model.stl", false);
    expect_truncated([&] { reader.read<uint32_t>("the triangle count"); }, "the triangle count");
    EXPECT_EQ(reader.position(), 0u);
    EXPECT_EQ(reader.read<uint16_t>("a"), 0x0201);
    expect_truncated([&] { reader.read<uint16_t>("b"); }, "b");
    EXPECT_EQ(reader.read<uint8_t>("c"), 3);
    expect_truncated([&] { reader.read<uint8_t>("d"); }, "d");
    EXPECT_EQ(reader.position(), 3u);
}

TEST(BinaryReader, SkippingPastTheEndIsBadInput) {
    const std::string data(10, 'x');
    BinaryReader reader(data, "model.stl", false);
    expect_truncated([&] { reader.skip(11, "the header"); }, "the header");
    EXPECT_EQ(reader.position(), 0u);
    reader.skip(10, "all");
    expect_truncated([&] { reader.skip(1, "one more"); }, "one more");
}

TEST(BinaryReader, EmptyInput) {
    BinaryReader reader(std::string_view(), "empty.stl", true);
    EXPECT_EQ(reader.size(), 0u);
    EXPECT_EQ(reader.remaining(), 0u);
    expect_truncated([&] { reader.read<uint8_t>("a byte"); }, "a byte", "empty.stl");
}

TEST(BinaryReader, ErrorNamesAFileWithAnyPath) {
    BinaryReader reader(std::string_view(), "/some/dir/a b.ply", false);
    try {
        reader.fail_truncated("vertex 7");
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_EQ(std::string(error.what()), "/some/dir/a b.ply: truncated: the file ends while reading vertex 7");
    }
}

TEST(StoreLittleEndian, WritesLowByteFirstAndReturnsTheNext) {
    char buffer[16] = {};
    char* at = fabvdb::io::store_little_endian<uint32_t>(buffer, 0xa1b2c3d4u);
    EXPECT_EQ(at, buffer + 4);
    at = fabvdb::io::store_little_endian<float>(at, -1.0f);  // 0xbf800000
    EXPECT_EQ(at, buffer + 8);
    at = fabvdb::io::store_little_endian<uint16_t>(at, 0x0102);
    EXPECT_EQ(at, buffer + 10);
    EXPECT_EQ(std::string(buffer, 10), bytes({0xd4, 0xc3, 0xb2, 0xa1, 0x00, 0x00, 0x80, 0xbf, 0x02, 0x01}));
}

TEST(WriteLittleEndian, StreamGetsLittleEndianBytesThatReadBack) {
    std::ostringstream out;
    fabvdb::io::write_little_endian<uint32_t>(out, 80u);
    fabvdb::io::write_little_endian<double>(out, 0.1);
    fabvdb::io::write_little_endian<int32_t>(out, -1);
    const std::string data = out.str();
    ASSERT_EQ(data.size(), 16u);
    EXPECT_EQ(data.substr(0, 4), bytes({80, 0, 0, 0}));
    // 0.1 is 0x3fb999999999999a.
    EXPECT_EQ(data.substr(4, 8), bytes({0x9a, 0x99, 0x99, 0x99, 0x99, 0x99, 0xb9, 0x3f}));
    EXPECT_EQ(data.substr(12), bytes({0xff, 0xff, 0xff, 0xff}));
    BinaryReader reader(data, "x", false);
    EXPECT_EQ(reader.read<uint32_t>("a"), 80u);
    EXPECT_EQ(reader.read<double>("b"), 0.1);
    EXPECT_EQ(reader.read<int32_t>("c"), -1);
}

}  // namespace
