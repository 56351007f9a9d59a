//! Reading the parts of a mold decomposition back from its document
//! (decomposition.json, written by decomposition_io.h) for mold generation:
//! per part its id, parting direction and closed low-resolution solid (the
//! part's surface with its corner ids resolved to positions). Validates
//! everything it uses and that the document belongs to the input mesh: the
//! format and version, every index in range, every part referenced by
//! part_of_triangle present and each part's surface closed (every edge run
//! as often one way as the other: where a part's boundary passes twice
//! through a vertex, four side triangles share that prism edge), and the
//! low-resolution surface lying on the input's surface (a decomposition of
//! another model, or of this one at another scale, does not). Pure functions
//! but for reading the file.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/mesh.h"

namespace fabvdb::surface {

struct DecomposedPart {
    int id = 0;
    Vec3 direction{0, 0, 1};  //!< unit parting direction
    Mesh solid;               //!< closed, outward, mm
};

struct DecomposedModel {
    double shell_thickness = 0;  //!< ω, mm
    std::vector<DecomposedPart> parts;
};

//! `name` names the document in error messages. Throws Error(BAD_INPUT)
//! naming it and the defect.
DecomposedModel decomposed_parts(const nlohmann::json& document, const std::string& name, const Mesh& input);

//! Reads and parses the file first: Error(IO) when it cannot be read,
//! Error(BAD_INPUT) when it is not JSON.
DecomposedModel read_decomposed_parts(const std::string& path, const Mesh& input);

}  // namespace fabvdb::surface
