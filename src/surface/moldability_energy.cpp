//! moldability_energy: one pass over the part's visible triangles for E_H,
//! one over the outer triangles' precomputed overlap lists for E_L (sides
//! looked up in a per-S_low-triangle array).
#include "surface/moldability_energy.h"

#include <vector>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

MoldabilityEnergy moldability_energy(const MoldabilityTerms& terms, const PartSurface& surface,
                                     const std::vector<char>& upper, int direction,
                                     const MoldabilityWeights& weights, std::vector<double>* per_triangle) {
    const Vec3& d = terms.directions.directions[direction];
    const Vec3 minus_d = -1.0 * d;
    MoldabilityEnergy energy;
    const auto& overlaps = terms.overlaps_along(direction);
    // Per S_low triangle: -1 not an outer triangle of the part, else its side.
    std::vector<signed char> outer_upper(overlaps.offset.size() - 1, -1);
    for (size_t i = 0; i < surface.size(); ++i) {
        if (surface.kind[i] == PartSurface::inner) continue;
        const double u = overhang_term(surface.normal[i], surface.area[i], upper[i] ? d : minus_d, terms.draft);
        energy.overhang += u;
        const uint32_t t = surface.kind[i] == PartSurface::outer ? surface.source[i] : surface.source[i] / 3;
        if (per_triangle) (*per_triangle)[t] += weights.overhang * u;
        if (surface.kind[i] == PartSurface::outer) outer_upper[t] = upper[i] ? 1 : 0;
    }
    for (size_t i = 0; i < surface.size(); ++i) {
        if (surface.kind[i] != PartSurface::outer) continue;
        const uint32_t t = surface.source[i];
        for (uint32_t k = overlaps.offset[t]; k < overlaps.offset[t + 1]; ++k) {
            if (outer_upper[overlaps.partner[k]] != outer_upper[t]) continue;
            const double o = 0.5 * overlaps.area[k];
            energy.overlap += o;
            if (per_triangle) (*per_triangle)[t] += weights.overlap * o;
        }
    }
    energy.total = weights.overhang * energy.overhang + weights.overlap * energy.overlap;
    return energy;
}

}  // namespace fabvdb::surface
