// test_support.cpp — see test_support.h.
#include "test_support.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace wf::test {

const OpenClDevice& cpu_device() {
    static const OpenClDevice device = open_device("cpu");
    return device;
}

uint32_t add_material(Scene& scene, glm::vec3 albedo, glm::vec3 emission, bool double_sided) {
    SceneMaterial m;
    m.name = "material " + std::to_string(scene.materials.size());
    m.albedo = albedo;
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

} // namespace wf::test
