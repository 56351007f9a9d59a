//! Process profiles: the three built-in ones and the JSON reader (see
//! process_profile.h; the values' sources are in docs/check.md).
#include "check/process_profile.h"

#include <cmath>

#include "core/error.h"
#include "io/input_file.h"

namespace fabvdb::check {

namespace {

bool ends_with(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

//! The number at `key` of `document`, if there, into `value`; it must be
//! finite and within [low, high].
void read_number(const nlohmann::json& document, const char* key, double low, double high, double& value,
                 const std::string& source) {
    if (!document.contains(key)) return;
    const nlohmann::json& item = document[key];
    if (!item.is_number() || !std::isfinite(item.get<double>()) || item.get<double>() < low ||
        item.get<double>() > high)
        throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"" + key + "\" must be a number from " + std::to_string(low) +
                                              " to " + std::to_string(high));
    value = item.get<double>();
}

}  // namespace

ProcessProfile builtin_profile(const std::string& name) {
    ProcessProfile p;
    p.name = name;
    p.margin_fraction = 0.2;
    if (name == "sla") {
        p.description = "resin vat photopolymerisation (SLA, DLP, MSLA)";
        p.min_wall = 0.5;
        p.min_pin = 0.5;
        p.min_feature = 0.5;
        p.min_hole = 0.5;
        p.escape_hole = 3.5;
        p.overhang_degrees = 45.0;
        p.cups = true;
    } else if (name == "powder") {
        p.description = "powder bed fusion and binder jetting (SLS, MJF, binder jetting)";
        p.min_wall = 0.7;
        p.min_pin = 1.0;
        p.min_feature = 0.5;
        p.min_hole = 1.5;
        p.escape_hole = 3.5;
        p.overhang_degrees = 90.0;
    } else if (name == "fdm") {
        p.description = "material extrusion (FDM, FFF) with a 0.4 mm nozzle";
        p.min_wall = 0.8;
        p.min_pin = 3.0;
        p.min_feature = 2.0;
        p.min_hole = 2.0;
        p.escape_hole = 0.0;
        p.overhang_degrees = 45.0;
    } else {
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    "no process '" + name + "' (known: sla, powder, fdm, or a JSON profile FILE.json)");
    }
    return p;
}

ProcessProfile profile_from_json(const std::string& text, const std::string& source) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw Error(FABVDB_ERR_BAD_INPUT, source + ": not valid JSON: " + e.what());
    }
    if (!document.is_object()) throw Error(FABVDB_ERR_BAD_INPUT, source + ": a profile must be a JSON object");
    std::string base = "sla";
    if (document.contains("base")) {
        if (!document["base"].is_string())
            throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"base\" must be sla, powder or fdm");
        base = document["base"].get<std::string>();
        if (base != "sla" && base != "powder" && base != "fdm")
            throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"base\" must be sla, powder or fdm, not '" + base + "'");
    }
    ProcessProfile p = builtin_profile(base);
    p.name = source;
    if (document.contains("name")) {
        if (!document["name"].is_string()) throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"name\" must be text");
        p.name = document["name"].get<std::string>();
    }
    if (document.contains("description")) {
        if (!document["description"].is_string())
            throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"description\" must be text");
        p.description = document["description"].get<std::string>();
    }
    read_number(document, "min_wall", 0.01, 100.0, p.min_wall, source);
    read_number(document, "min_pin", 0.01, 100.0, p.min_pin, source);
    read_number(document, "min_feature", 0.0, 1000.0, p.min_feature, source);
    read_number(document, "min_hole", 0.01, 100.0, p.min_hole, source);
    read_number(document, "escape_hole", 0.0, 100.0, p.escape_hole, source);
    read_number(document, "overhang_degrees", 0.0, 90.0, p.overhang_degrees, source);
    read_number(document, "margin_fraction", 0.0, 1.0, p.margin_fraction, source);
    if (document.contains("cups")) {
        if (!document["cups"].is_boolean()) throw Error(FABVDB_ERR_BAD_INPUT, source + ": \"cups\" must be true or false");
        p.cups = document["cups"].get<bool>();
    }
    static const char* known[] = {"base", "name", "description", "min_wall", "min_pin", "min_feature",
                                  "min_hole", "escape_hole", "overhang_degrees", "margin_fraction", "cups"};
    for (const auto& item : document.items()) {
        bool found = false;
        for (const char* key : known) found = found || item.key() == key;
        if (!found) throw Error(FABVDB_ERR_BAD_INPUT, source + ": unknown key \"" + item.key() + "\"");
    }
    return p;
}

ProcessProfile read_profile(const std::string& name_or_path) {
    if (!ends_with(name_or_path, ".json") && !ends_with(name_or_path, ".JSON")) return builtin_profile(name_or_path);
    return profile_from_json(io::read_file_bytes(name_or_path), name_or_path);
}

nlohmann::json profile_json(const ProcessProfile& p) {
    return {{"name", p.name},
            {"description", p.description},
            {"min_wall", p.min_wall},
            {"min_pin", p.min_pin},
            {"min_feature", p.min_feature},
            {"min_hole", p.min_hole},
            {"escape_hole", p.escape_hole},
            {"overhang_degrees", p.overhang_degrees},
            {"margin_fraction", p.margin_fraction},
            {"cups", p.cups}};
}

}  // namespace fabvdb::check
