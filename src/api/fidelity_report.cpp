//! The fidelity gate's report section (see fidelity_report.h).
#include "api/fidelity_report.h"

namespace fabvdb::api {

nlohmann::json fidelity_report(const volume::Fidelity& fidelity, const volume::FidelityLimits& limits) {
    nlohmann::json report = {{"passed", fidelity.passed},
                             {"max_distance", fidelity.max},
                             {"mean_distance", fidelity.mean},
                             {"far_fraction", fidelity.far_share},
                             {"far_sheet_fraction", fidelity.far_sheet_share},
                             {"far_distance", limits.distance},
                             {"allowed_far_fraction", limits.far_share},
                             {"samples", fidelity.samples},
                             {"left_out_samples", fidelity.left_out},
                             {"exempt_balls", limits.exempt.size()},
                             {"oriented_reference", fidelity.oriented_reference}};
    if (limits.volume) {
        report["input_volume"] = fidelity.input_volume;
        report["output_volume"] = fidelity.output_volume;
        report["tolerance_volume"] = fidelity.volume_tolerance;
        report["volume_compared"] = fidelity.volume_compared;
    }
    if (!fidelity.passed) report["defect"] = fidelity.defect;
    return report;
}

nlohmann::json fidelity_report_kept() {
    return {{"passed", true}, {"kept_input", true}, {"max_distance", 0.0}, {"mean_distance", 0.0}};
}

}  // namespace fabvdb::api
