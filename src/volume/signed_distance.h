//! Robust signed distance from a dirty triangle mesh: holes, self-
//! intersections, flipped or inconsistent orientation, duplicated triangles,
//! unwelded soups, overlapping and nested shells. Inside is decided by the
//! generalized winding number (w >= 1/2) of the consistently oriented input,
//! so holes close along the winding-number surface, inverted shells count as
//! solids and overlapping shells unite. Returns a narrow-band level set
//! (class GRID_LEVEL_SET, world units mm, negative inside, background
//! half_band_voxels * voxel_size) that is a true signed distance field of its
//! zero surface. Refuses with Error(OUT_OF_BUDGET) before allocating more than
//! the budget, with Error(BAD_INPUT) when the input encloses no volume (unless
//! `thicken` > 0), and is cancellable (Error(CANCELLED), no partial result).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct SignedDistanceOptions {
    //! Edge length of a voxel in mm; must be > 0.
    double voxel_size = 0.0;
    //! Half width of the narrow band on each side of the surface, in voxels (>= 2).
    int half_band_voxels = 3;
    //! Refuse (Error(OUT_OF_BUDGET)) when the estimated memory exceeds this; 0: no limit.
    uint64_t memory_budget_bytes = 0;
    //! > 0: an input that encloses no volume becomes a solid sheet of this
    //! thickness (mm) around its surface instead of an error.
    double thicken = 0.0;
    //! What the input is called in error messages (usually its file name).
    std::string input_name = "mesh";
    //! true: the input is already orient_soup's output (the mesh-level
    //! repair made it), so it is not oriented again.
    bool oriented = false;
};

//! Figures about one conversion, for reports.
struct SignedDistanceStats {
    uint64_t active_voxels = 0;
    uint64_t estimated_bytes = 0;
    //! true when the band had to be rebuilt from the winding-number surface
    //! (holes, interior or overlapping triangles); false for clean inputs.
    bool rebuilt = false;
    //! true when the input enclosed no volume and was thickened.
    bool thickened = false;
    //! Share of the input's area beside which the winding number reaches
    //! 0.9 (enclosed_share.h): under 0.1 the input encloses no volume.
    double enclosed_share = 0.0;
    //! Seconds per stage, by stage name.
    std::map<std::string, double> timings;
};

//! The input as the distance was taken from, for finding its closest points
//! later without a search structure of its own.
struct OrientedInput {
    //! The input after orient_soup (orient_soup.h): the same surface, welded,
    //! without degenerate or duplicate triangles.
    Mesh mesh;
    //! Same transform as the level set: per voxel within the unsigned band
    //! around `mesh`, the index of the triangle of `mesh` nearest to it.
    openvdb::Int32Grid::Ptr closest_triangle;
};

//! `oriented`, when given, receives the oriented input and its closest triangles.
openvdb::FloatGrid::Ptr signed_distance_from_mesh(const Mesh& mesh, const SignedDistanceOptions& options,
                                                  Progress& progress, SignedDistanceStats* stats = nullptr,
                                                  OrientedInput* oriented = nullptr);

}  // namespace fabvdb::volume
