//! Helpers of the mesh I/O tests: a temporary folder that removes itself,
//! writing raw bytes to a file, reading a mesh, and checking a read fails with
//! the right status and a message that names the file and the defect.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "io/mesh_io.h"

namespace fabvdb::test {

class TempDir {
public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "fabvdb-io-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

inline std::string write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
    return path;
}

inline Mesh read(const std::string& path) {
    Progress progress;
    return io::read_mesh(path, progress);
}

//! read_mesh(path) must throw Error(status) whose message contains the path and `defect`.
inline void expect_read_error(const std::string& path, fabvdb_status status, const std::string& defect) {
    SCOPED_TRACE(path);
    try {
        read(path);
        ADD_FAILURE() << "read succeeded; expected an error about: " << defect;
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), status) << e.what();
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find(defect), std::string::npos) << message;
    }
}

}  // namespace fabvdb::test
