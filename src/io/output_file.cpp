//! write_file_atomically over std::ofstream; write_double over std::to_chars.
#include "io/output_file.h"

#include <charconv>
#include <fstream>
#include <vector>

#include "core/atomic_output.h"
#include "core/error.h"

namespace fabvdb::io {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    AtomicOutput output(path);
    {
        std::vector<char> buffer(1 << 20);
        std::ofstream stream;
        stream.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        stream.open(output.temp_path(), std::ios::binary | std::ios::trunc);
        if (!stream) throw Error(FABVDB_ERR_IO, path + ": cannot write the file");
        write(stream);
        stream.close();
        if (!stream) throw Error(FABVDB_ERR_IO, path + ": write failed (disk full?)");
    }
    output.commit();
}

void write_double(std::ostream& out, double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out.write(text, result.ptr - text);
}

}  // namespace fabvdb::io
