// Opening mesh files: the size and the exact bytes of a regular file (binary
// zeros included); a missing path, a folder or a non-regular file is
// Error(IO) and an empty file Error(BAD_INPUT), each message naming the path.
#include <gtest/gtest.h>

#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"
#include "io/input_file.h"
#include "io/io_test_files.h"

namespace {

using fabvdb::io::read_file_bytes;
using fabvdb::io::readable_file_size;
using fabvdb::test::TempDir;
using fabvdb::test::write_bytes;

//! Both functions must throw Error(status) whose message starts with the path and contains `defect`.
void expect_error(const std::string& path, fabvdb_status status, const std::string& defect) {
    SCOPED_TRACE(path);
    for (int which = 0; which < 2; ++which) {
        try {
            if (which == 0)
                readable_file_size(path);
            else
                read_file_bytes(path);
            ADD_FAILURE() << "no error; expected: " << defect;
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), status) << error.what();
            const std::string message = error.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(defect), std::string::npos) << message;
        }
    }
}

TEST(InputFile, SizeAndBytesOfARegularFile) {
    TempDir dir;
    std::string content = "solid x\n";
    content.push_back('\0');
    content += std::string(3000, '\xff') + "end";
    const std::string path = write_bytes(dir.file("part.stl"), content);
    EXPECT_EQ(readable_file_size(path), 8u + 1u + 3000u + 3u);
    EXPECT_EQ(read_file_bytes(path), content);
}

TEST(InputFile, OneByteFile) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("one"), "x");
    EXPECT_EQ(readable_file_size(path), 1u);
    EXPECT_EQ(read_file_bytes(path), "x");
}

TEST(InputFile, MissingPathIsAnIoError) {
    TempDir dir;
    expect_error(dir.file("missing.stl"), FABVDB_ERR_IO, "cannot open");
    expect_error(dir.file("no/such/folder/part.obj"), FABVDB_ERR_IO, "cannot open");
}

TEST(InputFile, FolderIsAnIoError) {
    TempDir dir;
    expect_error(dir.path(), FABVDB_ERR_IO, "is a directory");
}

TEST(InputFile, NonRegularFileIsAnIoError) {
    TempDir dir;
    const std::string fifo = dir.file("pipe");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    expect_error(fifo, FABVDB_ERR_IO, "not a regular file");
    expect_error("/dev/null", FABVDB_ERR_IO, "not a regular file");
}

TEST(InputFile, EmptyFileIsBadInput) {
    TempDir dir;
    const std::string path = write_bytes(dir.file("empty.ply"), "");
    expect_error(path, FABVDB_ERR_BAD_INPUT, "empty file");
}

TEST(InputFile, UnreadableFileIsAnIoError) {
    if (geteuid() == 0) GTEST_SKIP() << "root reads files without read permission";
    TempDir dir;
    const std::string path = write_bytes(dir.file("secret.stl"), "solid");
    ASSERT_EQ(chmod(path.c_str(), 0), 0);
    try {
        read_file_bytes(path);
        ADD_FAILURE() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
    }
}

}  // namespace
