//! Reading and writing triangle meshes: STL (binary and ASCII, sniffed), OBJ,
//! PLY (ASCII and binary of both endiannesses, face lists and triangle strips),
//! OFF and 3MF. The format comes from the extension, in any case. Readers
//! fan-triangulate polygons, keep unreferenced vertices, weld the exactly
//! coincident corners of STL, and reject malformed files with
//! Error(FABVDB_ERR_BAD_INPUT) naming the file and the defect (Error(IO) for a
//! missing or unreadable path). Writers go through AtomicOutput.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::io {

enum class MeshFormat { stl, obj, ply, off, threemf };

//! The format named by the path's extension; throws Error(BAD_INPUT) for an
//! unknown one, naming it and listing the known ones.
MeshFormat format_from_path(const std::string& path);

Mesh read_mesh(const std::string& path, Progress& progress);
void write_mesh(const Mesh& mesh, const std::string& path);

}  // namespace fabvdb::io
