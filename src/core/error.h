//! The one exception type of the core: a status code and a message for the
//! user. The API firewall (src/api/guard.h) turns it into the call's status and
//! last-error text; nothing else is caught or rethrown in between.
#pragma once

#include <stdexcept>
#include <string>

#include "fabvdb.h"

namespace fabvdb {

class Error : public std::runtime_error {
public:
    Error(fabvdb_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    fabvdb_status status() const { return status_; }

private:
    fabvdb_status status_;
};

}  // namespace fabvdb
