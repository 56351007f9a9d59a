//! Ray queries on a triangle mesh with Embree 3 (robust traversal, so a ray
//! through an edge or a vertex is not lost between triangles): which
//! triangle a ray from a point along a direction meets first, and every
//! triangle a segment crosses. Builds the bounding volume hierarchy once
//! (float corners); queries are thread-safe; a first hit allocates nothing.
//! Used for the falls of powder from overhangs, for dropping the cavity's
//! powder, and for reading cast parts' surfaces off the input along their
//! parting directions.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! A crossing of a segment with a triangle: the segment's parameter t and the triangle.
struct RayHit {
    double t;
    uint32_t triangle;
};

class SurfaceRayCaster {
public:
    //! Keeps no reference to `mesh`. Throws Error(BAD_INPUT) for a mesh
    //! without triangles, Error(INTERNAL) if Embree cannot start and
    //! Error(OUT_OF_MEMORY) if it cannot hold the mesh.
    explicit SurfaceRayCaster(const Mesh& mesh);
    ~SurfaceRayCaster();
    SurfaceRayCaster(const SurfaceRayCaster&) = delete;
    SurfaceRayCaster& operator=(const SurfaceRayCaster&) = delete;

    //! Index of the first triangle hit by origin + t·direction, 0 < t < max_distance,
    //! or -1 when none is; `distance` (if not null) receives t.
    int64_t first_hit(const Vec3& origin, const Vec3& direction, double max_distance,
                      double* distance = nullptr) const;

    //! Every crossing of origin + t·direction with a triangle, t_min < t < t_max,
    //! ordered by t (a crossing through a shared edge or vertex is reported
    //! once per triangle that holds it).
    std::vector<RayHit> all_hits(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;

private:
    void* device_ = nullptr;
    void* scene_ = nullptr;
};

}  // namespace fabvdb::volume
