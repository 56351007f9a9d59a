//! AtomicFolder: mkdtemp beside the target, rename on commit (the old folder
//! moved aside first and removed after), remove otherwise.
#include "core/atomic_folder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace fabvdb {

namespace fs = std::filesystem;

AtomicFolder::AtomicFolder(std::string path) : path_(fs::path(path).lexically_normal().string()) {
    if (path.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "empty output folder");
    if (!path_.empty() && path_.back() == '/' && path_.size() > 1) path_.pop_back();
    const fs::path target(path_);
    const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code error;
    if (!fs::is_directory(parent, error)) throw Error(FABVDB_ERR_IO, path + ": the parent folder does not exist");
    if (fs::exists(target, error) && !fs::is_directory(target, error))
        throw Error(FABVDB_ERR_IO, path + ": exists and is not a folder");
    std::string pattern = (parent / ("." + target.filename().string() + ".partial-XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
        throw Error(FABVDB_ERR_IO, path + ": cannot create a folder beside it: " + std::strerror(errno));
    temp_path_ = pattern;
}

AtomicFolder::~AtomicFolder() {
    std::error_code error;
    if (!committed_) fs::remove_all(temp_path_, error);
}

void AtomicFolder::commit() {
    std::error_code error;
    const bool replacing = fs::exists(path_, error);
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
        if (replacing) {
            fs::rename(fs::path(old) / "folder", path_, error);
            if (!error) fs::remove(old, error);
        }
        throw Error(FABVDB_ERR_IO, path_ + ": cannot move the finished folder into place");
    }
    committed_ = true;
    if (replacing) fs::remove_all(old, error);
}

}  // namespace fabvdb
