//! Input file checks with stat(2) and a whole-file read.
#include "io/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "core/error.h"

namespace fabvdb::io {

uint64_t readable_file_size(const std::string& path) {
    struct stat info {};
    if (stat(path.c_str(), &info) != 0)
        throw Error(FABVDB_ERR_IO, path + ": cannot open: " + std::strerror(errno));
    if (S_ISDIR(info.st_mode)) throw Error(FABVDB_ERR_IO, path + ": is a directory, not a mesh file");
    if (!S_ISREG(info.st_mode)) throw Error(FABVDB_ERR_IO, path + ": is not a regular file");
    if (info.st_size == 0) throw Error(FABVDB_ERR_BAD_INPUT, path + ": empty file");
    return static_cast<uint64_t>(info.st_size);
}

std::string read_file_bytes(const std::string& path) {
    const uint64_t size = readable_file_size(path);
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw Error(FABVDB_ERR_IO, path + ": cannot open: " + std::strerror(errno));
    std::string bytes(size, '\0');
    const size_t read = std::fread(bytes.data(), 1, bytes.size(), file);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed || read != size) throw Error(FABVDB_ERR_IO, path + ": read failed");
    return bytes;
}

}  // namespace fabvdb::io
