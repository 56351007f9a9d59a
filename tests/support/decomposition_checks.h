//! Independent checks of a decomposition.json written by fabvdb decompose,
//! for tests (gtest expectations; no code shared with the decomposition): it
//! is read back as plain JSON and measured with code of its own — ownership of
//! every S_low triangle (disjoint, covering), edge-adjacency pieces of each
//! part and of its M⁺ and M⁻ surface triangles (one of each per piece of the
//! part's surface: a part that is a whole closed shell has its inner surface
//! apart), the overhang energy of every
//! part evaluated from the written triangles against the reported one — and
//! the part boundaries measured from the written triangles and labels
//! (length, and turning: the sum over boundary vertices with two boundary
//! edges of the angle by which the boundary bends there).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fabvdb::test {

struct BoundaryMeasure {
    double length = 0;   //!< mm
    double turning = 0;  //!< radians
    size_t vertices = 0; //!< boundary vertices with two boundary edges
};

//! Reads the document at `path`.
nlohmann::json read_decomposition(const std::string& path);

//! Expects (gtest) the checks above to pass on `doc`; returns the part areas (mm²).
std::vector<double> check_decomposition(const nlohmann::json& doc);

//! The part boundaries of `doc`, measured on its written S_low.
BoundaryMeasure measure_boundaries(const nlohmann::json& doc);

}  // namespace fabvdb::test
