//! BinaryReader's truncation error.
#include "io/binary_io.h"

#include "core/error.h"

namespace fabvdb::io {

void BinaryReader::fail_truncated(const char* what) const {
    throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": truncated: the file ends while reading " + what);
}

}  // namespace fabvdb::io
