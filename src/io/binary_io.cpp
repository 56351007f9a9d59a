//! BinaryReader's truncation error.
#include "io/binary_io.h"

#include "core/error.h"

namespace fabvdb::io {

void BinaryReader::fail_truncated(const char* what) const {
    throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": truncated: the file ends at byte " + std::to_string(bytes_.size()) +
                                          " while reading " + what);
}

}  // namespace fabvdb::io
