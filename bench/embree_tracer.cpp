// embree_tracer.cpp — Embree's defaults except the build quality: high, like
// the full binned-SAH build of our own BVH, so traversal is compared with
// traversal and not with a quicker build; and, for the robust reference, the
// robust scene flag on every scene, instanced meshes' too.
#include "embree_tracer.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace wf::bench {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

void check(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree: ") + what + " failed, error " +
                                                          std::to_string(static_cast<int>(error)));
}

// Runs work(begin, end) over [0, count) split into `threads` equal chunks,
// one std::thread each; returns the wall time.
template <class Work> double on_threads(unsigned threads, size_t count, const Work& work) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k)
        pool.emplace_back(work, count * k / threads, count * (k + 1) / threads);
    for (std::thread& t : pool) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A geometry of the scene's triangles [first, first + count), in their own space.
RTCGeometry triangles(RTCDevice device, const Scene& scene, size_t first, size_t count) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), count));
    check(device, "allocating the triangle buffers");
    std::memcpy(vertices, &scene.positions[3 * first], 3 * count * sizeof(glm::vec3)); // three packed floats each
    for (uint32_t i = 0; i < 3 * count; ++i) indices[i] = i;
    rtcCommitGeometry(geometry);
    return geometry;
}

} // namespace

EmbreeScene::EmbreeScene(const Scene& scene, unsigned threads, EmbreeMode mode) : threads_(threads) {
    if (mode == EmbreeMode::Robust) { // the open interval (embree_tracer.h)
        t_near_ = std::numeric_limits<float>::min();
        segment_end_ = std::nextafter(1.0f, 0.0f);
    }
    device_ = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
    if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
    const auto new_scene = [&] {
        RTCScene s = rtcNewScene(device_);
        rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
        if (mode == EmbreeMode::Robust) rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
        return s;
    };
    scene_ = new_scene();
    const auto start = std::chrono::steady_clock::now();
    if (const size_t world = scene.world_triangle_count(); world > 0) {
        RTCGeometry geometry = triangles(device_, scene, 0, world);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        first_.push_back(0u);
        placed_first_.push_back(0u);
    }
    std::vector<RTCScene> meshes;
    for (const SharedMesh& mesh : scene.shared_meshes) {
        meshes.push_back(new_scene());
        RTCGeometry geometry = triangles(device_, scene, mesh.first, mesh.count);
        rtcAttachGeometry(meshes.back(), geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(meshes.back());
    }
    auto placed = uint32_t(scene.world_triangle_count());
    for (const MeshInstance& instance : scene.instances) {
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geometry, meshes[instance.mesh]);
        float columns[12]; // RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR: x, y, z of each of the four columns
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) columns[3 * c + r] = float(instance.object_to_world[c][r]);
        rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, columns);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        first_.push_back(scene.shared_meshes[instance.mesh].first);
        placed_first_.push_back(placed);
        placed += scene.shared_meshes[instance.mesh].count;
    }
    rtcCommitScene(scene_);
    for (RTCScene mesh : meshes) rtcReleaseScene(mesh); // the instances hold them
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    check(device_, "building the scene");
}

void EmbreeScene::name_hit(uint32_t geometry, uint32_t prim, uint32_t* scene_triangle, uint32_t* placed) const {
    *scene_triangle = first_[geometry] + prim;
    *placed = placed_first_[geometry] + prim;
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

EmbreeHits EmbreeScene::intersect1(const std::vector<BatchRay>& rays, float t_far) const {
    EmbreeHits out;
    out.t.resize(rays.size());
    out.prim.resize(rays.size());
    out.placed.resize(rays.size());
    out.seconds = on_threads(threads_, rays.size(), [&](size_t begin, size_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (size_t i = begin; i < end; ++i) {
            const BatchRay& r = rays[i];
            RTCRayHit h{};
            h.ray.org_x = r.origin.x, h.ray.org_y = r.origin.y, h.ray.org_z = r.origin.z;
            h.ray.dir_x = r.direction.x, h.ray.dir_y = r.direction.y, h.ray.dir_z = r.direction.z;
            h.ray.tnear = t_near_;
            h.ray.tfar = t_far;
            h.ray.mask = ~0u;
            h.hit.geomID = h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_, &context, &h);
            const bool hit = h.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            out.t[i] = hit ? h.ray.tfar : kInfinity;
            out.prim[i] = out.placed[i] = RTC_INVALID_GEOMETRY_ID;
            if (hit)
                name_hit(h.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? h.hit.instID[0] : h.hit.geomID, h.hit.primID,
                         &out.prim[i], &out.placed[i]);
        }
    });
    return out;
}

EmbreeHits EmbreeScene::intersect8(const std::vector<BatchRay>& rays) const {
    EmbreeHits out;
    out.t.resize(rays.size());
    out.prim.resize(rays.size());
    out.placed.resize(rays.size());
    const size_t packets = (rays.size() + 7) / 8;
    out.seconds = on_threads(threads_, packets, [&](size_t begin, size_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (size_t p = begin; p < end; ++p) {
            alignas(32) int valid[8];
            alignas(32) RTCRayHit8 h{};
            for (size_t k = 0; k < 8; ++k) {
                const size_t i = 8 * p + k;
                valid[k] = i < rays.size() ? -1 : 0;
                if (!valid[k]) continue;
                const BatchRay& r = rays[i];
                h.ray.org_x[k] = r.origin.x, h.ray.org_y[k] = r.origin.y, h.ray.org_z[k] = r.origin.z;
                h.ray.dir_x[k] = r.direction.x, h.ray.dir_y[k] = r.direction.y, h.ray.dir_z[k] = r.direction.z;
                h.ray.tnear[k] = t_near_;
                h.ray.tfar[k] = kInfinity;
                h.ray.mask[k] = ~0u;
                h.hit.geomID[k] = h.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect8(valid, scene_, &context, &h);
            for (size_t k = 0; k < 8 && 8 * p + k < rays.size(); ++k) {
                const size_t i = 8 * p + k;
                const bool hit = h.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
                out.t[i] = hit ? h.ray.tfar[k] : kInfinity;
                out.prim[i] = out.placed[i] = RTC_INVALID_GEOMETRY_ID;
                if (hit)
                    name_hit(h.hit.instID[0][k] != RTC_INVALID_GEOMETRY_ID ? h.hit.instID[0][k] : h.hit.geomID[k],
                             h.hit.primID[k], &out.prim[i], &out.placed[i]);
            }
        }
    });
    return out;
}

EmbreeOcclusion EmbreeScene::occluded1(const std::vector<BatchRay>& rays) const {
    EmbreeOcclusion out;
    out.occluded.resize(rays.size());
    out.seconds = on_threads(threads_, rays.size(), [&](size_t begin, size_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (size_t i = begin; i < end; ++i) {
            const BatchRay& r = rays[i];
            RTCRay ray{};
            ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
            ray.dir_x = r.direction.x, ray.dir_y = r.direction.y, ray.dir_z = r.direction.z;
            ray.tnear = t_near_;
            ray.tfar = segment_end_;
            ray.mask = ~0u;
            rtcOccluded1(scene_, &context, &ray);
            out.occluded[i] = ray.tfar == -kInfinity; // Embree's mark of a blocked ray
        }
    });
    return out;
}

} // namespace wf::bench
