//! C API: reports (JSON documents) — text, look-up of numbers, strings and
//! element counts by JSON pointer, atomic write.
#include "api/guard.h"
#include "core/atomic_output.h"

namespace fabvdb::api {

namespace {

//! The value at `pointer`: INVALID_ARGUMENT for a malformed pointer,
//! NOT_FOUND when nothing is there.
const nlohmann::json& value_at(const fabvdb_report* report, const char* pointer) {
    require(report, "report");
    require(pointer, "pointer");
    nlohmann::json::json_pointer where;
    try {
        where = nlohmann::json::json_pointer(pointer);
    } catch (const nlohmann::json::exception&) {
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, std::string("not a JSON pointer: ") + pointer);
    }
    if (!report->document.contains(where)) throw Error(FABVDB_ERR_NOT_FOUND, std::string("no value at ") + pointer);
    return report->document.at(where);
}

}  // namespace

fabvdb_report* new_report_handle(nlohmann::json document) {
    auto* report = new fabvdb_report();
    report->document = std::move(document);
    report->text = report->document.dump(2) + "\n";
    return report;
}

}  // namespace fabvdb::api

extern "C" {

void fabvdb_report_free(fabvdb_report* report) { delete report; }

const char* fabvdb_report_json(const fabvdb_report* report) { return report ? report->text.c_str() : nullptr; }

fabvdb_status fabvdb_report_number(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer, double* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(out, "out");
        const nlohmann::json& value = fabvdb::api::value_at(report, pointer);
        if (value.is_boolean())
            *out = value.get<bool>() ? 1.0 : 0.0;
        else if (value.is_number())
            *out = value.get<double>();
        else
            throw fabvdb::Error(FABVDB_ERR_NOT_FOUND, std::string("the value at ") + pointer + " is not a number");
    });
}

fabvdb_status fabvdb_report_string(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer,
                                   const char** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(out, "out");
        const nlohmann::json& value = fabvdb::api::value_at(report, pointer);
        if (!value.is_string())
            throw fabvdb::Error(FABVDB_ERR_NOT_FOUND, std::string("the value at ") + pointer + " is not a string");
        *out = value.get_ref<const std::string&>().c_str();
    });
}

fabvdb_status fabvdb_report_count(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer, size_t* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(out, "out");
        const nlohmann::json& value = fabvdb::api::value_at(report, pointer);
        if (!value.is_array() && !value.is_object())
            throw fabvdb::Error(FABVDB_ERR_NOT_FOUND, std::string("the value at ") + pointer + " is neither an array nor an object");
        *out = value.size();
    });
}

fabvdb_status fabvdb_report_write(fabvdb_ctx* ctx, const fabvdb_report* report, const char* path) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(report, "report");
        fabvdb::api::require(path, "path");
        fabvdb::write_text_file_atomically(path, report->text);
    });
}

}  // extern "C"
