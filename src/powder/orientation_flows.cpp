//! S(g) and floor regions for a set of orientations (see orientation_flows.h).
#include "powder/orientation_flows.h"

#include <atomic>

#include <tbb/parallel_for.h>

#include "powder/settle_matrix.h"

namespace fabvdb::powder {

namespace {

OrientationFlow flow_for(const CavityPatches& patches, const volume::SurfaceRayCaster& caster, const Vec3& gravity,
                         const TransferOptions& options) {
    OrientationFlow flow;
    flow.gravity = gravity;
    flow.settle = settle_matrix(transfer_matrix(patches, caster, gravity, options), patches, gravity);
    const size_t n = patches.size();
    flow.main_destination.resize(n);
    std::vector<char> resting(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t begin = flow.settle.row_start[i], end = flow.settle.row_start[i + 1];
        uint32_t best = begin;
        for (uint32_t e = begin; e < end; ++e)
            if (flow.settle.weight[e] > flow.settle.weight[best]) best = e;
        flow.main_destination[i] = flow.settle.column[best];
        resting[i] = (end - begin == 1 && flow.settle.column[begin] == i);
    }
    flow.region.assign(n, -1);
    int32_t regions = 0;
    std::vector<uint32_t> stack;
    for (uint32_t seed = 0; seed < n; ++seed) {
        if (!resting[seed] || flow.region[seed] >= 0) continue;
        flow.region[seed] = regions;
        stack.push_back(seed);
        while (!stack.empty()) {
            const uint32_t p = stack.back();
            stack.pop_back();
            for (const PatchNeighbour& neighbour : patches.neighbours[p])
                if (resting[neighbour.patch] && flow.region[neighbour.patch] < 0) {
                    flow.region[neighbour.patch] = regions;
                    stack.push_back(neighbour.patch);
                }
        }
        ++regions;
    }
    return flow;
}

}  // namespace

std::vector<OrientationFlow> build_orientation_flows(const CavityPatches& patches, const volume::SurfaceRayCaster& caster,
                                                     const std::vector<Vec3>& gravities,
                                                     const TransferOptions& options, Progress& progress) {
    progress.stage("powder flow");
    std::vector<OrientationFlow> flows(gravities.size());
    std::atomic<size_t> done{0};
    tbb::parallel_for(size_t(0), gravities.size(), [&](size_t k) {
        if (progress.cancelled()) return;
        flows[k] = flow_for(patches, caster, gravities[k], options);
        ++done;
    });
    progress.check();
    progress.update(1.0);
    return flows;
}

}  // namespace fabvdb::powder
