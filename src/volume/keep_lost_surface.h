//! The input surface that the level sets of a model's parts lost, put back
//! as solid tubes: fins and sheets thinner than a voxel (a closed fin whose
//! two sides lie within a voxel, an open sheet enclosing nothing), sharp tips,
//! and thin features that a split between two parts left too thin on both
//! sides have no voxel inside them, so no part's zero surface holds them.
//! Each input triangle is sampled at half a voxel; a sample is lost where it
//! lies farther than `tolerance` outside every part but within `reach` of one
//! (measured on each part's band rebuilt from its zero surface,
//! rebuild_band.h) and not deeper than `tolerance` inside the input's solid
//! (surface the solid encloses, as an inner shell, no part need hold), and it
//! belongs to the part nearest to it (the first on a tie). Per part, its lost triangles'
//! unsigned distance minus `radius`, within `radius` + 1 voxel of its lost
//! samples, is its tube: united with the part and cut out of the others (a
//! place in two tubes goes to the first part's), so the parts stay disjoint.
//! Every lost sample then lies inside a part, within about `radius` of its
//! surface; elsewhere the surface moves only inside the tubes (≤ `radius`
//! outward). Costs a band rebuild per part and one sample per (half voxel)²
//! of input area and, for the parts that change, the lost triangles'
//! unsigned band and one more rebuild. Cancellable.
#pragma once

#include <cstddef>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct KeepLostSurfaceOptions {
    //! mm (> 0): how far outside every part an input sample counts as lost.
    double tolerance = 0.0;
    //! mm (> 0): the tube's radius around the lost triangles.
    double radius = 0.0;
    //! mm (> tolerance): samples farther than this from every part stay lost
    //! (no part reaches them; the band's half width bounds it too).
    double reach = 0.0;
    //! The input's level set (same voxel), or nullptr: surface deeper inside it
    //! than the tolerance is enclosed, never lost.
    const openvdb::FloatGrid* solid = nullptr;
    //! Half width in voxels (>= 2) of the changed parts' bands.
    int half_band_voxels = 3;
};

struct LostSurface {
    size_t samples = 0;         //!< input surface samples tested
    size_t lost_samples = 0;    //!< farther than the tolerance outside every part
    size_t lost_triangles = 0;  //!< input triangles with a lost sample
};

//! `parts`: disjoint level sets (GRID_LEVEL_SET) of pieces of `input`, on one
//! transform with uniform voxels (at least one). Returns the parts: a part
//! that neither gained nor gave up a tube is returned as given, the others
//! as new level sets on the same transform. Throws Error(INVALID_ARGUMENT)
//! for options out of range or parts on different transforms.
std::vector<openvdb::FloatGrid::Ptr> keep_lost_surface(const std::vector<openvdb::FloatGrid::Ptr>& parts,
                                                       const Mesh& input, const KeepLostSurfaceOptions& options,
                                                       Progress& progress, LostSurface* stats = nullptr);

}  // namespace fabvdb::volume
