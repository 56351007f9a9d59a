//! 3MF (3D Manufacturing Format) through lib3mf 1.8. Reading gathers the
//! meshes of every build item, following components objects, with the item and
//! component transforms applied, and scales the model's unit to millimetres;
//! each mesh object instance keeps its own vertices. A file that is not a valid
//! 3MF package (not a zip, no model part, malformed XML) is
//! Error(FABVDB_ERR_BAD_INPUT) with lib3mf's reason. Writing produces one mesh
//! object (at least one triangle) in millimetres with one build item; lib3mf
//! 1.8 stores coordinates in single precision printed with six decimals, so
//! they come back within about 1e-6 mm (plus single-precision rounding).
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

Mesh read_3mf(const std::string& path, Progress& progress);
void write_3mf(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
