//! STL, binary and ASCII. Reading decides the encoding by content, not by the
//! first word alone (binary files may begin with "solid"): a file whose size is
//! exactly 84 + 50 x (its triangle count) is binary; otherwise a file that
//! begins with "solid" and holds no NUL byte is ASCII (several `solid` blocks,
//! CRLF line ends, any keyword case, polygon loops fan-triangulated); anything
//! else is binary, and rejected if its count announces more triangles than it
//! holds; a binary count of 0 with whole facets after it (a writer that never
//! filled the count in) reads the facets the file holds. Corners with bit-identical coordinates become one vertex, so the
//! vertices are the distinct positions in order of first appearance. Writing
//! produces binary STL (single precision, as the format stores).
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

Mesh read_stl(const std::string& path, Progress& progress);
void write_stl(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
