//! Overhang removal by as-rigid-as-possible deformation (thesis §3.6.2, the
//! step before the sweep): a part that is not a double height field along its
//! parting direction d has lines parallel to d that leave it and enter it
//! again; where such a gap is small (at most twice `max_displacement`), the
//! two faces across it are pulled together instead of the sweep filling it.
//! Takes the part as a level set and d; extracts its surface, finds every
//! vertex whose face looks into a small empty gap along ±d (empty: outside
//! the part and outside every `keep_out` solid), makes those vertices handles
//! moved halfway across the gap, lets the vertices within `region_radius`
//! of a handle (straight-line, so both faces of a thin overhang) follow by CGAL's Surface_mesh_deformation (SRE-ARAP),
//! keeps the rest fixed (and every vertex within a voxel of a keep-out solid,
//! so nothing is dragged into another part), and gives the voxels near both
//! the moved vertices and the deformed surface the deformed surface's signed
//! distance (the others keep the part's own values). Handles move at most
//! `max_displacement`; the free vertices follow them as rigidly as possible
//! (the result reports how far they went). Returns the part unchanged when it
//! has no small gap or the ARAP system cannot be factored. Cancellable.
#pragma once

#include <cstddef>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

struct OverhangDeformationOptions {
    //! mm (> 0): how far a handle may move; gaps up to twice this are closed.
    double max_displacement = 0.0;
    //! mm (>= 0): how far (straight-line) from a handle vertices may follow
    //! it; 0: four times max_displacement.
    double region_radius = 0.0;
    //! ARAP iterations (>= 1).
    int iterations = 8;
};

struct OverhangDeformation {
    openvdb::FloatGrid::Ptr part;  //!< the deformed level set (the input itself when nothing moved)
    size_t handles = 0;            //!< vertices moved across a gap
    size_t moved_vertices = 0;     //!< handles and the free vertices that followed them
    double max_displacement = 0;   //!< mm, over all vertices
    double mean_displacement = 0;  //!< mm, over the moved vertices
    double volume_before = 0;      //!< mm³, of the input level set
    double volume_after = 0;       //!< mm³, of the result
};

//! `part`: a level set (GRID_LEVEL_SET, uniform voxels). `direction`: d, any
//! non-zero length. `keep_out`: level sets of the solids a gap must not be in
//! (the other parts). Throws Error(INVALID_ARGUMENT) for options out of range
//! or a non level set, CANCELLED.
OverhangDeformation deform_overhangs(const openvdb::FloatGrid& part, const Vec3& direction,
                                     const std::vector<openvdb::FloatGrid::ConstPtr>& keep_out,
                                     const OverhangDeformationOptions& options, Progress& progress);

}  // namespace fabvdb::surface
