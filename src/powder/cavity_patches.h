//! Clustering of a cavity surface into patches, the elements of the
//! drainability model. Takes the cavity's boundary mesh (outward-oriented for
//! the cavity region, as extracted from the cavity level set) and a target
//! patch count; bins the triangles on a grid whose cells hold about one
//! patch's area and splits each bin into its edge-connected pieces, so every
//! patch is connected and lies on one cavity. Guarantees: every triangle has
//! a patch; normals point into the cavity (up on a floor); `site` lies on the
//! surface; neighbours are symmetric with the length of their shared border.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::powder {

struct PatchNeighbour {
    uint32_t patch;
    double shared_length;
};

struct CavityPatches {
    std::vector<uint32_t> patch_of_triangle;
    //! Area-weighted centroid (may lie a little off a curved surface).
    std::vector<Vec3> centroid;
    //! Centroid of the patch triangle nearest `centroid`: on the surface.
    std::vector<Vec3> site;
    //! Unit area-weighted normal, pointing into the cavity.
    std::vector<Vec3> normal;
    std::vector<double> area;
    //! Which cavity (connected component of the cavity surface) holds the patch.
    std::vector<uint32_t> cavity;
    uint32_t cavity_count = 0;
    std::vector<std::vector<PatchNeighbour>> neighbours;

    size_t size() const { return area.size(); }
};

CavityPatches cluster_cavity_patches(const Mesh& cavity_surface, size_t target_count);

}  // namespace fabvdb::powder
