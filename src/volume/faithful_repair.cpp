//! The repair held to the fidelity gate, refined where it lost the model
//! (see faithful_repair.h).
#include "volume/faithful_repair.h"

#include <chrono>

#include "core/error.h"
#include "core/figure_text.h"

namespace fabvdb::volume {

namespace {

std::string millimetres(double x) { return figure_text(x) + " mm"; }

}  // namespace

FaithfulRepair faithful_repair(const Mesh& input, const Mesh& source, RepairOptions options, int refinements,
                               const CentredFrame* frame, Progress& progress) {
    FaithfulRepair result;
    for (int attempt = 0;; ++attempt) {
        const double voxel = options.distance.voxel_size;
        RepairResult repaired;
        try {
            repaired = frame ? repair_in_frame(source, options, *frame, progress) : repair(source, options, progress);
        } catch (const Error& e) {
            // A finer voxel than the budget holds, or one at which walls
            // thinner than a voxel before leave no consistent inside: the
            // coarser attempt stands, and its figures say what was tried.
            const bool over_budget = e.status() == FABVDB_ERR_OUT_OF_BUDGET;
            if (attempt == 0 || (!over_budget && e.status() != FABVDB_ERR_BAD_INPUT)) throw;
            result.fidelity.defect += "; at voxel " + millimetres(voxel) +
                                      (over_budget ? " it would exceed the memory budget"
                                                   : " the repair found no consistent inside");
            return result;
        }
        if (attempt > 0)
            result.warnings.push_back(options.distance.input_name + ": at voxel " + millimetres(result.voxels.back()) +
                                      " the repaired surface was not the input's model (" + result.fidelity.defect +
                                      "), so it was repaired again at " + millimetres(voxel));
        // A sheet thickened on purpose lies half its thickness off the
        // input, and encloses a volume the input does not.
        result.limits = voxel_limits(voxel);
        result.limits.distance += 0.5 * options.distance.thicken;
        result.limits.volume = options.distance.thicken == 0.0;
        const auto start = std::chrono::steady_clock::now();
        result.fidelity = measure_fidelity(input, repaired.mesh, result.limits, progress);
        result.fidelity_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.repaired = std::move(repaired);
        result.voxels.push_back(voxel);
        if (attempt == refinements || !finer_may_pass(result.fidelity, result.limits)) return result;
        options.distance.voxel_size = 0.5 * voxel;
    }
}

}  // namespace fabvdb::volume
