// AtomicFolder: the temporary folder sits beside the target, which appears or
// is replaced whole only on commit; without a commit the temporary goes and an
// old folder stays as it was, also when the commit fails; a missing parent or
// a file at the path is Error(IO).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

#include "core/atomic_folder.h"
#include "core/error.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::AtomicFolder;

struct TempFolder {
    fs::path path;
    TempFolder() {
        std::string pattern = (fs::temp_directory_path() / "fabvdb_atomic_folder_XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~TempFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
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
    TempFolder base;
    const fs::path target = base.path / "parts";
    AtomicFolder folder(target.string());
    const fs::path temp = folder.temp_path();
    EXPECT_TRUE(fs::is_directory(temp));
    EXPECT_TRUE(fs::is_empty(temp));
    EXPECT_EQ(temp.parent_path(), base.path);
    EXPECT_NE(temp, target);
    write(temp / "part_1.stl", "one");
    fs::create_directory(temp / "sub");
    write(temp / "sub" / "part_2.stl", "two");
    EXPECT_FALSE(fs::exists(target));
    folder.commit();
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(read(target / "part_1.stl"), "one");
    EXPECT_EQ(read(target / "sub" / "part_2.stl"), "two");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(entries(base.path), 1);
}

TEST(AtomicFolder, WithoutCommitTheTemporaryGoesAndAnOldFolderStays) {
    TempFolder base;
    const fs::path target = base.path / "out";
    fs::create_directory(target);
    write(target / "old.txt", "old");
    fs::path temp;
    {
        AtomicFolder folder(target.string());
        temp = folder.temp_path();
        write(temp / "new.txt", "half");
        fs::create_directory(temp / "deeper");
        write(temp / "deeper" / "x", "x");
    }
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(read(target / "old.txt"), "old");
    EXPECT_EQ(entries(target), 1);
    EXPECT_EQ(entries(base.path), 1);
    // And with no old folder, nothing is left at all.
    { AtomicFolder folder((base.path / "fresh").string()); }
    EXPECT_EQ(entries(base.path), 1);
}

TEST(AtomicFolder, CommitReplacesAnOldFolderWhole) {
    TempFolder base;
    const fs::path target = base.path / "out";
    fs::create_directories(target / "old_sub");
    write(target / "old.txt", "old");
    write(target / "same.txt", "old version");
    AtomicFolder folder(target.string());
    write(fs::path(folder.temp_path()) / "same.txt", "new version");
    folder.commit();
    EXPECT_EQ(read(target / "same.txt"), "new version");
    EXPECT_FALSE(fs::exists(target / "old.txt"));
    EXPECT_FALSE(fs::exists(target / "old_sub"));
    EXPECT_EQ(entries(target), 1);
    EXPECT_EQ(entries(base.path), 1);  // no moved-aside old folder left
}

TEST(AtomicFolder, TrailingSlashAndDotsAreTheSameFolder) {
    TempFolder base;
    fs::create_directory(base.path / "a");
    AtomicFolder folder((base.path / "a" / ".." / "out/").string());
    EXPECT_EQ(fs::path(folder.temp_path()).parent_path(), base.path);
    write(fs::path(folder.temp_path()) / "f", "f");
    folder.commit();
    EXPECT_EQ(read(base.path / "out" / "f"), "f");
    EXPECT_EQ(entries(base.path), 2);  // a and out
}

TEST(AtomicFolder, APathWithoutFolderIsInTheWorkingFolder) {
    TempFolder base;
    const fs::path before = fs::current_path();
    fs::current_path(base.path);
    {
        AtomicFolder folder("plain");
        EXPECT_EQ(fs::absolute(folder.temp_path()).lexically_normal().parent_path(), base.path);
        write(fs::path(folder.temp_path()) / "f", "f");
        folder.commit();
    }
    fs::current_path(before);
    EXPECT_EQ(read(base.path / "plain" / "f"), "f");
    EXPECT_EQ(entries(base.path), 1);
}

TEST(AtomicFolder, MissingParentOrAFileAtThePathIsAnIoError) {
    TempFolder base;
    expect_io_error((base.path / "missing" / "out").string());
    EXPECT_TRUE(fs::is_empty(base.path));
    write(base.path / "taken", "a file");
    expect_io_error((base.path / "taken").string());
    EXPECT_EQ(read(base.path / "taken"), "a file");
    // A file as the parent.
    expect_io_error((base.path / "taken" / "out").string());
    EXPECT_EQ(entries(base.path), 1);
}

TEST(AtomicFolder, EmptyPathIsRejected) { EXPECT_THROW(AtomicFolder folder(""), fabvdb::Error); }

TEST(AtomicFolder, AFailedCommitIsAnIoErrorAndPutsTheOldFolderBack) {
    TempFolder base;
    const fs::path target = base.path / "out";
    fs::create_directory(target);
    write(target / "old.txt", "old");
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
    EXPECT_EQ(read(target / "old.txt"), "old");
    EXPECT_EQ(entries(target), 1);
    // The old folder moved aside for the commit leaves an empty place-holder
    // at most; the target itself is whole.
    for (const auto& entry : fs::directory_iterator(base.path))
        if (entry.path() != target) EXPECT_TRUE(fs::is_empty(entry.path())) << entry.path();
}

TEST(AtomicFolder, TwoFoldersForOnePathHaveTheirOwnTemporaries) {
    TempFolder base;
    const std::string target = (base.path / "out").string();
    AtomicFolder first(target), second(target);
    EXPECT_NE(first.temp_path(), second.temp_path());
    write(fs::path(first.temp_path()) / "from", "first");
    write(fs::path(second.temp_path()) / "from", "second");
    first.commit();
    second.commit();
    EXPECT_EQ(read(fs::path(target) / "from"), "second");
    EXPECT_EQ(entries(base.path), 1);
}

}  // namespace
