// Embree 3 scene set-up and primary-ray frames, single rays and 4x4 packets (see
// embree_tracer.h).
#include "bench/peers/embree_tracer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <embree3/rtcore.h>
#include <fmt/format.h>

namespace fb89::peers {

namespace {

RTCDevice device_of(void* p) {
    return static_cast<RTCDevice>(p);
}
RTCScene scene_of(void* p) {
    return static_cast<RTCScene>(p);
}

RTCBuildQuality build_quality(EmbreeQuality q) {
    switch (q) {
        case EmbreeQuality::Low:
            return RTC_BUILD_QUALITY_LOW;
        case EmbreeQuality::Medium:
            return RTC_BUILD_QUALITY_MEDIUM;
        case EmbreeQuality::High:
            break;
    }
    return RTC_BUILD_QUALITY_HIGH;
}

// A pixel's ray, each component rounded to float.
struct FloatRay {
    float ox, oy, oz, dx, dy, dz;
};

FloatRay float_ray(const host::Ray& r) {
    return {static_cast<float>(r.origin.x), static_cast<float>(r.origin.y),
            static_cast<float>(r.origin.z), static_cast<float>(r.dir.x),
            static_cast<float>(r.dir.y),    static_cast<float>(r.dir.z)};
}

}  // namespace

EmbreeQuality parse_embree_quality(const std::string& name) {
    if (name == "low") return EmbreeQuality::Low;
    if (name == "medium") return EmbreeQuality::Medium;
    if (name == "high") return EmbreeQuality::High;
    throw std::invalid_argument("Embree build quality must be low, medium or high, not '" + name +
                                "'");
}

std::string to_string(EmbreeQuality quality) {
    switch (quality) {
        case EmbreeQuality::Low:
            return "low";
        case EmbreeQuality::Medium:
            return "medium";
        case EmbreeQuality::High:
            break;
    }
    return "high";
}

EmbreeTracer::EmbreeTracer(const host::Scene& scene, EmbreeOptions options)
    : m_options(options), m_rays(scene, true, 0) {
    m_device = rtcNewDevice("threads=1");
    if (!m_device) throw std::runtime_error("Embree: rtcNewDevice failed");

    // fan-triangulate every piece, vertices rounded to float
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    for (const host::Face& face : scene.faces) {
        const auto base = static_cast<uint32_t>(vertices.size() / 3);
        for (const glm::dvec3& v : face.vertices) {
            vertices.push_back(static_cast<float>(v.x));
            vertices.push_back(static_cast<float>(v.y));
            vertices.push_back(static_cast<float>(v.z));
        }
        for (uint32_t i = 1; i + 1 < face.vertices.size(); ++i) {
            indices.insert(indices.end(), {base, base + i, base + i + 1});
            m_face_of_triangle.push_back(face.id);
        }
    }

    RTCScene rtc_scene = rtcNewScene(device_of(m_device));
    m_scene = rtc_scene;
    int flags = RTC_SCENE_FLAG_NONE;
    if (options.robust) flags |= RTC_SCENE_FLAG_ROBUST;
    if (options.compact) flags |= RTC_SCENE_FLAG_COMPACT;
    rtcSetSceneFlags(rtc_scene, static_cast<RTCSceneFlags>(flags));
    rtcSetSceneBuildQuality(rtc_scene, build_quality(options.quality));

    if (!m_face_of_triangle.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device_of(m_device), RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geometry, build_quality(options.quality));
        // Embree over-allocates a new vertex buffer for its 16-byte loads itself
        auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               vertices.size() / 3));
        auto* ib = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(uint32_t), m_face_of_triangle.size()));
        check("allocating buffers");
        std::copy(vertices.begin(), vertices.end(), vb);
        std::copy(indices.begin(), indices.end(), ib);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(rtc_scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(rtc_scene);
    check("building the scene");
}

EmbreeTracer::~EmbreeTracer() {
    if (m_scene) rtcReleaseScene(scene_of(m_scene));
    if (m_device) rtcReleaseDevice(device_of(m_device));
}

void EmbreeTracer::check(const char* what) const {
    const RTCError error = rtcGetDeviceError(device_of(m_device));
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(fmt::format("Embree: error {} {}", static_cast<int>(error), what));
}

std::string EmbreeTracer::description() const {
    return fmt::format("Embree {} (device \"threads=1\"), build quality {}{}{}", RTC_VERSION_STRING,
                       to_string(m_options.quality), m_options.robust ? ", robust" : "",
                       m_options.compact ? ", compact" : "");
}

void EmbreeTracer::trace_single(std::vector<uint32_t>& ids) const {
    const int w = m_rays.width(), h = m_rays.height();
    ids.resize(static_cast<size_t>(w) * h);
    RTCScene rtc_scene = scene_of(m_scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    uint32_t* out = ids.data();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // the pixel's ray
            const FloatRay r = float_ray(m_rays.pixel_ray(x, y));
            RTCRayHit rh;
            rh.ray.org_x = r.ox, rh.ray.org_y = r.oy, rh.ray.org_z = r.oz;
            rh.ray.dir_x = r.dx, rh.ray.dir_y = r.dy, rh.ray.dir_z = r.dz;
            rh.ray.tnear = 0;
            rh.ray.tfar = INFINITY;
            rh.ray.time = 0;
            rh.ray.mask = ~0u;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            // nearest hit
            rtcIntersect1(rtc_scene, &context, &rh);
            *out++ = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID
                         ? 0
                         : m_face_of_triangle[rh.hit.primID] + 1;
        }
    }
}

void EmbreeTracer::trace_packets(std::vector<uint32_t>& ids) const {
    const int w = m_rays.width(), h = m_rays.height();
    ids.resize(static_cast<size_t>(w) * h);
    RTCScene rtc_scene = scene_of(m_scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    RTCRayHit16 packet;
    int valid[16];
    for (int ty = 0; ty < h; ty += 4) {
        for (int tx = 0; tx < w; tx += 4) {
            // the tile's rays, lane i at (tx + i % 4, ty + i / 4); lanes off the image masked
            for (int i = 0; i < 16; ++i) {
                const int x = tx + (i & 3), y = ty + (i >> 2);
                valid[i] = x < w && y < h ? -1 : 0;
                const FloatRay r = valid[i] ? float_ray(m_rays.pixel_ray(x, y)) : FloatRay{};
                packet.ray.org_x[i] = r.ox, packet.ray.org_y[i] = r.oy, packet.ray.org_z[i] = r.oz;
                packet.ray.dir_x[i] = r.dx, packet.ray.dir_y[i] = r.dy, packet.ray.dir_z[i] = r.dz;
                packet.ray.tnear[i] = 0;
                packet.ray.tfar[i] = INFINITY;
                packet.ray.time[i] = 0;
                packet.ray.mask[i] = ~0u;
                packet.ray.id[i] = 0;
                packet.ray.flags[i] = 0;
                packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
            }
            // nearest hits
            rtcIntersect16(valid, rtc_scene, &context, &packet);
            for (int i = 0; i < 16; ++i) {
                if (!valid[i]) continue;
                const size_t p = static_cast<size_t>(ty + (i >> 2)) * w + tx + (i & 3);
                ids[p] = packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID
                             ? 0
                             : m_face_of_triangle[packet.hit.primID[i]] + 1;
            }
        }
    }
}

}  // namespace fb89::peers
