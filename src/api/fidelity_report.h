//! The fidelity gate's figures as a report section (volume/input_fidelity.h),
//! the same in every command's report: the limits it was held to, what was
//! measured, and whether it passed.
#pragma once

#include <nlohmann/json.hpp>

#include "volume/input_fidelity.h"

namespace fabvdb::api {

nlohmann::json fidelity_report(const volume::Fidelity& fidelity, const volume::FidelityLimits& limits);

//! The section for an output that is the input itself, unchanged.
nlohmann::json fidelity_report_kept();

}  // namespace fabvdb::api
