//! Helpers of the mesh I/O tests: reading a mesh, and checking a read fails
//! with the right status and a message that names the file and the defect;
//! with the temporary folders and raw files of support/temp_files.h.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/mesh_io.h"
#include "support/temp_files.h"

namespace fabvdb::test {

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
