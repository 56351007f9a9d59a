// module.cpp — the extension module fabvdb._fabvdb: the C API of fabvdb.h for
// the Python package `fabvdb` (python/fabvdb/), which gives it the CLI's
// option names and units. Checks that header and library versions agree.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#include "binding.h"

PYBIND11_MODULE(_fabvdb, m) {
    namespace fp = fabvdb_python;
    m.doc() = "fabvdb's C API (fabvdb.h) for the Python package fabvdb; use the package, not this module.";
    if (fabvdb_version_number() != FABVDB_VERSION_NUMBER)
        throw std::runtime_error(std::string("fabvdb: the library is version ") + fabvdb_version_string() +
                                 " but the module was built for " FABVDB_VERSION_STRING);
    m.attr("version") = fabvdb_version_string();
    fp::bind_errors(m);
    fp::bind_context(m);
    fp::bind_mesh(m);
    fp::bind_commands(m);
    fp::bind_session(m);
}
