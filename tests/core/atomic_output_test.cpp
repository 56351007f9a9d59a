// AtomicOutput: the temporary file sits beside the target and the target
// appears (or is replaced) only on commit; without a commit nothing changes;
// failures to create or to move into place are Error(IO).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/atomic_output.h"
#include "core/error.h"
#include "support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::test::entry_count;
using fabvdb::test::read_bytes;
using fabvdb::test::TempDir;
using fabvdb::test::write_bytes;

TEST(AtomicOutput, TargetAppearsOnlyOnCommit) {
    TempDir folder;
    const fs::path target = fs::path(folder.path()) / "part.stl";
    fabvdb::AtomicOutput out(target.string());
    const fs::path temp = out.temp_path();
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_EQ(temp.parent_path(), target.parent_path());
    EXPECT_NE(temp, target);
    write_bytes(temp, "solid part\n");
    EXPECT_FALSE(fs::exists(target));
    out.commit();
    EXPECT_EQ(read_bytes(target), "solid part\n");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(entry_count(folder.path()), 1);
    // An ordinary file, readable by others (not mkstemp's 0600).
    EXPECT_NE(fs::status(target).permissions() & fs::perms::others_read, fs::perms::none);
}

TEST(AtomicOutput, WithoutCommitAnOldFileIsKeptAndNothingIsLeft) {
    TempDir folder;
    const fs::path target = fs::path(folder.path()) / "report.json";
    write_bytes(target, "old");
    {
        fabvdb::AtomicOutput out(target.string());
        write_bytes(out.temp_path(), "half of the new");
    }
    EXPECT_EQ(read_bytes(target), "old");
    EXPECT_EQ(entry_count(folder.path()), 1);
}

TEST(AtomicOutput, CommitReplacesAnOldFile) {
    TempDir folder;
    const fs::path target = fs::path(folder.path()) / "report.json";
    write_bytes(target, "old contents, longer than the new");
    fabvdb::AtomicOutput out(target.string());
    write_bytes(out.temp_path(), "new");
    out.commit();
    EXPECT_EQ(read_bytes(target), "new");
    EXPECT_EQ(entry_count(folder.path()), 1);
}

TEST(AtomicOutput, TwoOutputsToOnePathHaveTheirOwnTemporaries) {
    TempDir folder;
    const std::string target = (fs::path(folder.path()) / "a.txt").string();
    fabvdb::AtomicOutput first(target), second(target);
    EXPECT_NE(first.temp_path(), second.temp_path());
}

TEST(AtomicOutput, MissingFolderIsAnIoError) {
    TempDir folder;
    const fs::path target = fs::path(folder.path()) / "missing" / "a.txt";
    try {
        fabvdb::AtomicOutput out(target.string());
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_TRUE(fs::is_empty(fs::path(folder.path())));
}

TEST(AtomicOutput, EmptyPathIsRejected) {
    EXPECT_THROW(fabvdb::AtomicOutput out(""), fabvdb::Error);
}

TEST(AtomicOutput, FailedCommitIsAnIoErrorAndLeavesNoTemporary) {
    TempDir folder;
    // A folder (not empty) at the target path: a file cannot be renamed onto it.
    const fs::path target = fs::path(folder.path()) / "taken";
    fs::create_directories(target / "inside");
    {
        fabvdb::AtomicOutput out(target.string());
        write_bytes(out.temp_path(), "data");
        try {
            out.commit();
            FAIL() << "no error";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        }
    }
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(entry_count(folder.path()), 1);
}

TEST(WriteTextFileAtomically, WritesTheExactBytes) {
    TempDir folder;
    const fs::path target = fs::path(folder.path()) / "job.json";
    const std::string text = std::string("line one\r\nline two\n") + '\0' + "after a zero byte";
    fabvdb::write_text_file_atomically(target.string(), text);
    EXPECT_EQ(read_bytes(target), text);
    fabvdb::write_text_file_atomically(target.string(), "");
    EXPECT_EQ(read_bytes(target), "");
    EXPECT_EQ(entry_count(folder.path()), 1);
}

TEST(WriteTextFileAtomically, MissingFolderIsAnIoError) {
    TempDir folder;
    try {
        fabvdb::write_text_file_atomically((fs::path(folder.path()) / "no" / "x.txt").string(), "x");
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_TRUE(fs::is_empty(fs::path(folder.path())));
}

}  // namespace
