//! The surface of a swept level set (sweep.h) as a triangle mesh that is an
//! exact double height field along the grid's index z axis (the parting
//! direction d): every line parallel to d crosses it at most twice, by
//! construction, which an iso-surface extractor does not promise. The level
//! set decides, the input mesh supplies the geometry: each index column (i, j)
//! keeps the interval where the level set is inside (one inside run: where
//! other parts split a column, the run column_runs.h keeps), and an end of it
//! that lies on the input surface (the input's level set within a voxel of
//! zero there) is moved to where a ray along the column crosses the input,
//! the nearest crossing facing the same way within 1.5 voxels; other ends
//! (seams between parts, the fills moldability needs) stay on the level set's
//! zero crossing. The shadow of the part is the zero contour of the column
//! minimum (a 2D distance to the shadow), found by marching squares with
//! separated saddles; where the shadow's edge is the input's silhouette (the
//! outside column's ray crosses no input near the inside column's interval),
//! the contour vertex is found by bisecting rays along the grid edge to 1/64
//! of a voxel. Each polygon is fanned from an inside column and lifted twice,
//! to the column tops (facing +d) and bottoms (facing −d), the two sheets
//! sharing the contour vertices; where the input bends inside a cell (a tip
//! along d, a ridge, a steep slope by the silhouette), the fan is made from
//! the input vertex in the cell farthest along d from it instead (over a
//! twentieth of a voxel, on a sheet whose corners all lie on the input), the
//! other sheet there read by a ray; where a contour edge cuts off a corner of
//! the input's silhouette along d inside the cell, the silhouette vertex
//! farthest past it goes in between the edge's ends. The polygons' edges on
//! cell borders stay as they were, so neighbouring cells still meet edge to
//! edge. The result is closed, 2-manifold, outward,
//! without faces parallel to d, without shells under an eighth of a voxel³ or
//! flat (mesh_shells.h), and in world coordinates. Costs one ray per column,
//! six per silhouette edge and one per refined cell (Embree), and a pass over
//! the input's vertices. Cancellable.
#pragma once

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"
#include "volume/surface_ray_caster.h"

namespace fabvdb::volume {

//! The input the part is cut from.
struct InputSurface {
    //! Its level set: the zero crossings a column's kept run should hold, and
    //! where a run end lies on the input surface.
    const openvdb::FloatGrid* level_set = nullptr;
    //! Its triangles and rays at them (both or neither; nullptr: the ends
    //! stay on the swept level set's zero crossings).
    const Mesh* mesh = nullptr;
    const SurfaceRayCaster* rays = nullptr;
    //! +1 when `mesh` faces outward, −1 when it is stored inside out.
    double orientation = 1;
};

//! `swept`: a level set on a linear transform (sweep_double_height_field's
//! result). `input`: nullptr, or the input (a null level set: the longest run
//! is kept). An empty mesh when no column is inside or only noise is (the
//! part vanished).
Mesh double_height_field_mesh(const openvdb::FloatGrid& swept, Progress& progress,
                              const InputSurface* input = nullptr);

}  // namespace fabvdb::volume
