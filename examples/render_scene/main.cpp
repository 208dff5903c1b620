// main.cpp — the renderer as a library: load a glTF scene, render it on the
// first OpenCL device at 64x64, 16 spp, write the image, and print the mean
// radiance and the rate.   render_scene SCENE.gltf OUT.exr
#include <iostream>

#include "device/opencl_device.h"
#include "gltf/gltf_loader.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/environment_map.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: render_scene SCENE.gltf OUT.exr\n";
        return 2;
    }
    try {
        wf::Scene scene = wf::load_gltf(argv[1]);
        wf::light_unlit_scene(scene);
        const wf::OpenClDevice device = wf::open_device("");
        wf::RenderSettings settings;
        settings.spp = 16;
        const wf::ImageSize size = wf::resolve_image_size(64, 0, scene.camera);
        const wf::RenderOutput out = wf::render_scene(
            device, scene, scene.camera ? *scene.camera : wf::frame_bounds(scene.bounds()), size, settings);
        wf::write_image(argv[2], out.film.mean, wf::ImageMetadata{}, {});
        double sum = 0.0;
        for (float v : out.film.mean.rgb) sum += v;
        std::cout << "mean radiance " << sum / out.film.mean.rgb.size() << ", "
                  << out.summary.stats.samples / out.summary.stats.seconds * 1e-6 << " M samples/s on "
                  << out.summary.device << "\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
