//! AtomicOutput: mkstemp or mkdtemp beside the target, rename on commit (an
//! old folder moved aside first and removed after), remove otherwise.
#include "core/atomic_output.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"

namespace fabvdb {

namespace fs = std::filesystem;

namespace {

//! `path` without "." and ".." steps or a trailing slash.
std::string normal_path(const std::string& path) {
    std::string normal = fs::path(path).lexically_normal().string();
    if (normal.size() > 1 && normal.back() == '/') normal.pop_back();
    return normal;
}

}  // namespace

AtomicOutput::AtomicOutput(std::string path, Kind kind) : path_(normal_path(path)), kind_(kind) {
    const char* noun = kind == Kind::file ? "file" : "folder";
    if (path.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, std::string("empty output ") + noun);
    const fs::path target(path_);
    const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code error;
    if (!fs::is_directory(parent, error)) throw Error(FABVDB_ERR_IO, path + ": the parent folder does not exist");
    if (kind == Kind::folder && fs::exists(target, error) && !fs::is_directory(target, error))
        throw Error(FABVDB_ERR_IO, path + ": exists and is not a folder");
    // A file's temporary keeps its name visible (tools/batch clears NAME.partial-*
    // that a killed run left); a folder's is hidden.
    const std::string name = (kind == Kind::file ? "" : ".") + target.filename().string() + ".partial-XXXXXX";
    std::string pattern = (parent / name).string();
    if (kind == Kind::file) {
        const int fd = mkstemp(pattern.data());
        if (fd < 0) throw Error(FABVDB_ERR_IO, path + ": cannot create a file there: " + std::strerror(errno));
        fchmod(fd, 0644);  // mkstemp makes 0600; outputs are ordinary files
        close(fd);
    } else if (!mkdtemp(pattern.data())) {
        throw Error(FABVDB_ERR_IO, path + ": cannot create a folder beside it: " + std::strerror(errno));
    }
    temp_path_ = pattern;
}

AtomicOutput::~AtomicOutput() {
    std::error_code error;
    if (!committed_) fs::remove_all(temp_path_, error);
}

void AtomicOutput::commit() {
    // rename(2) replaces a file in one step but not a non-empty folder, so an
    // older folder goes aside into a fresh temporary folder first.
    std::error_code error;
    const bool replacing = kind_ == Kind::folder && fs::exists(path_, error);
    std::string old = path_ + ".old-XXXXXX";
    if (replacing) {
        if (!mkdtemp(old.data()))
            throw Error(FABVDB_ERR_IO, path_ + ": cannot move the old folder aside: " + std::strerror(errno));
        fs::rename(path_, fs::path(old) / "folder", error);
        if (error) {
            fs::remove(old, error);
            throw Error(FABVDB_ERR_IO, path_ + ": cannot move the old folder aside");
        }
    }
    fs::rename(temp_path_, path_, error);
    if (error) {
        const std::string reason = error.message();
        if (replacing) {
            fs::rename(fs::path(old) / "folder", path_, error);
            if (!error) fs::remove(old, error);
        }
        throw Error(FABVDB_ERR_IO, path_ + ": cannot move the finished " + (kind_ == Kind::file ? "file" : "folder") +
                                       " into place: " + reason);
    }
    committed_ = true;
    if (replacing) fs::remove_all(old, error);
}

void write_text_file_atomically(const std::string& path, const std::string& text) {
    AtomicOutput out(path);
    {
        std::ofstream stream(out.temp_path(), std::ios::binary | std::ios::trunc);
        stream << text;
        stream.flush();
        if (!stream) throw Error(FABVDB_ERR_IO, path + ": write failed");
    }
    out.commit();
}

}  // namespace fabvdb
