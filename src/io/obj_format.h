//! Wavefront OBJ geometry: `v x y z` vertices (extra values such as w or
//! colours ignored) and `f` faces whose corners may be written `a`, `a/b`,
//! `a//c` or `a/b/c`, with 1-based or negative (relative to the vertices read so
//! far) indices; polygons are fan-triangulated. Backslash-continued lines are
//! joined. Texture, normal, material, group, smoothing and line/point records
//! are ignored; vertices no face uses are kept. Writing produces `v` and `f`
//! records with coordinates that read back exactly.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

Mesh read_obj(const std::string& path, Progress& progress);
void write_obj(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
