//! Embree 3 first-hit queries (see surface_ray_caster.h).
#include "powder/surface_ray_caster.h"

#include <limits>

#include <embree3/rtcore.h>

#include "core/error.h"

namespace fabvdb::powder {

SurfaceRayCaster::SurfaceRayCaster(const Mesh& mesh) {
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the cavity surface has no triangles");
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw Error(FABVDB_ERR_INTERNAL, "Embree could not create a device");
    device_ = device;
    RTCScene scene = rtcNewScene(device);
    scene_ = scene;
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
        throw Error(FABVDB_ERR_OUT_OF_MEMORY, "Embree could not allocate the cavity surface");
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
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray.org_x = float(origin[0]);
    query.ray.org_y = float(origin[1]);
    query.ray.org_z = float(origin[2]);
    query.ray.dir_x = float(direction[0]);
    query.ray.dir_y = float(direction[1]);
    query.ray.dir_z = float(direction[2]);
    query.ray.tnear = 0.0f;
    query.ray.tfar = max_distance < double(std::numeric_limits<float>::max()) ? float(max_distance)
                                                                             : std::numeric_limits<float>::infinity();
    query.ray.mask = ~0u;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    if (distance) *distance = query.ray.tfar;
    return int64_t(query.hit.primID);
}

}  // namespace fabvdb::powder
