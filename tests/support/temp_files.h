//! Files for tests: a temporary folder that removes itself with what it
//! holds, and reading, writing and counting files byte for byte.
#pragma once

#include <string>

namespace fabvdb::test {

//! A fresh folder under the system's temporary folder (mkdtemp), removed
//! with its contents when the object goes.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    //! `name` inside the folder.
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

//! Writes `bytes` to `path` (replacing it); returns `path`.
std::string write_bytes(const std::string& path, const std::string& bytes);

//! The bytes of the file at `path` (empty when it cannot be read).
std::string read_bytes(const std::string& path);

//! Files and folders directly in `folder`.
int entry_count(const std::string& folder);

}  // namespace fabvdb::test
