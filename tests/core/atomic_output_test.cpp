// AtomicOutput: the temporary file sits beside the target and the target
// appears (or is replaced) only on commit; without a commit nothing changes;
// failures to create or to move into place are Error(IO).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/atomic_output.h"
#include "core/error.h"

namespace {

namespace fs = std::filesystem;

struct TempFolder {
    fs::path path;
    TempFolder() {
        std::string pattern = (fs::temp_directory_path() / "fabvdb_atomic_output_XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~TempFolder() { fs::remove_all(path); }
};

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

int entries(const fs::path& folder) {
    int count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++count;
    return count;
}

TEST(AtomicOutput, TargetAppearsOnlyOnCommit) {
    TempFolder folder;
    const fs::path target = folder.path / "part.stl";
    fabvdb::AtomicOutput out(target.string());
    const fs::path temp = out.temp_path();
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_EQ(temp.parent_path(), target.parent_path());
    EXPECT_NE(temp, target);
    write(temp, "solid part\n");
    EXPECT_FALSE(fs::exists(target));
    out.commit();
    EXPECT_EQ(read(target), "solid part\n");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(entries(folder.path), 1);
    // An ordinary file, readable by others (not mkstemp's 0600).
    EXPECT_NE(fs::status(target).permissions() & fs::perms::others_read, fs::perms::none);
}

TEST(AtomicOutput, WithoutCommitAnOldFileIsKeptAndNothingIsLeft) {
    TempFolder folder;
    const fs::path target = folder.path / "report.json";
    write(target, "old");
    {
        fabvdb::AtomicOutput out(target.string());
        write(out.temp_path(), "half of the new");
    }
    EXPECT_EQ(read(target), "old");
    EXPECT_EQ(entries(folder.path), 1);
}

TEST(AtomicOutput, CommitReplacesAnOldFile) {
    TempFolder folder;
    const fs::path target = folder.path / "report.json";
    write(target, "old contents, longer than the new");
    fabvdb::AtomicOutput out(target.string());
    write(out.temp_path(), "new");
    out.commit();
    EXPECT_EQ(read(target), "new");
    EXPECT_EQ(entries(folder.path), 1);
}

TEST(AtomicOutput, TwoOutputsToOnePathHaveTheirOwnTemporaries) {
    TempFolder folder;
    const std::string target = (folder.path / "a.txt").string();
    fabvdb::AtomicOutput first(target), second(target);
    EXPECT_NE(first.temp_path(), second.temp_path());
}

TEST(AtomicOutput, MissingFolderIsAnIoError) {
    TempFolder folder;
    const fs::path target = folder.path / "missing" / "a.txt";
    try {
        fabvdb::AtomicOutput out(target.string());
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_TRUE(fs::is_empty(folder.path));
}

TEST(AtomicOutput, EmptyPathIsRejected) {
    EXPECT_THROW(fabvdb::AtomicOutput out(""), fabvdb::Error);
}

TEST(AtomicOutput, FailedCommitIsAnIoErrorAndLeavesNoTemporary) {
    TempFolder folder;
    // A folder (not empty) at the target path: a file cannot be renamed onto it.
    const fs::path target = folder.path / "taken";
    fs::create_directories(target / "inside");
    {
        fabvdb::AtomicOutput out(target.string());
        write(out.temp_path(), "data");
        try {
            out.commit();
            FAIL() << "no error";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        }
    }
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(entries(folder.path), 1);
}

TEST(WriteTextFileAtomically, WritesTheExactBytes) {
    TempFolder folder;
    const fs::path target = folder.path / "job.json";
    const std::string text = std::string("line one\r\nline two\n") + '\0' + "after a zero byte";
    fabvdb::write_text_file_atomically(target.string(), text);
    EXPECT_EQ(read(target), text);
    fabvdb::write_text_file_atomically(target.string(), "");
    EXPECT_EQ(read(target), "");
    EXPECT_EQ(entries(folder.path), 1);
}

TEST(WriteTextFileAtomically, MissingFolderIsAnIoError) {
    TempFolder folder;
    try {
        fabvdb::write_text_file_atomically((folder.path / "no" / "x.txt").string(), "x");
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_TRUE(fs::is_empty(folder.path));
}

}  // namespace
