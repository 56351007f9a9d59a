//! Stanford PLY in all three encodings (ascii, binary_little_endian,
//! binary_big_endian) and with all scalar types. The `vertex` element gives the
//! positions (`x`, `y`, `z`; other properties skipped); the `face` element's
//! `vertex_indices` (or `vertex_index`) list gives polygons, fan-triangulated;
//! a `tristrips` element's `vertex_indices` list is decoded as triangle strips
//! (-1 restarts a strip, every other triangle reversed to keep the winding,
//! degenerate strip-joining triangles dropped). Other elements are skipped.
//! Header counts never size an allocation beyond what the file can hold.
//! Writing produces binary little-endian PLY with double coordinates.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

Mesh read_ply(const std::string& path, Progress& progress);
void write_ply(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
