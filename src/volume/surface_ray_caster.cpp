//! Embree 3 ray queries (see surface_ray_caster.h).
#include "volume/surface_ray_caster.h"

#include <algorithm>
#include <limits>

#include <embree3/rtcore.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

//! Robust traversal also reports hits at t = tnear; only t > tnear count
//! (a ray leaving a surface does not hit it).
struct StrictContext {
    RTCIntersectContext base;
    float t_min;
    std::vector<RayHit>* hits;  //!< nullptr: keep the first hit; else gather every hit and go on
};

void filter_hit(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const StrictContext*>(args->context);
    const float t = RTCRayN_tfar(args->ray, args->N, 0);
    if (t <= context->t_min) {
        args->valid[0] = 0;
        return;
    }
    if (!context->hits) return;
    context->hits->push_back({double(t), RTCHitN_primID(args->hit, args->N, 0)});
    args->valid[0] = 0;
}

RTCRay make_ray(const Vec3& origin, const Vec3& direction, double t_min, double t_max) {
    RTCRay ray{};
    ray.org_x = float(origin[0]);
    ray.org_y = float(origin[1]);
    ray.org_z = float(origin[2]);
    ray.dir_x = float(direction[0]);
    ray.dir_y = float(direction[1]);
    ray.dir_z = float(direction[2]);
    ray.tnear = float(t_min);
    ray.tfar = t_max < double(std::numeric_limits<float>::max()) ? float(t_max)
                                                               : std::numeric_limits<float>::infinity();
    ray.mask = ~0u;
    return ray;
}

}  // namespace


SurfaceRayCaster::SurfaceRayCaster(const Mesh& mesh) {
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the cavity surface has no triangles");
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw Error(FABVDB_ERR_INTERNAL, "Embree could not create a device");
    device_ = device;
    RTCScene scene = rtcNewScene(device);
    scene_ = scene;
    rtcSetSceneFlags(scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                 mesh.vertices.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                   mesh.triangles.size()));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
        throw Error(FABVDB_ERR_OUT_OF_MEMORY, "Embree could not allocate the surface to cast rays at");
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = float(mesh.vertices[i][k]);
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
}

SurfaceRayCaster::~SurfaceRayCaster() {
    rtcReleaseScene(static_cast<RTCScene>(scene_));
    rtcReleaseDevice(static_cast<RTCDevice>(device_));
}

int64_t SurfaceRayCaster::first_hit(const Vec3& origin, const Vec3& direction, double max_distance,
                                    double* distance) const {
    StrictContext context;
    rtcInitIntersectContext(&context.base);
    context.base.filter = filter_hit;
    context.t_min = 0.0f;
    context.hits = nullptr;
    RTCRayHit query{};
    query.ray = make_ray(origin, direction, 0.0, max_distance);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &context.base, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    if (distance) *distance = query.ray.tfar;
    return int64_t(query.hit.primID);
}

std::vector<RayHit> SurfaceRayCaster::all_hits(const Vec3& origin, const Vec3& direction, double t_min,
                                               double t_max) const {
    std::vector<RayHit> hits;
    // Embree takes tnear >= 0: the segment starts at the origin moved to t_min.
    StrictContext context;
    rtcInitIntersectContext(&context.base);
    context.base.filter = filter_hit;
    context.t_min = 0.0f;
    context.hits = &hits;
    const Vec3 start{origin[0] + t_min * direction[0], origin[1] + t_min * direction[1],
                     origin[2] + t_min * direction[2]};
    RTCRayHit query{};
    query.ray = make_ray(start, direction, 0.0, t_max - t_min);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &context.base, &query);
    for (RayHit& hit : hits) hit.t += t_min;
    std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) {
        return a.t < b.t || (a.t == b.t && a.triangle < b.triangle);
    });
    return hits;
}

}  // namespace fabvdb::volume
