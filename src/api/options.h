//! Reading a caller's options struct. Every fabvdb_*_options begins with
//! `size_t struct_size`, set by its _init(). A caller compiled against an
//! older fabvdb.h passes an older, smaller struct: its first struct_size
//! bytes are taken and the fields it does not know keep the defaults of
//! `init`, so adding a field at the end never breaks a caller. NULL gives the
//! defaults. Throws Error(INVALID_ARGUMENT) when struct_size is smaller than
//! the field itself (never set) or larger than this library's struct (a
//! caller built against a newer header). Costs one copy.
#pragma once

#include <cstring>
#include <string>

#include "core/error.h"

namespace fabvdb::api {

template <class Options>
Options options_from(const Options* given, void (*init)(Options*), const char* name) {
    Options options;
    init(&options);
    if (!given) return options;
    const size_t size = given->struct_size;
    if (size < sizeof(size_t))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    std::string(name) + ".struct_size is " + std::to_string(size) + ": set it with " + name + "_init()");
    if (size > sizeof(Options))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    std::string(name) + ".struct_size is " + std::to_string(size) + ", larger than this library's " +
                        std::to_string(sizeof(Options)) + ": the caller was built against a newer fabvdb.h");
    std::memcpy(static_cast<void*>(&options), static_cast<const void*>(given), size);
    options.struct_size = sizeof(Options);
    return options;
}

}  // namespace fabvdb::api
