//! The thresholds a printing process sets for a part (docs/check.md gives
//! each value's source): minimum wall, pin diameter, feature size and hole
//! width, the escape holes a sealed cavity needs, the overhang angle that
//! prints without support, the margin above a minimum that only warns, and
//! whether cups (pockets sealed against a vat film) matter.
//! Three built in — "sla" (resin: SLA, DLP, MSLA), "powder" (SLS, MJF,
//! binder jetting), "fdm" — and a farm's own as a JSON file whose keys are
//! those of ProcessProfile, starting from a built-in one named by "base"
//! (default "sla"). Unknown names are Error(INVALID_ARGUMENT); a file that
//! cannot be read is Error(IO), one that is not such JSON Error(BAD_INPUT),
//! each naming the file. Pure but for reading the file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace fabvdb::check {

struct ProcessProfile {
    std::string name;              //!< "sla", "powder", "fdm", or the file's "name" (else its path)
    std::string description;       //!< the processes it stands for, in words
    double min_wall = 0.0;         //!< mm, the thinnest wall that prints and survives
    double min_pin = 0.0;          //!< mm, the thinnest pin or post diameter
    double min_feature = 0.0;      //!< mm, the smallest separate piece (its longest side)
    double min_hole = 0.0;         //!< mm, the narrowest hole, channel or slot that stays open
    double escape_hole = 0.0;      //!< mm, escape-hole diameter a sealed cavity needs; 0: cavities print sealed
    double overhang_degrees = 0.0; //!< the largest tilt from vertical printed without support; 90: never needs any
    double margin_fraction = 0.0;  //!< a figure under (1 + margin_fraction) × its minimum warns
    bool cups = false;             //!< layers are cured against a vat film: pockets sealed by it are checked
};

//! The built-in profile called `name` ("sla", "powder", "fdm").
ProcessProfile builtin_profile(const std::string& name);

//! A profile from JSON text; `source` names it in messages.
ProcessProfile profile_from_json(const std::string& text, const std::string& source);

//! A built-in name, or the path of a JSON profile (it ends in .json).
ProcessProfile read_profile(const std::string& name_or_path);

//! The profile as the report gives it.
nlohmann::json profile_json(const ProcessProfile& profile);

}  // namespace fabvdb::check
