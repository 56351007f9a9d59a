//! Fixed-size numbers in binary mesh files (STL, binary PLY): a bounds-checked
//! reader over a file's bytes in either byte order, and a little-endian writer.
//! Reading past the end throws Error(FABVDB_ERR_BAD_INPUT) "<path>: truncated
//! ...", so a header count larger than the file never reads out of bounds.
#pragma once

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

namespace fabvdb::io {

template <typename T>
T reverse_bytes(T value) {
    static_assert(std::is_arithmetic_v<T>);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

constexpr bool host_is_big_endian = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;

class BinaryReader {
public:
    //! `bytes` must outlive the reader; `path` names the file in messages.
    BinaryReader(std::string_view bytes, std::string path, bool big_endian)
        : bytes_(bytes), path_(std::move(path)), swap_(big_endian != host_is_big_endian) {}

    template <typename T>
    T read(const char* what) {
        if (remaining() < sizeof(T)) fail_truncated(what);
        T value;
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return swap_ ? reverse_bytes(value) : value;
    }

    void skip(size_t count, const char* what) {
        if (remaining() < count) fail_truncated(what);
        pos_ += count;
    }

    size_t position() const { return pos_; }
    size_t remaining() const { return bytes_.size() - pos_; }
    size_t size() const { return bytes_.size(); }

    //! Throws Error(BAD_INPUT) "<path>: truncated: the file ends while reading <what>".
    [[noreturn]] void fail_truncated(const char* what) const;

private:
    std::string_view bytes_;
    std::string path_;
    bool swap_;
    size_t pos_ = 0;
};

//! Stores `value` little-endian at `at`; returns the byte after it.
template <typename T>
char* store_little_endian(char* at, T value) {
    if (host_is_big_endian) value = reverse_bytes(value);
    std::memcpy(at, &value, sizeof(T));
    return at + sizeof(T);
}

template <typename T>
void write_little_endian(std::ostream& out, T value) {
    char bytes[sizeof(T)];
    store_little_endian(bytes, value);
    out.write(bytes, sizeof(T));
}

}  // namespace fabvdb::io
