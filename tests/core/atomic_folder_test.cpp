// AtomicFolder: the temporary folder sits beside the target, which appears or
// is replaced whole only on commit; without a commit the temporary goes and an
// old folder stays as it was, also when the commit fails; a missing parent or
// a file at the path is Error(IO).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "core/atomic_folder.h"
#include "core/error.h"
#include "support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::test::entry_count;
using fabvdb::test::read_bytes;
using fabvdb::test::TempDir;
using fabvdb::test::write_bytes;
using fabvdb::AtomicFolder;

void expect_io_error(const std::string& path) {
    try {
        AtomicFolder folder(path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
}

TEST(AtomicFolder, TargetAppearsOnlyOnCommit) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "parts";
    AtomicFolder folder(target.string());
    const fs::path temp = folder.temp_path();
    EXPECT_TRUE(fs::is_directory(temp));
    EXPECT_TRUE(fs::is_empty(temp));
    EXPECT_EQ(temp.parent_path(), fs::path(base.path()));
    EXPECT_NE(temp, target);
    write_bytes(temp / "part_1.stl", "one");
    fs::create_directory(temp / "sub");
    write_bytes(temp / "sub" / "part_2.stl", "two");
    EXPECT_FALSE(fs::exists(target));
    folder.commit();
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(read_bytes(target / "part_1.stl"), "one");
    EXPECT_EQ(read_bytes(target / "sub" / "part_2.stl"), "two");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicFolder, WithoutCommitTheTemporaryGoesAndAnOldFolderStays) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
    fs::create_directory(target);
    write_bytes(target / "old.txt", "old");
    fs::path temp;
    {
        AtomicFolder folder(target.string());
        temp = folder.temp_path();
        write_bytes(temp / "new.txt", "half");
        fs::create_directory(temp / "deeper");
        write_bytes(temp / "deeper" / "x", "x");
    }
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(read_bytes(target / "old.txt"), "old");
    EXPECT_EQ(entry_count(target), 1);
    EXPECT_EQ(entry_count(base.path()), 1);
    // And with no old folder, nothing is left at all.
    { AtomicFolder folder((fs::path(base.path()) / "fresh").string()); }
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicFolder, CommitReplacesAnOldFolderWhole) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
    fs::create_directories(target / "old_sub");
    write_bytes(target / "old.txt", "old");
    write_bytes(target / "same.txt", "old version");
    AtomicFolder folder(target.string());
    write_bytes(fs::path(folder.temp_path()) / "same.txt", "new version");
    folder.commit();
    EXPECT_EQ(read_bytes(target / "same.txt"), "new version");
    EXPECT_FALSE(fs::exists(target / "old.txt"));
    EXPECT_FALSE(fs::exists(target / "old_sub"));
    EXPECT_EQ(entry_count(target), 1);
    EXPECT_EQ(entry_count(base.path()), 1);  // no moved-aside old folder left
}

TEST(AtomicFolder, TrailingSlashAndDotsAreTheSameFolder) {
    TempDir base;
    fs::create_directory(fs::path(base.path()) / "a");
    AtomicFolder folder((fs::path(base.path()) / "a" / ".." / "out/").string());
    EXPECT_EQ(fs::path(folder.temp_path()).parent_path(), fs::path(base.path()));
    write_bytes(fs::path(folder.temp_path()) / "f", "f");
    folder.commit();
    EXPECT_EQ(read_bytes(fs::path(base.path()) / "out" / "f"), "f");
    EXPECT_EQ(entry_count(base.path()), 2);  // a and out
}

TEST(AtomicFolder, APathWithoutFolderIsInTheWorkingFolder) {
    TempDir base;
    const fs::path before = fs::current_path();
    fs::current_path(fs::path(base.path()));
    {
        AtomicFolder folder("plain");
        EXPECT_EQ(fs::absolute(folder.temp_path()).lexically_normal().parent_path(), fs::path(base.path()));
        write_bytes(fs::path(folder.temp_path()) / "f", "f");
        folder.commit();
    }
    fs::current_path(before);
    EXPECT_EQ(read_bytes(fs::path(base.path()) / "plain" / "f"), "f");
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicFolder, MissingParentOrAFileAtThePathIsAnIoError) {
    TempDir base;
    expect_io_error((fs::path(base.path()) / "missing" / "out").string());
    EXPECT_TRUE(fs::is_empty(fs::path(base.path())));
    write_bytes(fs::path(base.path()) / "taken", "a file");
    expect_io_error((fs::path(base.path()) / "taken").string());
    EXPECT_EQ(read_bytes(fs::path(base.path()) / "taken"), "a file");
    // A file as the parent.
    expect_io_error((fs::path(base.path()) / "taken" / "out").string());
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicFolder, EmptyPathIsRejected) { EXPECT_THROW(AtomicFolder folder(""), fabvdb::Error); }

TEST(AtomicFolder, AFailedCommitIsAnIoErrorAndPutsTheOldFolderBack) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
    fs::create_directory(target);
    write_bytes(target / "old.txt", "old");
    {
        AtomicFolder folder(target.string());
        fs::remove_all(folder.temp_path());  // nothing left to move into place
        try {
            folder.commit();
            FAIL() << "no error";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_IO);
            EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(read_bytes(target / "old.txt"), "old");
    EXPECT_EQ(entry_count(target), 1);
    // Nothing but the target is left: neither the temporary nor the folder
    // the old one was moved aside into.
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicFolder, TwoFoldersForOnePathHaveTheirOwnTemporaries) {
    TempDir base;
    const std::string target = (fs::path(base.path()) / "out").string();
    AtomicFolder first(target), second(target);
    EXPECT_NE(first.temp_path(), second.temp_path());
    write_bytes(fs::path(first.temp_path()) / "from", "first");
    write_bytes(fs::path(second.temp_path()) / "from", "second");
    first.commit();
    second.commit();
    EXPECT_EQ(read_bytes(fs::path(target) / "from"), "second");
    EXPECT_EQ(entry_count(base.path()), 1);
}

}  // namespace
