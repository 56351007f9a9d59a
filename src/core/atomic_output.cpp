//! AtomicOutput: mkstemp beside the target, rename on commit, unlink otherwise.
#include "core/atomic_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"

namespace fabvdb {

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
    if (path_.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "empty output path");
    std::string pattern = path_ + ".partial-XXXXXX";
    int fd = mkstemp(pattern.data());
    if (fd < 0) throw Error(FABVDB_ERR_IO, path_ + ": cannot create a file there: " + std::strerror(errno));
    fchmod(fd, 0644);  // mkstemp makes 0600; outputs are ordinary files
    close(fd);
    temp_path_ = pattern;
}

AtomicOutput::~AtomicOutput() {
    if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicOutput::commit() {
    if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
        throw Error(FABVDB_ERR_IO, path_ + ": cannot move the finished file into place: " + std::strerror(errno));
    committed_ = true;
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
