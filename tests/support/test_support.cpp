// test_support.cpp — see test_support.h.
#include "support/test_support.h"

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include "device/kernel_program.h"
#include "gltf/gltf_loader.h"
#include "scene/mesh_placement.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace wf::test {

const OpenClDevice& cpu_device() {
    static const OpenClDevice device = open_device("cpu");
    return device;
}

uint32_t add_material(Scene& scene, glm::vec3 albedo, glm::vec3 emission, bool double_sided) {
    SceneMaterial m;
    m.name = "material " + std::to_string(scene.materials.size());
    m.base_color = albedo;
    m.emission = emission;
    m.double_sided = double_sided;
    scene.materials.push_back(m);
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

void add_quad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t material) {
    if (scene.mesh_names.empty()) scene.mesh_names.push_back("test mesh");
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (const glm::vec3& p : {a, b, c, a, c, d}) {
        scene.positions.push_back(p);
        scene.normals.push_back(n);
    }
    for (int t = 0; t < 2; ++t) {
        scene.triangle_material.push_back(material);
        scene.triangle_mesh.push_back(0);
    }
}

void add_box_inward(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Each face listed counter-clockwise as seen from inside the box.
    const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
    for (const auto& f : faces) add_quad(scene, c[f[0]], c[f[1]], c[f[2]], c[f[3]], material);
}

void report_measured(const std::string& line) { std::cout << "[ measured ] " << line << std::endl; }

Scene furnace_box(float albedo, float emission) {
    Scene scene;
    add_box_inward(scene, glm::vec3(-1.0f), glm::vec3(1.0f),
                   add_material(scene, glm::vec3(albedo), glm::vec3(emission), false));
    return scene;
}

void add_smooth_sphere(Scene& scene, uint32_t material, int rings, int segments) {
    if (scene.mesh_names.empty()) scene.mesh_names.push_back("sphere");
    auto point = [&](int i, int j) {
        const float theta = glm::pi<float>() * float(i) / float(rings),
                    phi = glm::two_pi<float>() * float(j) / float(segments);
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        if (glm::length(glm::cross(b - a, c - a)) == 0.0f) return; // the poles' collapsed corners
        for (const glm::vec3& p : {a, b, c}) {
            scene.positions.push_back(p);
            scene.normals.push_back(glm::normalize(p)); // the unit sphere's own normal
        }
        scene.triangle_material.push_back(material);
        scene.triangle_mesh.push_back(0);
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            // Counter-clockwise seen from outside.
            const glm::vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
            add(a, d, c);
            add(a, c, b);
        }
}

Scene instanced_cornell() {
    const Scene box = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf", LoadOptions{-1, Instancing::Off});
    const size_t block_mesh =
        size_t(std::find(box.mesh_names.begin(), box.mesh_names.end(), "short_block") - box.mesh_names.begin());
    const size_t first = size_t(std::find(box.triangle_mesh.begin(), box.triangle_mesh.end(), block_mesh) -
                                box.triangle_mesh.begin());
    size_t count = 0;
    while (first + count < box.triangle_count() && box.triangle_mesh[first + count] == block_mesh) ++count;
    Scene scene = box;
    for (auto* corners : {&scene.normals, &scene.positions}) corners->clear();
    for (auto* corners : {&scene.uv0, &scene.uv1}) corners->clear();
    for (auto* corners : {&scene.tangents, &scene.colors}) corners->clear();
    scene.triangle_material.clear();
    scene.triangle_mesh.clear();
    place_mesh(mesh_of(box, 0, first), glm::dmat4(1.0), scene);
    place_mesh(mesh_of(box, first + count, box.triangle_count() - first - count), glm::dmat4(1.0), scene);
    // The block in its own space: standing on y = 0 about the origin.
    const Bounds b = triangle_bounds(box, first, count);
    const glm::dvec3 foot(0.5 * (b.lo.x + b.hi.x), 0.0, 0.5 * (b.lo.z + b.hi.z));
    scene.shared_meshes.push_back({uint32_t(scene.triangle_count()), uint32_t(count)});
    place_mesh(mesh_of(box, first, count), glm::translate(glm::dmat4(1.0), -foot), scene);
    const glm::dmat4 identity(1.0);
    scene.instances.push_back({0, glm::translate(identity, foot)});
    scene.instances.push_back(
        {0, glm::scale(glm::translate(identity, glm::dvec3(150.0, 0.0, 420.0)), glm::dvec3(-1.0, 1.0, 1.0))});
    scene.instances.push_back({0, glm::scale(glm::rotate(glm::translate(identity, glm::dvec3(450.0, 330.0, 130.0)),
                                                         0.7, glm::dvec3(0.3, 1.0, 0.2)),
                                             glm::dvec3(0.3, 1.4, 0.5))});
    scene.instances.push_back({0, glm::scale(glm::translate(identity, glm::dvec3(370.0, 330.0, 350.0)),
                                             glm::dvec3(0.25))});
    return scene;
}

std::vector<cl_float4> intersect_on_device(const DeviceSceneData& data, const std::vector<TestRay>& rays) {
    const OpenClDevice& device = cpu_device();
    const DeviceScene uploaded = upload_scene(device.context, data);
    const KernelProgram program = build_kernel_program(device, "wavefront.cl");
    return RayBatch(device, program.program, uploaded, rays).closest_hits().hits;
}

ChannelStats channel_stats(const Image& image, int channel) {
    const size_t n = size_t{image.width} * image.height;
    double sum = 0.0, sum2 = 0.0;
    for (size_t p = 0; p < n; ++p) {
        const double v = image.rgb[3 * p + channel];
        sum += v;
        sum2 += v * v;
    }
    ChannelStats s;
    s.mean = sum / n;
    s.stddev = std::sqrt(std::max(0.0, (sum2 - n * s.mean * s.mean) / (n - 1)));
    return s;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

ProcessResult run_wavefront(const std::string& args, const std::string& scratch_dir, const std::string& env,
                            int limit_s) {
    const std::string out = scratch_dir + "/stdout.txt", err = scratch_dir + "/stderr.txt";
    const std::string command = (env.empty() ? "" : "env " + env + " ") +
                                (limit_s > 0 ? "timeout " + std::to_string(limit_s) + " " : "") + "'" + WF_BINARY +
                                "' " + args + " > '" + out + "' 2> '" + err + "'";
    const int status = std::system(command.c_str());
    return ProcessResult{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
}

ProcessResult run_wavefront_on_terminal(const std::string& args, const std::string& scratch_dir,
                                        const std::function<void(const std::string&, pid_t)>& watch) {
    const std::string command = "cd '" + scratch_dir + "' && exec '" + WF_BINARY + "' " + args;
    int terminal = -1;
    const pid_t child = ::forkpty(&terminal, nullptr, nullptr, nullptr);
    if (child < 0) throw std::runtime_error("forkpty failed");
    if (child == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ProcessResult result;
    char buffer[4096];
    for (ssize_t n; (n = ::read(terminal, buffer, sizeof buffer)) > 0;) {
        result.out.append(buffer, size_t(n));
        if (watch) watch(result.out, child);
    }
    ::close(terminal); // read() fails with EIO once the child has closed its side
    int status = 0;
    ::waitpid(child, &status, 0);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// ---------------------------------------------------------------------------
// Added for test_stability.cpp.

SceneCamera camera_looking(glm::vec3 position, glm::vec3 forward, glm::vec3 up, float vertical_fov) {
    SceneCamera c;
    c.position = position;
    c.forward = glm::normalize(forward);
    c.up = glm::normalize(up - glm::dot(up, c.forward) * c.forward);
    c.vertical_fov = vertical_fov;
    return c;
}

uint32_t add_triangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    if (scene.mesh_names.empty()) scene.mesh_names.push_back("test mesh");
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    const glm::vec3 n = length > 0.0f && std::isfinite(length) ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f);
    for (const glm::vec3& p : {a, b, c}) {
        scene.positions.push_back(p);
        scene.normals.push_back(n);
    }
    scene.triangle_material.push_back(material);
    scene.triangle_mesh.push_back(0);
    return static_cast<uint32_t>(scene.triangle_count() - 1);
}

MeanWithError image_mean(const FilmReadout& film, int channel) {
    const size_t n = size_t{film.mean.width} * film.mean.height;
    double sum = 0.0, variance = 0.0;
    for (size_t p = 0; p < n; ++p) {
        sum += film.mean.rgb[3 * p + channel];
        variance += film.variance_of_mean.rgb[3 * p + channel];
    }
    return MeanWithError{sum / n, std::sqrt(variance) / n};
}

double image_mean_z(const FilmReadout& a, const FilmReadout& b, int channel) {
    const MeanWithError x = image_mean(a, channel), y = image_mean(b, channel);
    return std::fabs(x.mean - y.mean) / std::hypot(x.standard_error, y.standard_error);
}

bool all_finite(const Image& image) {
    return std::all_of(image.rgb.begin(), image.rgb.end(), [](float v) { return std::isfinite(v); });
}

cl::Program build_test_program(const std::string& source, const std::string& options) {
    const OpenClDevice& device = cpu_device();
    cl::Program program(device.context, source);
    try {
        program.build({device.info.device}, ("-cl-std=CL1.2 " + options).c_str());
    } catch (const cl::Error&) {
        throw std::runtime_error("test kernel failed to build: " +
                                 program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device));
    }
    return program;
}

namespace {

std::string to_base64(const std::vector<unsigned char>& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    for (size_t at = 0; at < bytes.size(); at += 3) {
        uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k) group = group << 8 | (at + k < bytes.size() ? bytes[at + k] : 0u);
        const size_t present = std::min<size_t>(3, bytes.size() - at); // 1, 2 or 3 bytes: 2, 3 or 4 digits
        for (size_t k = 0; k < 4; ++k) text += k <= present ? digits[group >> (18 - 6 * k) & 63u] : '=';
    }
    return text;
}

} // namespace

void write_gltf(const std::string& path, const std::vector<GltfTestMesh>& meshes) {
    std::vector<unsigned char> blob;
    std::ostringstream views, accessors, mesh_list, nodes, roots;
    for (size_t m = 0; m < meshes.size(); ++m) {
        const std::vector<glm::vec3>& p = meshes[m].positions;
        const size_t offset = blob.size(), bytes = p.size() * sizeof(glm::vec3);
        blob.resize(offset + bytes);
        std::memcpy(blob.data() + offset, p.data(), bytes); // glm::vec3 is three packed floats
        const char* sep = m ? "," : "";
        views << sep << "{\"buffer\":0,\"byteOffset\":" << offset << ",\"byteLength\":" << bytes << "}";
        accessors << sep << "{\"bufferView\":" << m << ",\"componentType\":5126,\"count\":" << p.size()
                  << ",\"type\":\"VEC3\"}";
        mesh_list << sep << "{\"name\":\"" << meshes[m].name << "\",\"primitives\":[{\"attributes\":{\"POSITION\":"
                  << m << "}}]}";
        nodes << sep << "{\"mesh\":" << m << ",\"scale\":[" << meshes[m].node_scale << "," << meshes[m].node_scale
              << "," << meshes[m].node_scale << "]}";
        roots << sep << m;
    }
    std::ofstream out(path);
    out.precision(17);
    out << "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[" << roots.str() << "]}],"
        << "\"nodes\":[" << nodes.str() << "],\"meshes\":[" << mesh_list.str() << "],"
        << "\"accessors\":[" << accessors.str() << "],\"bufferViews\":[" << views.str() << "],"
        << "\"buffers\":[{\"byteLength\":" << blob.size()
        << ",\"uri\":\"data:application/octet-stream;base64," << to_base64(blob) << "\"}]}";
}

} // namespace wf::test
