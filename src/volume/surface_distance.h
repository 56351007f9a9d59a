//! Distances from points to the surface of a triangle mesh: a CGAL AABB tree
//! over its triangles, built once and queried many times, from any number
//! of threads at once. Used to tell whether a decomposition belongs to an
//! input, how closely cast parts reproduce it, and whether an output still
//! is its input's model (input_fidelity.h).
#pragma once

#include <cstddef>
#include <memory>

#include "core/mesh.h"

namespace fabvdb::volume {

class SurfaceDistance {
public:
    //! Throws Error(BAD_INPUT) for a mesh without triangles.
    explicit SurfaceDistance(const Mesh& mesh);
    ~SurfaceDistance();
    SurfaceDistance(const SurfaceDistance&) = delete;
    SurfaceDistance& operator=(const SurfaceDistance&) = delete;

    struct Nearest {
        double distance = 0;
        size_t triangle = 0;  //!< index into the mesh's triangles
    };
    Nearest nearest(const Vec3& point) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace fabvdb::volume
