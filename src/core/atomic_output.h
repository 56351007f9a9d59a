//! A file that appears at its path only when complete: writers write to
//! `temp_path()` (a new file in the same folder), then `commit()` renames it
//! into place. Destroyed without a commit, it removes the temporary file, so a
//! failed or cancelled run never leaves a half-written output.
#pragma once

#include <string>

namespace fabvdb {

class AtomicOutput {
public:
    //! Throws Error(FABVDB_ERR_IO) if the folder of `path` cannot take a file.
    explicit AtomicOutput(std::string path);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    const std::string& temp_path() const { return temp_path_; }
    //! Renames the temporary file to the final path; throws Error(IO) on failure.
    void commit();

private:
    std::string path_;
    std::string temp_path_;
    bool committed_ = false;
};

//! Writes `text` to `path` through an AtomicOutput.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace fabvdb
