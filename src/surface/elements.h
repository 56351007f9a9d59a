//! The elements the coarse decomposition assigns (thesis §3.4.3): one per
//! outer triangle (its prism), except that each no-cut set — a thin-feature
//! segment or a user's no-cut stroke — becomes a single element, so it ends up
//! whole in one part. Overlapping no-cut sets merge. Only triangles inside
//! `domain` take part; the others belong to no element.
#pragma once

#include <cstdint>
#include <vector>

#include "surface/shell.h"

namespace fabvdb::surface {

struct Elements {
    std::vector<int> element_of_triangle;          //!< −1 outside the domain
    std::vector<std::vector<uint32_t>> triangles;  //!< per element
    std::vector<std::vector<int>> adjacent;        //!< edge-adjacent elements
};

//! `no_cut_sets`: extra no-cut triangle sets (user strokes); thin segments come
//! from shell.thin_segment. `domain`: per triangle, whether it takes part.
Elements make_elements(const Shell& shell, const std::vector<std::vector<uint32_t>>& no_cut_sets,
                       const std::vector<char>& domain);

}  // namespace fabvdb::surface
