// AtomicOutput, of both kinds: the temporary file or folder sits beside the
// target, which appears or is replaced (a folder whole) only on commit;
// without a commit the temporary goes and an old output stays as it was, also
// when the commit fails; a missing parent, a file where a folder should go or
// a failed move into place is Error(IO). Then write_text_file_atomically.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/atomic_output.h"
#include "core/error.h"
#include "support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::AtomicOutput;
using fabvdb::test::entry_count;
using fabvdb::test::read_bytes;
using fabvdb::test::TempDir;
using fabvdb::test::write_bytes;
using Kind = AtomicOutput::Kind;

void expect_io_error(const std::string& path, Kind kind) {
    try {
        AtomicOutput output(path, kind);
        ADD_FAILURE() << "no error for " << path;
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
}

// --- what both kinds share -------------------------------------------------

// Fills an output's temporary with "content": the bytes for a file, a file
// named "content" holding them for a folder.
void fill(const AtomicOutput& output, Kind kind, const std::string& bytes) {
    write_bytes(kind == Kind::file ? output.temp_path() : output.temp_path() + "/content", bytes);
}

std::string content(const fs::path& target, Kind kind) {
    return read_bytes(kind == Kind::file ? target : target / "content");
}

// An older output at `target`, holding `bytes` as fill() would.
void put_old(const fs::path& target, Kind kind, const std::string& bytes) {
    if (kind == Kind::folder) fs::create_directory(target);
    write_bytes(kind == Kind::file ? target : target / "content", bytes);
}

class BothKinds : public testing::TestWithParam<Kind> {
protected:
    const Kind kind = GetParam();
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
};

TEST_P(BothKinds, TargetAppearsOnlyOnCommit) {
    AtomicOutput output(target.string(), kind);
    const fs::path temp = output.temp_path();
    EXPECT_EQ(fs::is_directory(temp), kind == Kind::folder);
    EXPECT_TRUE(fs::is_empty(temp));
    EXPECT_EQ(temp.parent_path(), target.parent_path());
    EXPECT_NE(temp, target);
    fill(output, kind, "new");
    EXPECT_FALSE(fs::exists(target));
    output.commit();
    EXPECT_EQ(content(target, kind), "new");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST_P(BothKinds, WithoutCommitTheTemporaryGoesAndAnOldOutputStays) {
    put_old(target, kind, "old");
    fs::path temp;
    {
        AtomicOutput output(target.string(), kind);
        temp = output.temp_path();
        fill(output, kind, "half of the new");
    }
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(content(target, kind), "old");
    EXPECT_EQ(entry_count(base.path()), 1);
    // And with no old output, nothing is left at all.
    { AtomicOutput output((fs::path(base.path()) / "fresh").string(), kind); }
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST_P(BothKinds, CommitReplacesAnOldOutput) {
    put_old(target, kind, "old contents, longer than the new");
    AtomicOutput output(target.string(), kind);
    fill(output, kind, "new");
    output.commit();
    EXPECT_EQ(content(target, kind), "new");
    EXPECT_EQ(entry_count(base.path()), 1);  // for a folder: no moved-aside old one left
}

TEST_P(BothKinds, MissingParentIsAnIoErrorAndLeavesNothing) {
    expect_io_error((fs::path(base.path()) / "missing" / "out").string(), kind);
    EXPECT_TRUE(fs::is_empty(fs::path(base.path())));
    // A file as the parent.
    write_bytes(fs::path(base.path()) / "taken", "a file");
    expect_io_error((fs::path(base.path()) / "taken" / "out").string(), kind);
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST_P(BothKinds, EmptyPathIsRejected) {
    try {
        AtomicOutput output("", kind);
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
    }
}

TEST_P(BothKinds, TwoOutputsForOnePathHaveTheirOwnTemporaries) {
    AtomicOutput first(target.string(), kind), second(target.string(), kind);
    EXPECT_NE(first.temp_path(), second.temp_path());
    fill(first, kind, "first");
    fill(second, kind, "second");
    first.commit();
    second.commit();
    EXPECT_EQ(content(target, kind), "second");
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST_P(BothKinds, DotsAndAFolderTrailingSlashAreTheSamePath) {
    fs::create_directory(fs::path(base.path()) / "a");
    const std::string path = (fs::path(base.path()) / "a" / ".." / "out").string() + (kind == Kind::folder ? "/" : "");
    AtomicOutput output(path, kind);
    EXPECT_EQ(fs::path(output.temp_path()).parent_path(), fs::path(base.path()));
    fill(output, kind, "f");
    output.commit();
    EXPECT_EQ(content(target, kind), "f");
    EXPECT_EQ(entry_count(base.path()), 2);  // a and out
}

TEST_P(BothKinds, APathWithoutFolderIsInTheWorkingFolder) {
    const fs::path before = fs::current_path();
    fs::current_path(fs::path(base.path()));
    {
        AtomicOutput output("plain", kind);
        EXPECT_EQ(fs::absolute(output.temp_path()).lexically_normal().parent_path(), fs::path(base.path()));
        fill(output, kind, "f");
        output.commit();
    }
    fs::current_path(before);
    EXPECT_EQ(content(fs::path(base.path()) / "plain", kind), "f");
    EXPECT_EQ(entry_count(base.path()), 1);
}

INSTANTIATE_TEST_SUITE_P(AtomicOutput, BothKinds, testing::Values(Kind::file, Kind::folder),
                         [](const testing::TestParamInfo<Kind>& info) {
                             return std::string(info.param == Kind::file ? "File" : "Folder");
                         });

// --- files -----------------------------------------------------------------

TEST(AtomicOutputFile, IsAnOrdinaryFileReadableByOthers) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "part.stl";
    AtomicOutput output(target.string());  // a file unless told otherwise
    EXPECT_TRUE(fs::is_regular_file(output.temp_path()));
    EXPECT_EQ(fs::path(output.temp_path()).filename().string().rfind("part.stl.partial-", 0), 0u);
    output.commit();
    // Not mkstemp's 0600.
    EXPECT_NE(fs::status(target).permissions() & fs::perms::others_read, fs::perms::none);
}

TEST(AtomicOutputFile, AFailedCommitIsAnIoErrorAndLeavesNoTemporary) {
    TempDir base;
    // A folder (not empty) at the target path: a file cannot be renamed onto it.
    const fs::path target = fs::path(base.path()) / "taken";
    fs::create_directories(target / "inside");
    {
        AtomicOutput output(target.string());
        write_bytes(output.temp_path(), "data");
        try {
            output.commit();
            FAIL() << "no error";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_IO);
        }
    }
    EXPECT_TRUE(fs::is_directory(target / "inside"));
    EXPECT_EQ(entry_count(base.path()), 1);
}

// --- folders ---------------------------------------------------------------

TEST(AtomicOutputFolder, CommitReplacesAnOldFolderWhole) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
    fs::create_directories(target / "old_sub");
    write_bytes(target / "old.txt", "old");
    write_bytes(target / "same.txt", "old version");
    AtomicOutput output(target.string(), Kind::folder);
    fs::create_directory(fs::path(output.temp_path()) / "sub");
    write_bytes(fs::path(output.temp_path()) / "sub" / "part.stl", "nested");
    write_bytes(fs::path(output.temp_path()) / "same.txt", "new version");
    output.commit();
    EXPECT_EQ(read_bytes(target / "same.txt"), "new version");
    EXPECT_EQ(read_bytes(target / "sub" / "part.stl"), "nested");
    EXPECT_FALSE(fs::exists(target / "old.txt"));
    EXPECT_FALSE(fs::exists(target / "old_sub"));
    EXPECT_EQ(entry_count(target), 2);
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicOutputFolder, AFileAtThePathIsAnIoError) {
    TempDir base;
    write_bytes(fs::path(base.path()) / "taken", "a file");
    expect_io_error((fs::path(base.path()) / "taken").string(), Kind::folder);
    EXPECT_EQ(read_bytes(fs::path(base.path()) / "taken"), "a file");
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(AtomicOutputFolder, AFailedCommitIsAnIoErrorAndPutsTheOldFolderBack) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "out";
    fs::create_directory(target);
    write_bytes(target / "old.txt", "old");
    {
        AtomicOutput output(target.string(), Kind::folder);
        fs::remove_all(output.temp_path());  // nothing left to move into place
        try {
            output.commit();
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

// --- write_text_file_atomically ----------------------------------------------

TEST(WriteTextFileAtomically, WritesTheExactBytes) {
    TempDir base;
    const fs::path target = fs::path(base.path()) / "job.json";
    const std::string text = std::string("line one\r\nline two\n") + '\0' + "after a zero byte";
    fabvdb::write_text_file_atomically(target.string(), text);
    EXPECT_EQ(read_bytes(target), text);
    fabvdb::write_text_file_atomically(target.string(), "");
    EXPECT_EQ(read_bytes(target), "");
    EXPECT_EQ(entry_count(base.path()), 1);
}

TEST(WriteTextFileAtomically, MissingFolderIsAnIoError) {
    TempDir base;
    try {
        fabvdb::write_text_file_atomically((fs::path(base.path()) / "no" / "x.txt").string(), "x");
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_TRUE(fs::is_empty(fs::path(base.path())));
}

}  // namespace
