//! Writing a mesh that must be the clean boundary of a solid, as the last
//! step of every command that outputs one. The mesh is checked as the file
//! will hold it — coordinates rounded to floats for STL and 3MF, and STL's
//! corners welded where they coincide, as a reader sees them — with
//! check_solid (volume/clean_solid.h: closed, 2-manifold, no degenerate
//! triangle, no two triangles crossing, bounding a volume). When the float
//! rounding alone breaks it, the rounding is redone without crossings
//! (float_rounding.h) and checked again. A mesh that still fails is not
//! written: Error(status) names the file and the defects found (inspect.h),
//! and no file appears. Costs one exact crossing test of the output (two when
//! the rounding must be redone); reports progress, throws Error(CANCELLED).
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"
#include "fabvdb.h"
#include "io/mesh_io.h"

namespace fabvdb::surface {

//! The mesh as a file of `format` stores it and a reader reads it back.
Mesh mesh_as_written(const Mesh& mesh, io::MeshFormat format);

//! Empty when `mesh` is the clean boundary of a solid; else the defects in
//! words ("12 boundary edges, 3 crossing triangle pairs").
std::string solid_defects(const Mesh& mesh, Progress& progress);

//! `status`: what a failure is reported as (FABVDB_ERR_INTERNAL when the
//! caller made the mesh, FABVDB_ERR_BAD_INPUT when it passes the input on).
void write_solid_mesh(const Mesh& mesh, const std::string& path, Progress& progress,
                      fabvdb_status status = FABVDB_ERR_INTERNAL);

}  // namespace fabvdb::surface
