//! A measured figure as messages print it: three significant digits
//! ("0.0375", "1.25e+03"). Pure.
#pragma once

#include <sstream>
#include <string>

namespace fabvdb {

inline std::string figure_text(double x) {
    std::ostringstream text;
    text.precision(3);
    text << x;
    return text.str();
}

}  // namespace fabvdb
