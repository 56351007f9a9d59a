//! Object File Format (OFF): the `OFF` keyword (also the COFF/NOFF/CNOFF/STOFF
//! variants, whose extra per-vertex values are ignored), the vertex, face and
//! edge counts on the keyword's line or the next, `#` comments and blank lines
//! anywhere, then one vertex per line (first three values used) and one face
//! per line: a corner count, the corners (0-based), and optional colour values,
//! which are ignored. Polygons are fan-triangulated. Writing produces plain OFF
//! with coordinates that read back exactly.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

Mesh read_off(const std::string& path, Progress& progress);
void write_off(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
