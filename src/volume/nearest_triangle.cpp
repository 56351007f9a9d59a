//! Nearest triangle from grid hints and descent (see nearest_triangle.h).
#include "volume/nearest_triangle.h"

#include <algorithm>
#include <cmath>
#include <iterator>


namespace fabvdb::volume {

namespace {

openvdb::Vec3d vec(const Vec3& p) { return openvdb::Vec3d(p[0], p[1], p[2]); }

}  // namespace

NearestTriangle::NearestTriangle(const Mesh& mesh, const openvdb::Int32Grid& hints)
    : mesh_(mesh), hints_(hints), corners_(mesh) {}

NearestTriangle::Query::Query(const NearestTriangle& search, bool descend)
    : search_(search), descend_(descend), hints_(search.hints_.tree()) {}

NearestTriangle::Result NearestTriangle::Query::operator()(const openvdb::Vec3d& p) {
    candidates_.clear();
    considered_.clear();
    const openvdb::Coord center = search_.hints_.transform().worldToIndexCellCentered(p);
    // Neighbouring voxels mostly share their hint: keep each once.
    const auto add = [&](openvdb::Int32 triangle) {
        if (triangle >= 0 && size_t(triangle) < search_.mesh_.triangles.size() &&
            std::find(candidates_.begin(), candidates_.end(), uint32_t(triangle)) == candidates_.end())
            candidates_.push_back(uint32_t(triangle));
    };
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                openvdb::Int32 triangle;
                if (hints_.probeValue(center.offsetBy(dx, dy, dz), triangle)) add(triangle);
            }
    // best.distance holds the squared distance until the end.
    Result best;
    consider(p, best);
    // Descend over the triangles around the best one's corners while its
    // nearest point lies on an edge or a corner: a triangle beyond that
    // boundary may be nearer.
    for (int step = 0; descend_ && step < 8 && best.found() && best.feature != TriangleFeature::face; ++step) {
        const uint32_t before = best.triangle;
        candidates_.clear();
        for (uint32_t v : search_.mesh_.triangles[before])
            for (uint32_t k = search_.corners_.first[v]; k < search_.corners_.first[v + 1]; ++k)
                candidates_.push_back(search_.corners_.corner[k] / 3);
        consider(p, best);
        if (best.triangle == before) break;
    }
    if (best.found()) best.distance = std::sqrt(best.distance);
    return best;
}

void NearestTriangle::Query::consider(const openvdb::Vec3d& p, Result& best) {
    std::sort(candidates_.begin(), candidates_.end());
    candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
    // Only the triangles not measured yet (the descent meets the hints again).
    fresh_.clear();
    std::set_difference(candidates_.begin(), candidates_.end(), considered_.begin(), considered_.end(),
                        std::back_inserter(fresh_));
    const Mesh& mesh = search_.mesh_;
    for (uint32_t t : fresh_) {
        const Triangle& tri = mesh.triangles[t];
        const TrianglePoint nearest =
            closest_point_on_triangle(p, vec(mesh.vertices[tri[0]]), vec(mesh.vertices[tri[1]]), vec(mesh.vertices[tri[2]]));
        const double squared = (p - nearest.point).lengthSqr();
        if (squared < best.distance) {
            best.distance = squared;
            best.point = nearest.point;
            best.feature = nearest.feature;
            best.triangle = t;
        }
    }
    candidates_.clear();
    std::merge(considered_.begin(), considered_.end(), fresh_.begin(), fresh_.end(), std::back_inserter(candidates_));
    considered_.swap(candidates_);
}

}  // namespace fabvdb::volume
