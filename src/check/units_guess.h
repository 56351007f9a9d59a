//! Whether a part's size suggests it was exported in other units than
//! millimetres: a part whose longest side is under 10 mm or over 1000 mm is
//! suspicious, and each reading that brings that side between 10 and 1000 mm
//! is offered with the scale that fixes it — metres (× 1000), inches
//! (× 25.4) and centimetres (× 10) for a small part, micrometres (× 0.001)
//! for a huge one — the most likely first (metres below 1 mm, then inches:
//! CAD exports in inches are common, centimetres rare). A size between 10 and
//! 1000 mm passes. Never fails: a tiny part may be meant. Pure.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::check {

struct UnitsReading {
    std::string unit;     //!< "m", "in", "cm", "um"
    double scale = 1.0;   //!< the factor that turns the file's numbers into mm
    double longest = 0.0; //!< the longest side after scaling, mm
};

struct UnitsGuess {
    bool suspicious = false;              //!< the size is outside 10 to 1000 mm
    double longest = 0.0;                 //!< the longest bounding-box side as read, mm
    std::vector<UnitsReading> readings;   //!< plausible other readings, most likely first
};

UnitsGuess guess_units(const BoundingBox& box);

}  // namespace fabvdb::check
