//! A folder that appears at its path only when complete: writers fill
//! `temp_path()` (a new folder beside the target), then `commit()` renames it
//! into place, replacing an older folder of that name. Destroyed without a
//! commit, it removes the temporary folder, so a failed or cancelled run
//! leaves neither a partial folder nor a changed old one.
#pragma once

#include <string>

namespace fabvdb {

class AtomicFolder {
public:
    //! Throws Error(FABVDB_ERR_IO) if the parent folder does not exist, the
    //! path is a file, or the temporary folder cannot be created.
    explicit AtomicFolder(std::string path);
    ~AtomicFolder();
    AtomicFolder(const AtomicFolder&) = delete;
    AtomicFolder& operator=(const AtomicFolder&) = delete;

    const std::string& temp_path() const { return temp_path_; }
    //! Moves the folder into place; throws Error(IO) on failure.
    void commit();

private:
    std::string path_;
    std::string temp_path_;
    bool committed_ = false;
};

}  // namespace fabvdb
