// gltf_loader.cpp — glTF 2.0 into wf::Scene. tinygltf parses the JSON and
// loads the buffers; everything after that is checked here, because tinygltf
// trusts the file: it does not range-check accessors, indices or node
// references, and it parses sparse accessors without applying them.
//
// In load order: read the file, parse it (images kept encoded), check
// extensions, convert materials one to one (decoding the images they use,
// gltf_textures.h), walk the node tree of the default scene instancing each
// mesh's object-space triangles with the node's world matrix, then pick the
// camera among those the walk met.
//
// The parts, in that order: gltf_file.h (reading, parsing, the folder
// sandbox; with gltf_glb.h and gltf_json_scan.h, what is checked before
// tinygltf parses), gltf_diagnostics.h (messages, extensions), gltf_float.h
// (numbers as the renderer's floats), gltf_materials.h and gltf_textures.h,
// gltf_nodes.h (transforms, cameras), gltf_meshes.h and gltf_accessors.h
// (primitives), gltf_lights.h. This file walks the nodes and puts the scene
// together.
#include "gltf/gltf_loader.h"

#include <cmath>
#include <map>
#include <optional>

#include "base/errors.h"
#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_float.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_nodes.h"
#include "gltf/gltf_textures.h"
#include "scene/mesh_placement.h"

namespace wf {
namespace {

using tinygltf::Model;

class SceneBuilder {
public:
    SceneBuilder(const Model& model, const std::string& path)
        : model_(model), path_(path), meshes_(model.meshes.size()), shares_(model.meshes.size()) {}

    Scene build(const LoadOptions& options) {
        check_extensions(model_, path_, scene_.warnings);
        check_core_features(model_, scene_.warnings);
        convert_materials();
        walk_nodes();
        place_meshes(options.instancing);
        if (scene_.triangle_count() == 0) fail(path_, "the scene has no triangles");
        scene_.punctual_lights = punctual_lights(model_, visited_, path_);
        scene_.camera = choose_camera(options);
        return std::move(scene_);
    }

private:
    // A camera the node walk met, with its node's world matrix.
    struct PlacedCamera {
        size_t camera;
        glm::dmat4 world;
    };

    // A mesh a node places, with the node's world matrix.
    struct Placement {
        size_t mesh;
        glm::dmat4 world;
        size_t node;      // the node that places it,
        int64_t instance; // and its EXT_mesh_gpu_instancing instance, -1 for none (where_of)
    };

    // Scene::materials mirrors the file's materials index for index; the
    // default material, if needed, comes after them.
    void convert_materials() {
        GltfTextures textures(model_, path_, scene_.textures);
        std::map<std::string, size_t> unsupported; // property -> materials that set it
        for (size_t i = 0; i < model_.materials.size(); ++i) {
            scene_.materials.push_back(convert_material(model_.materials[i], i, path_));
            textures.convert(model_.materials[i], i, scene_.materials.back()); // gltf_textures.h
            for (const std::string& property : unsupported_properties(model_.materials[i])) ++unsupported[property];
        }
        for (std::string& warning : textures.warnings()) scene_.warnings.push_back(std::move(warning));
        std::string ignored;
        for (const auto& [property, materials] : unsupported)
            ignored += (ignored.empty() ? "" : ", ") + property + " (" + std::to_string(materials) + " material(s))";
        if (!ignored.empty()) scene_.warnings.push_back("material properties not supported, ignored: " + ignored);
    }

    uint32_t material_index(int gltf_material, const std::string& where) {
        if (gltf_material >= 0) {
            if (size_t(gltf_material) >= model_.materials.size())
                fail(where, "material " + std::to_string(gltf_material) + " does not exist");
            return uint32_t(gltf_material);
        }
        if (!default_material_) {
            default_material_ = uint32_t(scene_.materials.size());
            scene_.materials.push_back(default_material());
        }
        return *default_material_;
    }

    // The default scene's roots; without scenes, every node no other node
    // lists as a child.
    std::vector<int> root_nodes() const {
        if (!model_.scenes.empty()) {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (size_t(scene) >= model_.scenes.size())
                fail(path_, "default scene " + std::to_string(scene) + " does not exist");
            return model_.scenes[size_t(scene)].nodes;
        }
        std::vector<bool> is_child(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes)
            for (int child : node.children)
                if (child >= 0 && size_t(child) < is_child.size()) is_child[size_t(child)] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < is_child.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
        return roots;
    }

    // Depth first from each root, on a stack of our own: a file can chain
    // nodes deeper than the call stack goes. glTF makes the hierarchy a forest
    // (glTF 2.0, "Nodes and Hierarchy": no cycles, at most one parent), so a
    // node is reached once; were a second parent allowed, a chain that lists
    // each child twice would double the instances at every level.
    void walk_nodes() {
        struct Frame {
            size_t node;
            glm::dmat4 world;
            size_t next_child = 0;
        };
        std::vector<Frame> path; // from the root to the node being walked
        std::vector<bool> on_path(model_.nodes.size(), false);
        std::vector<bool> reached(model_.nodes.size(), false);
        const auto enter = [&](int node_index, const glm::dmat4& parent_world) {
            if (node_index < 0 || size_t(node_index) >= model_.nodes.size())
                fail(path_, "node " + std::to_string(node_index) + " does not exist");
            const auto index = size_t(node_index);
            const std::string where = path_ + ": " + label("node", index, model_.nodes[index].name);
            if (on_path[index]) fail(where, "the node is its own ancestor");
            if (reached[index]) fail(where, "the node is reached a second time: glTF gives a node one parent at most");
            on_path[index] = reached[index] = true;
            path.push_back({index, place(index, parent_world, where)});
        };
        for (int root : root_nodes()) {
            enter(root, glm::dmat4(1.0));
            while (!path.empty()) {
                Frame& top = path.back();
                const std::vector<int>& children = model_.nodes[top.node].children;
                if (top.next_child == children.size()) {
                    on_path[top.node] = false;
                    path.pop_back();
                } else {
                    const glm::dmat4 parent_world = top.world; // enter() may move `top`
                    enter(children[top.next_child++], parent_world);
                }
            }
        }
    }

    // The node's world matrix, with its mesh instanced and its camera noted.
    glm::dmat4 place(size_t index, const glm::dmat4& parent_world, const std::string& where) {
        const tinygltf::Node& node = model_.nodes[index];
        const glm::dmat4 world = parent_world * local_transform(node, where);
        // What the node places (mesh, camera, lights) is taken to float from here.
        check_float_range(world, where, "world transform");
        visited_.push_back({index, world});
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model_.meshes.size())
                fail(where, "mesh " + std::to_string(node.mesh) + " does not exist");
            const std::vector<glm::dmat4> instances = mesh_instances(model_, node, where);
            if (instances.empty()) placements_.push_back({size_t(node.mesh), world, index, -1});
            for (size_t i = 0; i < instances.size(); ++i) { // EXT_mesh_gpu_instancing: each its own placement
                const Placement placed{size_t(node.mesh), world * instances[i], index, int64_t(i)};
                if (!in_float_range(placed.world)) check_float_range(placed.world, where_of(placed), "transform");
                placements_.push_back(placed);
            }
        }
        if (node.camera >= 0) {
            if (size_t(node.camera) >= model_.cameras.size())
                fail(where, "camera " + std::to_string(node.camera) + " does not exist");
            cameras_.push_back({size_t(node.camera), world});
        }
        return world;
    }

    // The node, and the instance of EXT_mesh_gpu_instancing, that placed a mesh: for messages alone.
    std::string where_of(const Placement& placed) const {
        const std::string node = path_ + ": " + label("node", placed.node, model_.nodes[placed.node].name);
        return placed.instance < 0 ? node : node + ": instance " + std::to_string(placed.instance);
    }

    // Appends one placement of a mesh in world space (scene/mesh_placement.h).
    // A transform that carries a finite vertex past float range is an error.
    void flatten(const Placement& placed) {
        const MeshTriangles& mesh = mesh_triangles(placed.mesh);
        for (size_t corner = 0; corner < mesh.positions.size(); ++corner) {
            const glm::dvec3 p(placed.world * glm::dvec4(mesh.positions[corner], 1.0));
            if (!glm::all(glm::lessThanEqual(glm::abs(p), glm::dvec3(kMaxCoordinate))))
                fail(where_of(placed) + ": " + label("mesh", placed.mesh, model_.meshes[placed.mesh].name),
                     "vertex " + std::to_string(corner) +
                         " leaves float range (a quarter of FLT_MAX) after the node transform");
        }
        place_mesh(mesh, placed.world, scene_);
    }

    // What sharing needs of a mesh, found once: whether it may be shared
    // (it has triangles, emits nothing, since each placement of an emitter is
    // a light of its own, and its own coordinates are in range), and its box.
    struct MeshShare {
        bool allowed = false;
        Bounds box;
    };

    const MeshShare& mesh_share(size_t mesh_index) {
        std::optional<MeshShare>& cached = shares_[mesh_index];
        if (cached) return *cached;
        const MeshTriangles& mesh = mesh_triangles(mesh_index);
        MeshShare share;
        for (const glm::vec3& p : mesh.positions) share.box.grow(p);
        share.allowed = !mesh.materials.empty() && within_float_range(share.box);
        for (uint32_t material : mesh.materials) share.allowed = share.allowed && !scene_.materials[material].emits();
        return *(cached = share);
    }

    static bool within_float_range(const Bounds& b) {
        const float limit = float(kMaxCoordinate);
        return glm::all(glm::lessThanEqual(glm::abs(b.lo), glm::vec3(limit))) &&
               glm::all(glm::lessThanEqual(glm::abs(b.hi), glm::vec3(limit)));
    }

    // Whether a placement can be an instance of a shared mesh: a mesh that
    // may be shared, and a transform the kernels can invert whose placed box
    // stays in float range.
    bool can_share(const Placement& placed) {
        const MeshShare& mesh = mesh_share(placed.mesh);
        if (!mesh.allowed) return false;
        const double det = glm::determinant(glm::dmat3(placed.world));
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
        const glm::dmat4 inverse = glm::inverse(placed.world);
        for (int column = 0; column < 4; ++column)
            if (!glm::all(glm::lessThanEqual(glm::abs(inverse[column]), glm::dvec4(kMaxCoordinate)))) return false;
        return within_float_range(transformed_bounds(mesh.box, placed.world));
    }

    // The meshes placed: in world space, each where it is placed, but for a
    // mesh that two or more placements can share, which is kept once after
    // the rest and placed by instances where `instancing` says so.
    void place_meshes(Instancing instancing) {
        std::vector<bool> sharing(placements_.size(), false);
        std::vector<size_t> sharers(model_.meshes.size(), 0);
        for (size_t i = 0; i < placements_.size() && instancing != Instancing::Off; ++i)
            if (can_share(placements_[i])) {
                sharing[i] = true;
                ++sharers[placements_[i].mesh];
            }
        const auto shared = [&](size_t mesh) {
            const size_t copies = sharers[mesh] - 1; // those beyond the first, which sharing saves
            return sharers[mesh] >= 2 && (instancing == Instancing::All ||
                                          copies * mesh_triangles(mesh).materials.size() >= kLargeSharedTriangles);
        };
        for (size_t i = 0; i < placements_.size(); ++i) {
            sharing[i] = sharing[i] && shared(placements_[i].mesh);
            if (!sharing[i]) flatten(placements_[i]);
        }
        constexpr uint32_t kNotShared = ~0u;
        std::vector<uint32_t> shared_index(model_.meshes.size(), kNotShared);
        for (size_t i = 0; i < placements_.size(); ++i) {
            if (!sharing[i]) continue;
            const size_t mesh = placements_[i].mesh;
            if (shared_index[mesh] == kNotShared) {
                shared_index[mesh] = uint32_t(scene_.shared_meshes.size());
                scene_.shared_meshes.push_back(
                    {uint32_t(scene_.triangle_count()), uint32_t(mesh_triangles(mesh).materials.size())});
                place_mesh(mesh_triangles(mesh), glm::dmat4(1.0), scene_);
            }
            scene_.instances.push_back({shared_index[mesh], placements_[i].world});
        }
    }

    const MeshTriangles& mesh_triangles(size_t mesh_index) {
        std::optional<MeshTriangles>& cached = meshes_[mesh_index];
        if (!cached) cached = build_mesh(mesh_index);
        return *cached;
    }

    MeshTriangles build_mesh(size_t mesh_index) {
        const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
        const std::string mesh_label = label("mesh", mesh_index, mesh.name);
        const std::string where = path_ + ": " + mesh_label;
        MeshTriangles triangles;
        SkippedElements skipped;
        for (const tinygltf::Primitive& primitive : mesh.primitives)
            append_primitive(model_, primitive, where,
                             [this](int material, const std::string& at) { return material_index(material, at); },
                             scene_.materials, triangles, skipped);
        if (!skipped.describe().empty())
            scene_.warnings.push_back(mesh_label + ": " + skipped.describe());
        if (!triangles.materials.empty()) {
            triangles.name_index = uint32_t(scene_.mesh_names.size());
            scene_.mesh_names.push_back(mesh.name.empty() ? mesh_label : mesh.name);
        }
        return triangles;
    }

    std::optional<SceneCamera> choose_camera(const LoadOptions& options) const {
        const auto is_perspective = [this](size_t camera) {
            return model_.cameras[camera].type == "perspective";
        };
        if (options.camera_index < 0) {
            for (const PlacedCamera& placed : cameras_)
                if (is_perspective(placed.camera)) return convert_placed(placed);
            return std::nullopt;
        }
        const auto wanted = size_t(options.camera_index);
        if (wanted >= model_.cameras.size())
            fail(path_, "camera " + std::to_string(wanted) + " does not exist (the file has " +
                            std::to_string(model_.cameras.size()) + ")");
        const tinygltf::Camera& camera = model_.cameras[wanted];
        if (!is_perspective(wanted))
            fail(path_, label("camera", wanted, camera.name) + " is not perspective (type '" +
                            camera.type + "')");
        for (const PlacedCamera& placed : cameras_)
            if (placed.camera == wanted) return convert_placed(placed);
        fail(path_, label("camera", wanted, camera.name) + " is not placed in the scene");
    }

    SceneCamera convert_placed(const PlacedCamera& placed) const {
        const tinygltf::Camera& camera = model_.cameras[placed.camera];
        return convert_camera(camera, placed.world,
                              path_ + ": " + label("camera", placed.camera, camera.name));
    }

    const Model& model_;
    const std::string& path_;
    Scene scene_;
    std::vector<std::optional<MeshTriangles>> meshes_; // by glTF mesh index, built on first use
    std::optional<uint32_t> default_material_;
    std::vector<PlacedCamera> cameras_; // in the order the node walk met them
    std::vector<Placement> placements_; // the meshes placed, in the order the node walk met them
    std::vector<std::optional<MeshShare>> shares_; // by glTF mesh index, found on first use
    std::vector<NodeWorld> visited_;    // every node the walk reached, for its lights
};

// Both entry points; the file is read from `path` when `given` is null.
Scene load(const std::string& path, const std::vector<unsigned char>* given, const LoadOptions& options) {
    try {
        const std::vector<unsigned char> read = given ? std::vector<unsigned char>() : read_gltf_file(path);
        const Model model = parse_model(path, given ? *given : read);
        return SceneBuilder(model, path).build(options);
    } catch (const std::bad_alloc&) { // an accessor without a bufferView may claim any count
        throw InputError(path + ": not enough memory to load the file");
    }
}

} // namespace

Scene load_gltf(const std::string& path, const LoadOptions& options) {
    return load(path, nullptr, options);
}

Scene load_gltf_bytes(const std::string& path, const std::vector<unsigned char>& bytes, const LoadOptions& options) {
    return load(path, &bytes, options);
}

} // namespace wf
