// embree_peer: the model of docs/model.md on the CPU with Intel Embree 3 as the intersector, the
// peer a user with a CPU would pick for scenes of many triangles. tools/bench runs it beside
// Raytracer and brute_force_peer.
//
// Geometry: one RTC_GEOMETRY_TYPE_TRIANGLE mesh over a shared vertex buffer, and the
// spheres as RTC_GEOMETRY_TYPE_SPHERE_POINT, which Embree intersects as exact spheres
// (a ray/sphere quadratic, not a tessellation). The scene is built with
// RTC_SCENE_FLAG_ROBUST: watertight triangle tests and conservative traversal, as the
// model asks of shared edges (it costs 10-20% here). Primary rays go through rtcIntersect8 in
// packets of 8 neighbouring pixels (10-25% faster on toy and table than one at a
// time; measured), the incoherent shadow and reflection rays one at a time through
// rtcIntersect1 / rtcOccluded1. 2 std::threads, each with its own RTCIntersectContext;
// Embree's own thread pool (TBB) builds the BVH and is held to the same thread count.
#include "peer_driver.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

namespace {

// The device and the committed scene; released in reverse order.
struct EmbreeState {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    unsigned sphereGeometry = RTC_INVALID_GEOMETRY_ID;
    unsigned triangleGeometry = RTC_INVALID_GEOMETRY_ID;
    std::atomic<std::int64_t> bytes{0}; // what Embree holds now, from its memory monitor

    EmbreeState() = default;
    EmbreeState(const EmbreeState&) = delete;
    EmbreeState& operator=(const EmbreeState&) = delete;
    ~EmbreeState() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

// Embree 3 has no error-string function (Embree 4 added one).
const char* errorName(RTCError error) {
    switch (error) {
    case RTC_ERROR_NONE:
        return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
        return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
        return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
        return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
        return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
        return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
        return "RTC_ERROR_CANCELLED";
    }
    return "an unknown RTCError";
}

// Throws, naming the step and Embree's error, if the device has recorded one.
void checkDevice(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree: ") + what + " failed: " + errorName(error));
}

bool countBytes(void* user, ssize_t bytes, bool /*post*/) {
    static_cast<EmbreeState*>(user)->bytes += bytes;
    return true; // never refuse an allocation
}

// One thread's view of the scene: its own intersect contexts, one flagged for coherent
// rays (a row's primary rays) and one for the rest.
struct EmbreeWorker {
    const EmbreeState* state;
    RTCIntersectContext context;
    RTCIntersectContext coherent;

    explicit EmbreeWorker(const EmbreeState* s) : state(s) {
        rtcInitIntersectContext(&context);
        rtcInitIntersectContext(&coherent);
        coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    }

    static RTCRay toRtc(const PeerRay& ray, float tMax) {
        RTCRay r;
        r.org_x = ray.origin.x;
        r.org_y = ray.origin.y;
        r.org_z = ray.origin.z;
        r.tnear = 0.0f; // the origin is already off the surface (ray_offset.h)
        r.dir_x = ray.direction.x;
        r.dir_y = ray.direction.y;
        r.dir_z = ray.direction.z;
        r.time = 0.0f;
        r.tfar = tMax;
        r.mask = ~0u;
        r.id = 0;
        r.flags = 0;
        return r;
    }

    PeerHit toHit(unsigned geomID, unsigned primID, float t, float u, float v) const {
        if (geomID == RTC_INVALID_GEOMETRY_ID) return {};
        if (geomID == state->sphereGeometry) return {t, HitKind::sphere, primID, 0.0f, 0.0f};
        // Embree's u, v weigh corners 1 and 2, as PeerHit's do.
        return {t, HitKind::triangle, primID, u, v};
    }

    PeerHit closestHit(const PeerRay& ray) {
        RTCRayHit rayHit;
        rayHit.ray = toRtc(ray, std::numeric_limits<float>::infinity());
        rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(state->scene, &context, &rayHit);
        const RTCHit& h = rayHit.hit;
        return toHit(h.geomID, h.primID, rayHit.ray.tfar, h.u, h.v);
    }

    // Primary rays of a row, 8 at a time; a short last packet masks its missing lanes.
    void closestHits(std::span<const PeerRay> rays, std::span<PeerHit> hits) {
        for (std::size_t base = 0; base < rays.size(); base += 8) {
            const std::size_t lanes = std::min<std::size_t>(8, rays.size() - base);
            alignas(32) int valid[8];
            alignas(32) RTCRayHit8 packet;
            for (std::size_t l = 0; l < 8; ++l) {
                valid[l] = l < lanes ? -1 : 0;
                const PeerRay& r = rays[base + std::min(l, lanes - 1)];
                packet.ray.org_x[l] = r.origin.x;
                packet.ray.org_y[l] = r.origin.y;
                packet.ray.org_z[l] = r.origin.z;
                packet.ray.tnear[l] = 0.0f;
                packet.ray.dir_x[l] = r.direction.x;
                packet.ray.dir_y[l] = r.direction.y;
                packet.ray.dir_z[l] = r.direction.z;
                packet.ray.time[l] = 0.0f;
                packet.ray.tfar[l] = std::numeric_limits<float>::infinity();
                packet.ray.mask[l] = ~0u;
                packet.ray.id[l] = 0;
                packet.ray.flags[l] = 0;
                packet.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect8(valid, state->scene, &coherent, &packet);
            for (std::size_t l = 0; l < lanes; ++l)
                hits[base + l] = toHit(packet.hit.geomID[l], packet.hit.primID[l],
                                       packet.ray.tfar[l], packet.hit.u[l], packet.hit.v[l]);
        }
    }

    bool occluded(const PeerRay& ray, float tMax) {
        RTCRay r = toRtc(ray, tMax);
        rtcOccluded1(state->scene, &context, &r);
        return r.tfar < 0.0f; // Embree sets tfar to -inf on a hit
    }
};

struct EmbreeIntersector {
    const EmbreeState* state;
    EmbreeWorker worker() const { return EmbreeWorker(state); }
};

void addSpheres(EmbreeState& s, const PeerScene& scene) {
    if (scene.spheres.empty()) return;
    RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* points = static_cast<glm::vec4*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                sizeof(glm::vec4), scene.spheres.size()));
    checkDevice(s.device, "allocating the sphere buffer");
    std::copy(scene.spheres.begin(), scene.spheres.end(), points); // centre xyz, radius w
    rtcCommitGeometry(geometry);
    s.sphereGeometry = rtcAttachGeometry(s.scene, geometry);
    rtcReleaseGeometry(geometry);
}

void addTriangles(EmbreeState& s, const PeerScene& scene) {
    if (scene.triangles.empty()) return;
    RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads 16 bytes at the last vertex; rtcSetNewGeometryBuffer pads for that.
    auto* vertices = static_cast<glm::vec3*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(glm::vec3), scene.positions.size()));
    auto* indices = static_cast<glm::uvec3*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                sizeof(glm::uvec3), scene.triangles.size()));
    checkDevice(s.device, "allocating the triangle buffers");
    std::copy(scene.positions.begin(), scene.positions.end(), vertices);
    std::copy(scene.triangles.begin(), scene.triangles.end(), indices);
    rtcCommitGeometry(geometry);
    s.triangleGeometry = rtcAttachGeometry(s.scene, geometry);
    rtcReleaseGeometry(geometry);
}

PeerRenderer makeEmbree(const PeerScene& scene, const PeerOptions& options) {
    auto state = std::make_shared<EmbreeState>();
    // threads=N holds Embree's build pool to the thread count the renderer uses.
    const std::string config = "threads=" + std::to_string(options.threads);
    state->device = rtcNewDevice(config.c_str());
    if (!state->device) throw std::runtime_error("Embree: rtcNewDevice failed");
    rtcSetDeviceMemoryMonitorFunction(state->device, countBytes, state.get());
    state->scene = rtcNewScene(state->device);
    rtcSetSceneFlags(state->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(state->scene, RTC_BUILD_QUALITY_MEDIUM);
    addSpheres(*state, scene);
    addTriangles(*state, scene);
    rtcCommitScene(state->scene); // builds the BVH
    checkDevice(state->device, "building the scene");

    PeerRenderer peer;
    peer.device = "embree " + std::to_string(RTC_VERSION_MAJOR) + "." +
                  std::to_string(RTC_VERSION_MINOR) + "." + std::to_string(RTC_VERSION_PATCH) +
                  ", " + threadCount(options.threads);
    peer.memoryBytes = peerSceneBytes(scene) + std::size_t(std::max<std::int64_t>(state->bytes, 0));
    peer.renderFrame = [state, &scene, options](Image8& image) {
        return renderImage(scene, EmbreeIntersector{state.get()}, options.render, options.threads,
                           image);
    };
    return peer;
}

} // namespace

int main(int argc, char** argv) {
    return runPeer(argc, argv, "embree_peer", makeEmbree);
}
