//! Writing a mesh file: the bytes go to an AtomicOutput's temporary file
//! through a buffered stream and the file is renamed into place only when the
//! whole content was written, so a failed write leaves no partial output.
//! Also the number formatting the text writers share.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace fabvdb::io {

//! Runs `write` on a stream to a temporary file beside `path`, then moves it to
//! `path`. Throws Error(FABVDB_ERR_IO) naming `path` if anything fails.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

//! Writes the shortest decimal text that reads back as exactly `value`.
void write_double(std::ostream& out, double value);

}  // namespace fabvdb::io
