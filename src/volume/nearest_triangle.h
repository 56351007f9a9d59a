//! The triangle of a mesh nearest to a point, and the point on it, found
//! from hints: the nearest triangles an index grid records in the 27 voxels
//! around the point (centred on the voxel whose centre is nearest, as a
//! mesh-to-volume conversion leaves them), then, while
//! the best one's nearest point lies on its edge or corner, a descent over the
//! triangles around its corners for as long as it gets nearer. Exact when the
//! true nearest triangle is among the hints or reachable by that descent (the
//! hints of a point's own voxels are the nearest triangles a voxel away, so it
//! is in practice: docs/design/geometry.md); a point with no hint around it
//! has none.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "volume/closest_point_on_triangle.h"
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

class NearestTriangle {
public:
    struct Result {
        openvdb::Vec3d point;
        uint32_t triangle = 0;
        TriangleFeature feature = TriangleFeature::face;  //!< where `point` lies on the triangle
        double distance = std::numeric_limits<double>::infinity();
        bool found() const { return distance < std::numeric_limits<double>::infinity(); }
    };

    //! `mesh` (world units) and `hints` (triangle indices, -1 or inactive:
    //! none) must outlive the search; the hint grid may gain voxels between
    //! queries, not during them.
    NearestTriangle(const Mesh& mesh, const openvdb::Int32Grid& hints);

    //! One per thread (it caches the hint grid's nodes). Without `descend`,
    //! only the hints are compared.
    class Query {
    public:
        explicit Query(const NearestTriangle& search, bool descend = true);
        Result operator()(const openvdb::Vec3d& p);

    private:
        //! Measures the `candidates_` not in `considered_` and adds them to
        //! it; `best.distance` is squared here.
        void consider(const openvdb::Vec3d& p, Result& best);
        const NearestTriangle& search_;
        bool descend_;
        openvdb::tree::ValueAccessor<const openvdb::Int32Tree> hints_;
        std::vector<uint32_t> candidates_, considered_, fresh_;  //!< sorted, but candidates_ as gathered
    };

private:
    const Mesh& mesh_;
    const openvdb::Int32Grid& hints_;
    VertexCorners corners_;
};

}  // namespace fabvdb::volume
