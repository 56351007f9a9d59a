//! Reading a caller's options struct. Every fabvdb_*_options begins with
//! `size_t struct_size`, set by its _init(). A caller compiled against an
//! older fabvdb.h passes an older, smaller struct: its first struct_size
//! bytes are taken and the fields it does not know keep the defaults of
//! `init`, so adding a field at the end never breaks a caller. NULL gives the
//! defaults. Throws Error(INVALID_ARGUMENT) when struct_size is smaller than
//! the field itself (never set) or larger than this library's struct (a
//! caller built against a newer header). Costs one copy. write_to is the
//! same for a struct the library fills (decomposition info, part info, the
//! options a session has): only the caller's first struct_size bytes are
//! written, struct_size itself stays the caller's.
#pragma once

#include <cstring>
#include <string>

#include "core/error.h"

namespace fabvdb::api {

//! Checks a caller's struct_size against this library's struct.
inline void check_struct_size(size_t size, size_t ours, const char* name) {
    if (size < sizeof(size_t))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    std::string(name) + ".struct_size is " + std::to_string(size) + ": set it with " + name + "_init()");
    if (size > ours)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    std::string(name) + ".struct_size is " + std::to_string(size) + ", larger than this library's " +
                        std::to_string(ours) + ": the caller was built against a newer fabvdb.h");
}

template <class Options>
Options options_from(const Options* given, void (*init)(Options*), const char* name) {
    Options options;
    init(&options);
    if (!given) return options;
    const size_t size = given->struct_size;
    check_struct_size(size, sizeof(Options), name);
    std::memcpy(static_cast<void*>(&options), static_cast<const void*>(given), size);
    options.struct_size = sizeof(Options);
    return options;
}

template <class Struct>
void write_to(const Struct& value, Struct* out, const char* name) {
    const size_t size = out->struct_size;
    check_struct_size(size, sizeof(Struct), name);
    std::memcpy(static_cast<void*>(out), static_cast<const void*>(&value), size);
    out->struct_size = size;
}

}  // namespace fabvdb::api
