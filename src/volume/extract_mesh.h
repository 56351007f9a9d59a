//! Extraction of the zero iso-surface of a level set as a triangle mesh.
//! Takes a FloatGrid level set (world units mm, negative inside) and an
//! adaptivity in [0, 1] (0: uniform, every voxel crossing gives a vertex);
//! returns OpenVDB's `volumeToMesh` surface with quads split along their
//! shorter diagonal, triangles oriented outward, vertices shared, no two
//! at one position (where sheets touch at a point, each copy is moved 1% of
//! the way toward the centre of its ring, into its own sheet), and without
//! shells, solid or void, under an eighth of a voxel³ in volume or flat
//! (mesh_shells.h; sign noise: crumbs and slivers). An empty level set gives
//! an empty mesh. Checks cancellation between stages.
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! The isovalue the zero surface is extracted at: a ten-thousandth of a voxel
//! above 0, so samples that are exactly 0 (a flat face through voxel centres)
//! count as inside instead of making duplicate vertices and folded triangles.
double surface_isovalue(const openvdb::FloatGrid& grid);

//! `shells_dropped`, when given, receives the number of shells dropped as noise.
Mesh extract_mesh(const openvdb::FloatGrid& grid, double adaptivity, Progress& progress,
                  uint64_t* shells_dropped = nullptr);

}  // namespace fabvdb::volume
