//! Opening a mesh file for reading: checks that the path names a readable,
//! non-empty regular file, and loads its bytes. Errors name the path: a missing
//! path, a directory or an unreadable file is Error(FABVDB_ERR_IO); an empty
//! file is Error(FABVDB_ERR_BAD_INPUT).
#pragma once

#include <cstdint>
#include <string>

namespace fabvdb::io {

//! The size in bytes of the regular, non-empty file at `path`.
uint64_t readable_file_size(const std::string& path);

//! All bytes of the regular, non-empty file at `path`.
std::string read_file_bytes(const std::string& path);

}  // namespace fabvdb::io
