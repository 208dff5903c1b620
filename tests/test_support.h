// test_support.h — what several test files need: the OpenCL CPU device the
// suite runs on (opened once), scenes built in code, and image statistics.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "film.h"
#include "opencl_device.h"
#include "scene.h"

namespace wf::test {

// PoCL's CPU device, shared by every test in the process.
const OpenClDevice& cpu_device();

// Appends a material and returns its index.
uint32_t add_material(Scene& scene, glm::vec3 albedo, glm::vec3 emission, bool double_sided);

// Appends the quad a-b-c-d as triangles (a,b,c) and (a,c,d); its front face is
// the one from which a, b, c run counter-clockwise. Flat shading normals.
void add_quad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t material);

// An axis-aligned box from lo to hi whose six faces face inward.
void add_box_inward(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material);

struct ChannelStats {
    double mean = 0.0;
    double stddev = 0.0; // of the pixel values about their mean
};

// Mean and standard deviation of one channel over all pixels.
ChannelStats channel_stats(const Image& image, int channel);

// The bytes of a file, for comparing two renders bit for bit.
std::string read_file(const std::string& path);

} // namespace wf::test
