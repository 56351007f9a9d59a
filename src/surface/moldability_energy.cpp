//! moldability_energy: one pass over the part's visible triangles for E_H,
//! one over the outer triangles' precomputed overlap lists for E_L.
#include "surface/moldability_energy.h"

#include <unordered_map>

#include "surface/vec3_ops.h"

namespace fabvdb::surface {

MoldabilityEnergy moldability_energy(const MoldabilityTerms& terms, const PartSurface& surface,
                                     const std::vector<char>& upper, int direction,
                                     const MoldabilityWeights& weights, std::vector<double>* per_triangle) {
    const Vec3& d = terms.directions.directions[direction];
    const Vec3 minus_d = -1.0 * d;
    MoldabilityEnergy energy;
    std::unordered_map<uint32_t, char> outer_upper;
    for (size_t i = 0; i < surface.size(); ++i) {
        if (surface.kind[i] == PartSurface::inner) continue;
        const double u = overhang_term(surface.normal[i], surface.area[i], upper[i] ? d : minus_d, terms.draft);
        energy.overhang += u;
        const uint32_t t = surface.kind[i] == PartSurface::outer ? surface.source[i] : surface.source[i] / 3;
        if (per_triangle) (*per_triangle)[t] += weights.overhang * u;
        if (surface.kind[i] == PartSurface::outer) outer_upper.emplace(t, upper[i]);
    }
    const auto& overlaps = terms.overlaps_along(direction);
    for (const auto& [t, is_upper] : outer_upper)
        for (uint32_t k = overlaps.offset[t]; k < overlaps.offset[t + 1]; ++k) {
            const auto other = outer_upper.find(overlaps.partner[k]);
            if (other == outer_upper.end() || other->second != is_upper) continue;
            const double o = 0.5 * overlaps.area[k];
            energy.overlap += o;
            if (per_triangle) (*per_triangle)[t] += weights.overlap * o;
        }
    energy.total = weights.overhang * energy.overhang + weights.overlap * energy.overlap;
    return energy;
}

}  // namespace fabvdb::surface
