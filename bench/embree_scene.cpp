#include "embree_scene.h"

#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

namespace rt_bench {

namespace {

constexpr unsigned sphere_geometry = 0, quad_geometry = 1;

// Embree calls this from C code, so it only reports; the constructor checks the error code.
void report_error(void* /*user*/, RTCError code, const char* message) {
    std::cerr << "Embree error " << int(code) << ": " << message << '\n';
}

float f(rt::real x) {
    return static_cast<float>(x);
}

}  // namespace

embree_scene::embree_scene(const anchor_geometry& g)
    : sphere_count(std::uint32_t(g.spheres.size())) {
    // One thread: the anchor compares single-thread traversal, and the build has no need for
    // the other core (which other work on this machine may be using).
    device = rtcNewDevice("threads=1");
    if (!device) throw std::runtime_error("Embree: no device");
    rtcSetDeviceErrorFunction(device, report_error, nullptr);
    scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);

    if (!g.spheres.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* points         = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                            4 * sizeof(float), g.spheres.size()));
        for (const auto& s : g.spheres) {
            *points++ = f(s.center.x());
            *points++ = f(s.center.y());
            *points++ = f(s.center.z());
            *points++ = f(s.radius);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(scene, geometry, sphere_geometry);
        rtcReleaseGeometry(geometry);
    }
    if (!g.quads.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
        auto* corners        = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                           3 * sizeof(float), 4 * g.quads.size()));
        auto* index = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                    4 * sizeof(unsigned), g.quads.size()));
        unsigned next = 0;
        for (const auto& q : g.quads) {
            for (const rt::point3& p :
                 {q.corner, q.corner + q.u, q.corner + q.u + q.v, q.corner + q.v}) {
                *corners++ = f(p.x());
                *corners++ = f(p.y());
                *corners++ = f(p.z());
                *index++   = next++;
            }
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(scene, geometry, quad_geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the scene (message above)");
}

embree_scene::~embree_scene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
}

void embree_scene::trace(const std::vector<RTCRay>& rays, std::vector<std::int32_t>& shape,
                         std::vector<float>& t) const {
    shape.resize(rays.size());
    t.resize(rays.size());
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        RTCRayHit query;
        query.ray           = rays[i];
        query.hit.geomID    = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &query);
        const unsigned geometry = query.hit.geomID;
        shape[i]                = geometry == RTC_INVALID_GEOMETRY_ID ? -1
                                  : geometry == sphere_geometry ? std::int32_t(query.hit.primID)
                                                                : std::int32_t(sphere_count + query.hit.primID);
        t[i]                    = query.ray.tfar;
    }
}

RTCRay embree_ray(const rt::ray& r, float t_min) {
    RTCRay out;
    out.org_x = f(r.origin().x());
    out.org_y = f(r.origin().y());
    out.org_z = f(r.origin().z());
    out.tnear = t_min;
    out.dir_x = f(r.direction().x());
    out.dir_y = f(r.direction().y());
    out.dir_z = f(r.direction().z());
    out.time  = 0;
    out.tfar  = std::numeric_limits<float>::infinity();
    out.mask  = ~0u;
    out.id    = 0;
    out.flags = 0;
    return out;
}

}  // namespace rt_bench
