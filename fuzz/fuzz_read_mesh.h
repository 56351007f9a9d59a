//! The body every reader fuzzer shares: the input bytes become a file with the
//! format's extension in $TMPDIR (default /tmp; /dev/shm is much faster on a
//! busy machine), one per process so parallel fuzzing jobs do not collide,
//! which read_mesh then reads and which is removed afterwards. A fabvdb::Error is the expected
//! answer to malformed input and is swallowed; anything else (a crash, a
//! sanitizer report, another exception) is a finding.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "io/mesh_io.h"

inline int fuzz_read_mesh(const uint8_t* data, size_t size, const char* extension) {
    static const std::string path = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") +
                                    "/fabvdb-fuzz-" + std::to_string(getpid()) + "." + extension;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) std::abort();
    if (size && std::fwrite(data, 1, size, file) != size) std::abort();
    std::fclose(file);
    try {
        fabvdb::Progress progress;
        fabvdb::io::read_mesh(path, progress);
    } catch (const fabvdb::Error&) {
    }
    std::remove(path.c_str());
    return 0;
}
