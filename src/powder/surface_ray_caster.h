//! First-hit ray queries on a triangle mesh with Embree 3: which triangle a
//! ray from a point along a direction meets first. Builds the bounding volume
//! hierarchy once; queries are thread-safe and allocation-free. Used for the
//! falls of powder from overhangs and for dropping the cavity's powder.
#pragma once

#include <cstdint>

#include "core/mesh.h"

namespace fabvdb::powder {

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

private:
    void* device_ = nullptr;
    void* scene_ = nullptr;
};

}  // namespace fabvdb::powder
