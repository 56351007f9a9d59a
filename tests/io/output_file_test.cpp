// Writing output files: write_file_atomically leaves the exact bytes at the
// path (replacing an old file) and, when the writer throws or the stream
// fails or the folder is missing, no partial file and the old file untouched;
// write_double prints the shortest decimal that reads back as the same double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "io/io_test_files.h"
#include "io/output_file.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::io::write_double;
using fabvdb::io::write_file_atomically;
using fabvdb::test::entry_count;
using fabvdb::test::read_bytes;
using fabvdb::test::TempDir;
using fabvdb::test::write_bytes;

TEST(WriteFileAtomically, WritesTheExactBytes) {
    TempDir dir;
    const std::string path = dir.file("part.stl");
    std::string expected = "solid\r\n";
    expected.push_back('\0');
    expected += std::string(3 << 20, 'z');  // more than the 1 MiB buffer
    write_file_atomically(path, [&](std::ostream& out) { out.write(expected.data(), std::streamsize(expected.size())); });
    EXPECT_EQ(read_bytes(path), expected);
    EXPECT_EQ(entry_count(dir.path()), 1);
}

TEST(WriteFileAtomically, NothingWrittenMakesAnEmptyFile) {
    TempDir dir;
    const std::string path = dir.file("empty.obj");
    write_file_atomically(path, [](std::ostream&) {});
    EXPECT_TRUE(fs::is_regular_file(path));
    EXPECT_EQ(fs::file_size(path), 0u);
}

TEST(WriteFileAtomically, ReplacesAnOldFile) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("part.obj"), "an old file, longer than the new one");
    write_file_atomically(path, [](std::ostream& out) { out << "new"; });
    EXPECT_EQ(read_bytes(path), "new");
    EXPECT_EQ(entry_count(dir.path()), 1);
}

TEST(WriteFileAtomically, AThrowingWriterLeavesTheOldFileAndNoTemporary) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("part.ply"), "old");
    EXPECT_THROW(write_file_atomically(path,
                                       [](std::ostream& out) {
                                           out << "half";
                                           throw std::runtime_error("cancelled");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(read_bytes(path), "old");
    EXPECT_EQ(entry_count(dir.path()), 1);
    // Without an old file, nothing appears.
    const std::string fresh = dir.file("fresh.ply");
    EXPECT_THROW(write_file_atomically(fresh, [](std::ostream&) { throw std::runtime_error("x"); }),
                 std::runtime_error);
    EXPECT_FALSE(fs::exists(fresh));
    EXPECT_EQ(entry_count(dir.path()), 1);
}

TEST(WriteFileAtomically, AFailedStreamIsAnIoErrorNamingThePath) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("part.stl"), "old");
    try {
        write_file_atomically(path, [](std::ostream& out) {
            out << "some";
            out.setstate(std::ios::badbit);  // as a full disk would
        });
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
    EXPECT_EQ(read_bytes(path), "old");
    EXPECT_EQ(entry_count(dir.path()), 1);
}

TEST(WriteFileAtomically, MissingFolderIsAnIoError) {
    TempDir dir;
    const std::string path = dir.file("no/such/part.stl");
    bool called = false;
    try {
        write_file_atomically(path, [&](std::ostream&) { called = true; });
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
    EXPECT_FALSE(called);
    EXPECT_EQ(entry_count(dir.path()), 0);
}

std::string text_of(double value) {
    std::ostringstream out;
    write_double(out, value);
    return out.str();
}

TEST(WriteDouble, KnownTexts) {
    EXPECT_EQ(text_of(0.0), "0");
    EXPECT_EQ(text_of(1.0), "1");
    EXPECT_EQ(text_of(-2.5), "-2.5");
    EXPECT_EQ(text_of(0.1), "0.1");
    EXPECT_EQ(text_of(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(text_of(1.0 / 3.0), "0.3333333333333333");
    EXPECT_EQ(text_of(12.75), "12.75");
    EXPECT_EQ(text_of(1e300), "1e+300");
    EXPECT_EQ(text_of(5e-324), "5e-324");  // the smallest subnormal
    EXPECT_EQ(text_of(double(float(0.1f))), "0.10000000149011612");
}

TEST(WriteDouble, AppendsToTheStream) {
    std::ostringstream out;
    out << "v ";
    write_double(out, 1.5);
    out << ' ';
    write_double(out, -0.25);
    EXPECT_EQ(out.str(), "v 1.5 -0.25");
}

TEST(WriteDouble, RandomValuesReadBackExactlyInTheFewestCharacters) {
    std::mt19937_64 random(20261127);
    for (int i = 0; i < 2000; ++i) {
        uint64_t bits = random();
        double value;
        std::memcpy(&value, &bits, sizeof value);
        if (!std::isfinite(value)) continue;
        if (i % 2) value = std::ldexp(double(random() % 100000) / 1000.0, int(random() % 40) - 20);
        const std::string text = text_of(value);
        SCOPED_TRACE(text);
        const double back = std::strtod(text.c_str(), nullptr);
        EXPECT_EQ(std::memcmp(&back, &value, sizeof value), 0);
        // No longer than printf's texts (%g and %e) with the fewest
        // significant digits that read back.
        int fewest = 1;
        char general[64], exponent[64];
        for (; fewest < 17; ++fewest) {
            std::snprintf(general, sizeof general, "%.*g", fewest, value);
            if (std::strtod(general, nullptr) == value) break;
        }
        std::snprintf(general, sizeof general, "%.*g", fewest, value);
        std::snprintf(exponent, sizeof exponent, "%.*e", fewest - 1, value);
        EXPECT_LE(text.size(), std::strlen(general));
        EXPECT_LE(text.size(), std::strlen(exponent));
    }
}

}  // namespace
