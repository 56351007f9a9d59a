//! Writes a heat map's legend as a small PNG: a vertical viridis bar from
//! `low` (bottom) to `high` (top) with five labelled ticks, the unit beside
//! them and a title above (cairo; its toy text API and the system's default
//! sans font). Written atomically (Error(IO) on failure, no partial file).
#pragma once

#include <string>

namespace fabvdb {

void write_colour_bar_png(const std::string& path, const std::string& title, double low, double high,
                          const std::string& unit);

}  // namespace fabvdb
