// test_support.h — what several test files need: the OpenCL CPU device the
// suite runs on (opened once), scenes built in code, and image statistics.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

#include <glm/glm.hpp>

#include "device/device_scene.h"
#include "film/film.h"
#include "device/opencl_device.h"
#include "integrator/ray_batch.h"
#include "scene/scene.h"

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

// Prints one line of what a test measured ("[ measured ] ..."), the figures
// the tables in docs/ quote.
void report_measured(const std::string& line);

// The furnace: the box [-1, 1]^3 whose inward walls all emit `emission` and
// reflect `albedo`, where the radiance is emission / (1 - albedo) everywhere.
Scene furnace_box(float albedo, float emission);

// The unit sphere about the origin, `rings` x `segments` quads, with the
// sphere's own normals at the corners.
void add_smooth_sphere(Scene& scene, uint32_t material, int rings = 64, int segments = 128);

// The Cornell box (scenes/cornell-box.gltf) with its short block a shared
// mesh placed four times: where it stood, mirrored across x elsewhere on the
// floor, turned and stretched in the air by the red wall, and shrunk on the
// tall block. The light and the rest stay in world space.
Scene instanced_cornell();

// A ray for the device tests; the direction need not be unit.
using TestRay = BatchRay;

// The `intersect` stage kernel run over one queue holding `rays`, on
// cpu_device() (host/integrator/ray_batch.h); the hits as it stores them: (t, u, v,
// triangle index bits).
std::vector<cl_float4> intersect_on_device(const DeviceSceneData& data, const std::vector<TestRay>& rays);

struct ChannelStats {
    double mean = 0.0;
    double stddev = 0.0; // of the pixel values about their mean
};

// Mean and standard deviation of one channel over all pixels.
ChannelStats channel_stats(const Image& image, int channel);

// The bytes of a file, for comparing two renders bit for bit.
std::string read_file(const std::string& path);

struct ProcessResult {
    int exit_code = -1; // -1 when the process did not exit normally
    std::string out, err;
};

// Runs the `wavefront` executable with `args` (shell words), as a user would,
// capturing its output in files under `scratch_dir`; `env` (NAME=value words)
// is added to its environment. With `limit_s`, a run still going after that
// many seconds is killed and exits 124 (timeout(1)): for tests of inputs that
// could make it wait forever, which then fail instead of hanging the suite.
ProcessResult run_wavefront(const std::string& args, const std::string& scratch_dir, const std::string& env = "",
                            int limit_s = 0);

// The same, with stdout and stderr both on one pseudo-terminal, as a user at a
// terminal sees them: `out` holds what the terminal received, `err` is empty.
// `watch`, if given, sees what has arrived so far, and the process, after each
// read (to signal it once it shows a sign of life, say).
ProcessResult run_wavefront_on_terminal(const std::string& args, const std::string& scratch_dir,
                                        const std::function<void(const std::string&, pid_t)>& watch = {});

// ---------------------------------------------------------------------------
// Added for test_stability.cpp.

// A camera at `position` looking along `forward`; `up` need only not be
// parallel to it (it is made orthogonal and unit here).
SceneCamera camera_looking(glm::vec3 position, glm::vec3 forward, glm::vec3 up, float vertical_fov);

// Appends the triangle a-b-c with the normal of its front face, or +z where it
// has none (zero area), as the glTF loader does; returns its index.
uint32_t add_triangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material);

// The mean of one channel over all pixels and its standard error, from the
// film's per-pixel variance of the mean (pixels are independent estimates):
// SE² = Σ variance_of_mean / N².
struct MeanWithError {
    double mean = 0.0;
    double standard_error = 0.0;
};
MeanWithError image_mean(const FilmReadout& film, int channel);

// |difference| of two renders' image means of one channel over its standard
// error, the two renders being independent.
double image_mean_z(const FilmReadout& a, const FilmReadout& b, int channel);

// Whether every value of an image is finite.
bool all_finite(const Image& image);

// Compiles OpenCL C `source` for cpu_device() with `options`; a failed build
// throws std::runtime_error carrying the build log.
cl::Program build_test_program(const std::string& source, const std::string& options = "");

// Runs kernel `name` of `program` on cpu_device() over `work_items`
// work-items, its arguments one read-only buffer per input, in order, then an
// output of `out_floats` floats, which it returns.
template <typename... Input>
std::vector<float> run_probe(const cl::Program& program, const char* name, size_t work_items, size_t out_floats,
                             const std::vector<Input>&... inputs) {
    const OpenClDevice& device = cpu_device();
    cl::Kernel kernel(program, name);
    std::vector<cl::Buffer> buffers;
    (buffers.emplace_back(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, inputs.size() * sizeof(Input),
                          const_cast<Input*>(inputs.data())),
     ...);
    cl::Buffer output(device.context, CL_MEM_WRITE_ONLY, out_floats * sizeof(float));
    buffers.push_back(output);
    for (cl_uint i = 0; i < buffers.size(); ++i) kernel.setArg(i, buffers[i]);
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(work_items), cl::NullRange);
    std::vector<float> out(out_floats);
    device.queue.enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    return out;
}

// A glTF file written for a test: one node per mesh (with a uniform scale),
// each mesh one non-indexed triangle primitive whose float POSITIONs live in
// one buffer embedded as a base64 data URI.
struct GltfTestMesh {
    std::string name;
    std::vector<glm::vec3> positions; // three per triangle
    double node_scale = 1.0;
};
void write_gltf(const std::string& path, const std::vector<GltfTestMesh>& meshes);

} // namespace wf::test
