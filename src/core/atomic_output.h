//! An output — a file or a folder — that appears at its path only when
//! complete: writers fill `temp_path()` (a new file or folder beside the
//! target), then `commit()` renames it into place, replacing an older file or
//! folder of that name. Destroyed without a commit, it removes the temporary,
//! so a failed or cancelled run leaves neither a partial output nor a changed
//! old one. Costs one temporary entry beside the target and one or two
//! renames; nothing is copied.
#pragma once

#include <string>

namespace fabvdb {

class AtomicOutput {
public:
    enum class Kind { file, folder };

    //! `path` names the output; its parent folder must exist. Throws
    //! Error(FABVDB_ERR_INVALID_ARGUMENT) for an empty path and
    //! Error(FABVDB_ERR_IO) if the parent folder does not exist, a folder's
    //! path is a file, or the temporary cannot be created.
    explicit AtomicOutput(std::string path, Kind kind = Kind::file);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    //! The temporary: PATH.partial-XXXXXX for a file (an empty file, mode
    //! 0644), .NAME.partial-XXXXXX beside the target for a folder (empty).
    const std::string& temp_path() const { return temp_path_; }
    //! Moves the temporary into place (an older folder is moved aside first,
    //! put back if the move fails, and removed after); throws Error(IO) on
    //! failure.
    void commit();

private:
    std::string path_;
    std::string temp_path_;
    Kind kind_;
    bool committed_ = false;
};

//! Writes `text` to `path` through an AtomicOutput.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace fabvdb
