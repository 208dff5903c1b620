// ray_throughput.cpp — `wavefront_ray_bench`: how many rays per second the
// renderer's traversal kernels trace on the OpenCL device, against Embree on
// the CPU, over the very same rays in the same run (the throughput study's
// measurement: ours against Embree's single-ray API, same rays, same threads).
//
//   wavefront_ray_bench SCENE.gltf|.glb [--rays N] [--threads T] [--device D] [--kernels K] [--trace-width W]
//                       [--json OUT.json]
//
// --device, --kernels and --trace-width take what `wavefront render` does
// (default cpu, auto and auto: ours and Embree on the same cores).
// Three sets of about N rays each: the camera rays of one sample per pixel
// (coherent), diffuse bounces from points spread over the surfaces by area
// (incoherent), and shadow segments between two such points (any hit). Our
// times are the kernels' own, from profiling events; Embree's the wall time of
// T threads. Embree runs twice: as it is by default, the targets' reference,
// and in its robust mode (embree_tracer.h), whose test, like ours, is meant to
// leave no crack between triangles that share an edge, so that what robustness
// costs is seen apart from what the code costs. Each time is the best of three
// runs after one warm-up, which for the kernels is where PoCL compiles them
// for the launch. PoCL is held to T threads too (POCL_MAX_PTHREAD_COUNT), each
// pinned to a core (POCL_AFFINITY), unless the environment already says:
// unpinned, the scheduler moved them between launches this short (tens of
// milliseconds), and the same kernels read from 16 to 20 M rays/s from run to
// run where Embree's threads held steady (bench/results/ray-throughput.md).
// Beside the times, the node visits and block tests a ray of each set, counted
// by a CPU's traversal on the host (traversal_work.h) over up to 200 000 of
// the set's rays.
//
// Exit codes as for `wavefront`: 0, 1 (the machine failed, or the tracers
// disagree on more than 0.1% of some set's rays, not counting the shadow
// segments Embree finds blocked at or past their end), 2 (the input is at fault).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bvh/bvh_builder.h"
#include "scene/camera.h"
#include "scene/mesh_placement.h"
#include "device/device_scene.h"
#include "embree_tracer.h"
#include "base/errors.h"
#include "session/exit_status.h"
#include "gltf/gltf_loader.h"
#include "hit_agreement.h"
#include "device/layout_check.h"
#include "device/opencl_device.h"
#include "integrator/ray_batch.h"
#include "render/device_renderer.h"
#include "render/renderer.h"
#include "device/scene_features.h"
#include "surface_rays.h"
#include "traversal_work.h"
#include "tree_cost.h"

namespace wf::bench {
namespace {

constexpr double kMaxMismatch = 1e-3;
// The most rays of a set whose traversal work is counted: its mean is steady
// to three figures long before, and a GPU's run of millions of rays stays quick.
constexpr size_t kWorkRays = 200000;

struct Options {
    std::string scene;
    uint32_t rays = 1u << 20;
    unsigned threads = 2;
    std::string device = "cpu";
    KernelKind kernels = KernelKind::Auto;
    uint32_t trace_width = 0;
    Instancing instancing = Instancing::Off; // every placement written out unless asked
    std::string json;
};

uint32_t positive(const std::string& flag, const std::string& value) {
    std::istringstream in(value);
    unsigned long n = 0;
    if (!(in >> n) || !in.eof() || n == 0 || n > 1u << 28)
        throw InputError(flag + " " + value + ": expected a whole number from 1 to 2^28");
    return static_cast<uint32_t>(n);
}

Options parse(int argc, const char** argv) {
    const std::string usage = "usage: wavefront_ray_bench SCENE.gltf|.glb [--rays N] [--threads T] [--device D] "
                              "[--kernels K] [--trace-width W] [--instancing off|large|all] [--json OUT.json]";
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--rays" && has_value) o.rays = positive(a, argv[++i]);
        else if (a == "--threads" && has_value) o.threads = positive(a, argv[++i]);
        else if (a == "--device" && has_value) o.device = argv[++i];
        else if (a == "--kernels" && has_value) {
            const std::optional<uint32_t> kind = choice_value(kKernelKindNames, argv[++i]);
            if (!kind) throw InputError(std::string("--kernels ") + argv[i] + ": expected cpu, gpu or auto");
            o.kernels = static_cast<KernelKind>(*kind);
        }
        else if (a == "--trace-width" && has_value) {
            o.trace_width = positive(a, argv[++i]);
            if (o.trace_width > 2) throw InputError(std::string("--trace-width ") + argv[i] + ": expected 1 or 2");
        }
        else if (a == "--instancing" && has_value) {
            const std::optional<uint32_t> mode = choice_value(kInstancingNames, argv[++i]);
            if (!mode) throw InputError(std::string("--instancing ") + argv[i] + ": expected off, large or all");
            o.instancing = static_cast<Instancing>(*mode);
        }
        else if (a == "--json" && has_value) o.json = argv[++i];
        else if (a.rfind("--", 0) != 0 && o.scene.empty()) o.scene = a;
        else throw InputError("unexpected argument '" + a + "'; " + usage);
    }
    if (o.scene.empty()) throw InputError(usage);
    return o;
}

// One warm-up run, then the best of three by `seconds`.
template <class Run, class Result> Result best_of_three(const Run& run, double Result::*seconds) {
    run();
    Result best = run();
    for (int k = 0; k < 2; ++k) {
        Result r = run();
        if (r.*seconds < best.*seconds) best = std::move(r);
    }
    return best;
}

struct Row {
    std::string set;
    size_t rays = 0;
    double ours_seconds = 0.0, embree_seconds = 0.0;
    double robust_seconds = 0.0;          // Embree's robust scene, one ray per call
    std::optional<double> packet_seconds; // rtcIntersect8, for the camera rays
    Agreement agreement, packet_agreement, robust_agreement;
    TraversalWork work; // one ray at a time, as bounce and shadow rays go (camera rays go in packets)
};

double mrays(size_t rays, double seconds) { return rays / seconds * 1e-6; }

// At most kWorkRays of a set, spread evenly over it: camera rays come in
// pixel order, whose first rows would speak for the top of the image alone.
std::vector<BatchRay> work_rays(const std::vector<BatchRay>& rays) {
    const size_t stride = (rays.size() + kWorkRays - 1) / kWorkRays;
    if (stride <= 1) return rays;
    std::vector<BatchRay> some;
    for (size_t i = 0; i < rays.size(); i += stride) some.push_back(rays[i]);
    return some;
}

// The camera image with about `rays` pixels, in the camera's aspect.
ImageSize image_of_about(uint32_t rays, const std::optional<SceneCamera>& camera) {
    const ImageSize typical = resolve_image_size(0, 0, camera);
    const double scale = std::sqrt(static_cast<double>(rays) / (static_cast<double>(typical.width) * typical.height));
    return resolve_image_size(std::max(1u, static_cast<uint32_t>(std::lround(typical.width * scale))), 0, camera);
}

Row closest_row(const std::string& set, const RayBatch& batch, const std::vector<BatchRay>& rays,
                const EmbreeScene& embree, const EmbreeScene& robust, const SceneBuild& build, bool packets) {
    const Bvh& bvh = build.bvh;
    Row row;
    row.set = set;
    row.rays = rays.size();
    row.work = traversal_work(build.data, work_rays(rays), false);
    const ClosestHits ours = best_of_three([&] { return batch.closest_hits(); }, &ClosestHits::kernel_seconds);
    const EmbreeHits theirs = best_of_three([&] { return embree.intersect1(rays); }, &EmbreeHits::seconds);
    row.ours_seconds = ours.kernel_seconds;
    row.embree_seconds = theirs.seconds;
    const EmbreeHits robust_hits = best_of_three([&] { return robust.intersect1(rays); }, &EmbreeHits::seconds);
    row.robust_seconds = robust_hits.seconds;
    row.robust_agreement = compare_closest(ours, robust_hits, bvh.order);
    row.agreement = compare_closest(ours, theirs, bvh.order);
    if (packets) {
        const EmbreeHits packet = best_of_three([&] { return embree.intersect8(rays); }, &EmbreeHits::seconds);
        row.packet_seconds = packet.seconds;
        row.packet_agreement = compare_closest(ours, packet, bvh.order);
    }
    return row;
}

Row any_row(const std::string& set, const RayBatch& batch, const std::vector<BatchRay>& rays,
            const EmbreeScene& embree, const EmbreeScene& robust, const SceneBuild& build,
            const std::vector<glm::vec3>& positions) {
    Row row;
    row.set = set;
    row.rays = rays.size();
    row.work = traversal_work(build.data, work_rays(rays), true);
    const AnyHits ours = best_of_three([&] { return batch.any_hits(); }, &AnyHits::kernel_seconds);
    const EmbreeOcclusion theirs = best_of_three([&] { return embree.occluded1(rays); }, &EmbreeOcclusion::seconds);
    row.ours_seconds = ours.kernel_seconds;
    row.embree_seconds = theirs.seconds;
    const EmbreeOcclusion robust_occlusion =
        best_of_three([&] { return robust.occluded1(rays); }, &EmbreeOcclusion::seconds);
    row.robust_seconds = robust_occlusion.seconds;
    row.robust_agreement = compare_any(ours, robust_occlusion);
    classify_embree_only(row.robust_agreement, rays, ours, robust_occlusion, robust, positions);
    row.agreement = compare_any(ours, theirs);
    classify_embree_only(row.agreement, rays, ours, theirs, embree, positions);
    return row;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
}

struct Report {
    std::string scene, device, features;
    size_t triangles = 0;
    unsigned threads = 0;
    double build_seconds = 0.0, embree_build_seconds = 0.0;
    size_t traversal_bytes = 0;
    TreeCost tree;
    std::vector<Row> rows;
};

// How the segments Embree alone finds blocked split, where they were classified.
std::string embree_only_split(const Agreement& a) {
    if (a.embree_past_end + a.embree_inside == 0) return "";
    return " [" + std::to_string(a.embree_past_end) + " at or past the segment's end, " +
           std::to_string(a.embree_inside) + " inside it]";
}

void print_table(std::ostream& out, const Report& r) {
    out << "scene    " << r.scene << " (" << r.triangles << " triangles; compiled for: " << r.features << ")\n"
        << "device   " << r.device << "; Embree on " << r.threads << " threads\n"
        << std::fixed << std::setprecision(3) << "build    ours " << r.build_seconds << " s (one thread), Embree "
        << r.embree_build_seconds << " s (RTC_BUILD_QUALITY_HIGH, " << r.threads << " threads)\n"
        << std::setprecision(1) << "tree     " << static_cast<double>(r.traversal_bytes) / r.triangles
        << " bytes a triangle; a ray through the scene's box meets " << std::setprecision(2) << r.tree.node_visits
        << " nodes and " << r.tree.block_tests << " blocks of four triangles (SAH)\n\n"
        << std::defaultfloat;
    out << "M rays/s; Embree 1: rtcIntersect1 or rtcOccluded1, Embree 8: rtcIntersect8, agreement: our hits as\n"
        << "Embree 1's; robust: Embree 1 in Embree's robust mode\n";
    out << std::left << std::setw(10) << "set" << std::right << std::setw(10) << "rays" << std::setw(12) << "ours"
        << std::setw(12) << "Embree 1" << std::setw(13) << "ours/Embree" << std::setw(12) << "Embree 8"
        << std::setw(12) << "agreement" << std::setw(10) << "robust" << std::setw(14) << "ours/robust" << "\n";
    out << std::fixed;
    for (const Row& row : r.rows) {
        const double ours = mrays(row.rays, row.ours_seconds), embree = mrays(row.rays, row.embree_seconds),
                     robust = mrays(row.rays, row.robust_seconds);
        std::ostringstream packet;
        if (row.packet_seconds) packet << std::fixed << std::setprecision(2) << mrays(row.rays, *row.packet_seconds);
        else packet << "-";
        out << std::left << std::setw(10) << row.set << std::right << std::setw(10) << row.rays << std::setprecision(2)
            << std::setw(12) << ours << std::setw(12) << embree << std::setw(13) << ours / embree << std::setw(12)
            << packet.str() << std::setprecision(3) << std::setw(11) << 100.0 * row.agreement.fraction() << "%"
            << std::setprecision(2) << std::setw(10) << robust << std::setw(14) << ours / robust << "\n";
    }
    out << "work     a ray, nodes + blocks, by a CPU's traversal one ray at a time:" << std::setprecision(2);
    for (const Row& row : r.rows)
        out << (&row == &r.rows.front() ? " " : ", ") << row.set << " " << row.work.node_visits << " + "
            << row.work.block_tests;
    out << "\n";
    const auto disagreement = [&](const std::string& set, const Agreement& a) {
        if (a.agree == a.rays) return;
        out << set << ": " << a.rays - a.agree << " disagree (" << a.ours_only << " hit by us alone, "
            << a.embree_only << " by Embree alone" << embree_only_split(a) << ", " << a.other_triangle
            << " another triangle, " << a.other_t << " t off by more than " << std::defaultfloat << kTTolerance
            << " relative)\n" << std::fixed;
    };
    for (const Row& row : r.rows) disagreement(row.set, row.agreement);
    for (const Row& row : r.rows) disagreement("robust " + row.set, row.robust_agreement);
}

void write_json(const std::string& path, const Report& r) {
    std::ofstream out(path);
    out << std::setprecision(6) << "{\n  \"scene\": " << json_string(r.scene) << ",\n  \"triangles\": " << r.triangles
        << ",\n  \"device\": " << json_string(r.device) << ",\n  \"features\": " << json_string(r.features)
        << ",\n  \"threads\": " << r.threads << ",\n  \"build_seconds\": " << r.build_seconds
        << ",\n  \"embree_build_seconds\": " << r.embree_build_seconds
        << ",\n  \"bytes_per_triangle\": " << static_cast<double>(r.traversal_bytes) / r.triangles
        << ",\n  \"sah_node_visits\": " << r.tree.node_visits << ",\n  \"sah_block_tests\": " << r.tree.block_tests
        << ",\n  \"sets\": [";
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const Row& row = r.rows[i];
        const double ours = mrays(row.rays, row.ours_seconds), embree = mrays(row.rays, row.embree_seconds);
        out << (i ? "," : "") << "\n    {\"set\": " << json_string(row.set) << ", \"rays\": " << row.rays
            << ", \"ours_mrays_per_s\": " << ours << ", \"embree_mrays_per_s\": " << embree
            << ", \"ours_over_embree\": " << ours / embree << ", \"agreement\": " << row.agreement.fraction()
            << ", \"embree_robust_mrays_per_s\": " << mrays(row.rays, row.robust_seconds)
            << ", \"ours_over_embree_robust\": " << row.robust_seconds / row.ours_seconds
            << ", \"robust_agreement\": " << row.robust_agreement.fraction()
            << ", \"node_visits_per_ray\": " << row.work.node_visits
            << ", \"block_tests_per_ray\": " << row.work.block_tests;
        if (row.packet_seconds)
            out << ", \"embree_packet8_mrays_per_s\": " << mrays(row.rays, *row.packet_seconds)
                << ", \"packet8_agreement\": " << row.packet_agreement.fraction();
        out << "}";
    }
    out << "\n  ]\n}\n";
    if (!out) throw InputError(path + ": cannot write the JSON report");
}

int run(const Options& options) {
    // Every placement written out, one tree on both sides, unless --instancing
    // asks for shared meshes: then ours are a two-level tree and Embree's its
    // own instances, hits compared by the unique triangle, the rays drawn on
    // the placed triangles.
    const Scene scene = load_gltf(options.scene, LoadOptions{-1, options.instancing});
    const Scene flat = scene.instances.empty() ? Scene{} : flattened(scene);
    const Scene& placed = scene.instances.empty() ? scene : flat;
    setenv("POCL_MAX_PTHREAD_COUNT", std::to_string(options.threads).c_str(), 0);
    setenv("POCL_AFFINITY", "1", 0);
    const OpenClDevice device = open_device(options.device);
    check_shared_layouts(device);
    const SceneBuild build(scene); // as a render builds it, the BVH's build timed
    const Bvh& bvh = build.bvh;
    const DeviceScene uploaded = upload_scene(device.context, build.data);
    Report report;
    RenderSettings settings;
    settings.kernels = options.kernels;
    settings.trace_width = options.trace_width;
    const KernelProgram program = build_render_program(device, scene, settings, &report.features);
    const EmbreeScene embree(scene, options.threads);
    const EmbreeScene robust(scene, options.threads, EmbreeMode::Robust);
    report.scene = options.scene;
    report.triangles = scene.triangle_count();
    report.threads = options.threads;
    report.build_seconds = build.seconds;
    report.embree_build_seconds = embree.build_seconds();
    report.traversal_bytes = build.data.traversal_bytes();
    report.tree = tree_cost(bvh);
    report.device = device.info.name + " (" + std::to_string(device.info.compute_units) + " compute units, " +
                    device.info.platform + " " + device.info.driver + ")";
    if (scene_features(scene).alpha_mask)
        std::cerr << "warning: the kernels skip alpha-masked texels and Embree does not: expect disagreement\n";

    const SceneCamera camera = scene.camera ? *scene.camera : frame_bounds(scene.bounds());
    {
        const RayBatch batch(device, program.program, uploaded,
                             make_device_camera(camera, image_of_about(options.rays, scene.camera)), 0);
        report.rows.push_back(closest_row("camera", batch, batch.rays(), embree, robust, build, true));
    }
    {
        const std::vector<BatchRay> rays = bounce_rays(placed, options.rays, 1);
        report.rows.push_back(closest_row("bounce", RayBatch(device, program.program, uploaded, rays), rays, embree,
                                          robust, build, false));
    }
    {
        const std::vector<BatchRay> rays = shadow_segments(placed, options.rays, 2);
        report.rows.push_back(
            any_row("shadow", RayBatch(device, program.program, uploaded, rays), rays, embree, robust, build,
                    placed.positions));
    }

    print_table(std::cout, report);
    if (!options.json.empty()) write_json(options.json, report);
    for (const Row& row : report.rows) {
        const std::pair<const char*, const Agreement*> references[] = {
            {"Embree", &row.agreement}, {"Embree's packets", &row.packet_agreement},
            {"Embree's robust mode", &row.robust_agreement}};
        for (const auto& [reference, a] : references)
            if (1.0 - a->explained_fraction() > kMaxMismatch) {
                std::cerr << "error: " << row.set << " rays: the kernels and " << reference << " disagree on "
                          << std::setprecision(3) << 100.0 * (1.0 - a->explained_fraction()) << "% of rays (at most "
                          << 100.0 * kMaxMismatch << "% allowed)\n";
                return 1;
            }
    }
    return 0;
}

} // namespace
} // namespace wf::bench

int main(int argc, const char** argv) {
    try {
        return wf::bench::run(wf::bench::parse(argc, argv));
    } catch (...) {
        return wf::report_exception();
    }
}
