#include "scene/gltf_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "core/untrusted_text.h"
#include "scene/default_walkthrough.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_cameras.h"
#include "scene/gltf_document_checks.h"
#include "scene/gltf_materials.h"
#include "scene/mesh_ops.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

namespace glint {
namespace {

constexpr int kNoSlot = -1;

// The most instances a glTF's node hierarchy may expand to, and the most node visits (one per node on
// each path from a root) it may take (docs/scene-format.md, "Limits"): far above real scenes (the
// paper's largest has a few hundred instances), far below what would exhaust memory or time (an
// instance is about 100 bytes here, and more in every acceleration structure).
constexpr std::uint64_t kMaxGltfInstances = 1'000'000;

// True when the file starts with the binary glTF magic "glTF" (whatever its extension says).
bool is_binary_gltf(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  char magic[4] = {};
  file.read(magic, 4);
  return file.gcount() == 4 && magic[0] == 'g' && magic[1] == 'l' && magic[2] == 'T' && magic[3] == 'F';
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

// The node's transform relative to its parent: "matrix" (column-major), else T * R * S.
mat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    mat4 m(1.0f);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(node.matrix[static_cast<std::size_t>(c * 4 + r)]);
    return m;
  }
  mat4 m(1.0f);
  if (node.translation.size() == 3)
    m[3] = vec4(static_cast<float>(node.translation[0]), static_cast<float>(node.translation[1]),
                static_cast<float>(node.translation[2]), 1.0f);
  if (node.rotation.size() == 4) {
    // glTF stores quaternions as (x, y, z, w); glm's constructor takes w first.
    const glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    m = m * glm::scale(mat4(1.0f), vec3(static_cast<float>(node.scale[0]), static_cast<float>(node.scale[1]),
                                        static_cast<float>(node.scale[2])));
  return m;
}

// Turns one tinygltf::Model into a Scene, converting meshes, materials and images on first use.
class GltfSceneBuilder {
public:
  GltfSceneBuilder(const tinygltf::Model& model, const GltfImageFailures& image_failures,
                   const std::filesystem::path& path, const LoadOptions& options)
      : model_(model), image_failures_(image_failures), path_(path), label_(path.string()), options_(options) {
    scene_.name = path.stem().string();
    scene_.source = label_;
    primitive_slots_.resize(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m) primitive_slots_[m].resize(model.meshes[m].primitives.size());
    material_slots_.assign(model.materials.size(), kNoSlot);
    image_slots_.assign(model.images.size(), std::nullopt);
  }

  Scene build() {
    const std::vector<int> roots = root_nodes();
    check_instance_expansion(roots);
    expand_nodes(roots);
    if (skipped_primitives_ > 0)
      log_warning("{}: skipped {} primitive(s) made of points or lines (only triangles are loaded)", label_,
                  skipped_primitives_);
    if (degenerate_triangles_ > 0)
      log_warning("{}: dropped {} degenerate (zero-area) triangle(s)", label_, degenerate_triangles_);
    if (scene_.instances.empty()) fail("{}: the scene is empty (no node of the scene references triangles)", label_);
    // The file's own camera when it has one (gltf_cameras.h), else a default one; the light fits it.
    assign_default_walkthrough(scene_, first_camera_ ? gltf_fixed_camera(model_, *first_camera_, label_) : std::nullopt);
    scene_.validate();
    return std::move(scene_);
  }

private:
  // The default scene's nodes; without one, every node that is nobody's child.
  std::vector<int> root_nodes() const {
    if (model_.defaultScene >= 0) {
      if (static_cast<std::size_t>(model_.defaultScene) >= model_.scenes.size())
        fail("{}: scene: scene {} does not exist ({} scenes)", label_, model_.defaultScene, model_.scenes.size());
      return model_.scenes[static_cast<std::size_t>(model_.defaultScene)].nodes;
    }
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int child : node.children)
        if (child >= 0 && static_cast<std::size_t>(child) < is_child.size()) is_child[static_cast<std::size_t>(child)] = true;
    std::vector<int> roots;
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      if (!is_child[n]) roots.push_back(static_cast<int>(n));
    return roots;
  }

  // The node graph may be a DAG (a child listed by several parents, or twice by one): each path from a
  // root visits its nodes once more and makes one more instance, so 41 levels that each list the same
  // child twice are 2^41 visits and instances from 1.3 KB of JSON. Count both first, per node and
  // saturating, with a depth-first walk that also finds cycles, and refuse more than
  // kMaxGltfInstances of either before anything is expanded.
  void check_instance_expansion(const std::vector<int>& roots) const {
    enum class State : std::uint8_t { unvisited, open, done };
    struct Counts {
      std::uint64_t visits = 0;     // the node and every node below it, once per path
      std::uint64_t instances = 0;  // at most one per primitive of each mesh visited
    };
    static constexpr std::uint64_t kSaturated = kMaxGltfInstances + 1;  // static: std::min binds it by reference
    const auto saturating_add = [](std::uint64_t a, std::uint64_t b) { return std::min(a + b, kSaturated); };  // a, b <= kSaturated
    std::vector<State> state(model_.nodes.size(), State::unvisited);
    std::vector<Counts> below(model_.nodes.size());
    const auto check_index = [&](int index) {
      if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
        fail("{}: node {} does not exist ({} nodes)", label_, index, model_.nodes.size());
      return static_cast<std::size_t>(index);
    };
    struct Frame {
      std::size_t node;
      std::size_t next_child;
    };
    std::vector<Frame> stack;  // explicit, so that a chain of a million nodes cannot overflow the call stack
    Counts total;
    for (int root : roots) {
      const std::size_t start = check_index(root);
      if (state[start] == State::unvisited) {
        stack.push_back({start, 0});
        state[start] = State::open;
      }
      while (!stack.empty()) {
        Frame& frame = stack.back();
        const tinygltf::Node& node = model_.nodes[frame.node];
        if (frame.next_child < node.children.size()) {
          const std::size_t child = check_index(node.children[frame.next_child++]);
          if (state[child] == State::open) fail("{}: nodes[{}]: the node hierarchy has a cycle", label_, child);
          if (state[child] == State::unvisited) {
            state[child] = State::open;
            stack.push_back({child, 0});
          }
          continue;
        }
        Counts counts{1, 0};
        if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < model_.meshes.size())
          counts.instances = std::min<std::uint64_t>(model_.meshes[static_cast<std::size_t>(node.mesh)].primitives.size(), kSaturated);
        for (int child : node.children) {
          counts.visits = saturating_add(counts.visits, below[static_cast<std::size_t>(child)].visits);
          counts.instances = saturating_add(counts.instances, below[static_cast<std::size_t>(child)].instances);
        }
        below[frame.node] = counts;
        state[frame.node] = State::done;
        stack.pop_back();
      }
      total.visits = saturating_add(total.visits, below[start].visits);
      total.instances = saturating_add(total.instances, below[start].instances);
    }
    if (total.instances > kMaxGltfInstances || total.visits > kMaxGltfInstances)
      fail("{}: the node hierarchy expands to more than {} {} (nodes reached along many paths, e.g. a child "
           "listed twice at many levels); glint refuses scenes above that limit",
           label_, kMaxGltfInstances, total.instances > kMaxGltfInstances ? "instances" : "node visits");
  }

  // Every node reached from the roots, depth first and children in order (each path one instance),
  // with the hierarchy's world transform. check_instance_expansion has bounded the work and ruled out
  // cycles and missing nodes.
  void expand_nodes(const std::vector<int>& roots) {
    struct Pending {
      int node;
      mat4 parent;
    };
    std::vector<Pending> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.push_back({*root, mat4(1.0f)});
    while (!stack.empty()) {
      const Pending pending = stack.back();
      stack.pop_back();
      const int index = pending.node;
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
      const mat4 world = pending.parent * local_transform(node);  // parent * child: the child's frame nests in the parent's
      if (node.camera >= 0 && !first_camera_) first_camera_ = GltfCameraNode{index, world};
      if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
          fail("{}: nodes[{}]: mesh {} does not exist ({} meshes)", label_, index, node.mesh, model_.meshes.size());
        const std::string name = node.name.empty() ? fmt::format("nodes[{}]", index) : node.name;
        const std::size_t primitives = model_.meshes[static_cast<std::size_t>(node.mesh)].primitives.size();
        for (std::size_t p = 0; p < primitives; ++p) {
          const int slot = mesh_slot(static_cast<std::size_t>(node.mesh), p);
          if (slot == kNoSlot) continue;
          scene_.instances.push_back({primitives > 1 ? fmt::format("{}/{}", name, p) : name,
                                      static_cast<std::uint32_t>(slot), world});
        }
      }
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
    }
  }

  // Index of the glint Mesh for a primitive (converted on first use), or kNoSlot when it has no triangles.
  int mesh_slot(std::size_t mesh, std::size_t primitive) {
    std::optional<int>& slot = primitive_slots_[mesh][primitive];
    if (!slot) slot = convert_primitive(mesh, primitive);
    return *slot;
  }

  int convert_primitive(std::size_t mesh_index, std::size_t primitive_index) {
    const tinygltf::Mesh& source = model_.meshes[mesh_index];
    const tinygltf::Primitive& primitive = source.primitives[primitive_index];
    const std::string where = fmt::format("{}: meshes[{}].primitives[{}]", label_, mesh_index, primitive_index);
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      ++skipped_primitives_;
      return kNoSlot;
    }

    Mesh mesh;
    mesh.name = fmt::format("{}/{}", source.name.empty() ? fmt::format("meshes[{}]", mesh_index) : source.name,
                            primitive_index);
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) fail("{}: no POSITION attribute", where);
    const std::vector<float> xyz = read_float_accessor(model_, position->second, 3, where + ".attributes.POSITION");
    const std::size_t vertex_count = xyz.size() / 3;
    for (std::size_t v = 0; v < vertex_count; ++v) {
      mesh.positions.emplace_back(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
      if (!is_finite(mesh.positions.back()))
        fail("{}.attributes.POSITION: vertex {} is not finite ({}, {}, {})", where, v, xyz[3 * v], xyz[3 * v + 1],
             xyz[3 * v + 2]);
    }

    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
      indices = read_index_accessor(model_, primitive.indices, where + ".indices");
      for (std::uint32_t index : indices)
        if (index >= vertex_count) fail("{}: index {} out of range ({} vertices)", where, index, vertex_count);
    } else {
      for (std::size_t v = 0; v < vertex_count; ++v) indices.push_back(static_cast<std::uint32_t>(v));
    }
    mesh.indices = triangle_list(indices, mode, where);

    const auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end()) {
      const std::vector<float> n = read_float_accessor(model_, normal->second, 3, where + ".attributes.NORMAL");
      if (n.size() != xyz.size())
        fail("{}.attributes.NORMAL: {} normals for {} vertices", where, n.size() / 3, vertex_count);
      for (std::size_t v = 0; v < vertex_count; ++v) mesh.normals.emplace_back(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
    }
    const auto uv = primitive.attributes.find("TEXCOORD_0");
    if (uv != primitive.attributes.end()) {
      const std::vector<float> st = read_float_accessor(model_, uv->second, 2, where + ".attributes.TEXCOORD_0");
      if (st.size() / 2 != vertex_count)
        fail("{}.attributes.TEXCOORD_0: {} UVs for {} vertices", where, st.size() / 2, vertex_count);
      // glTF's v runs down from the image's top edge; glint's runs up from the bottom (scene.h).
      for (std::size_t v = 0; v < vertex_count; ++v) mesh.uvs.emplace_back(st[2 * v], 1.0f - st[2 * v + 1]);
    }

    degenerate_triangles_ += remove_degenerate_triangles(mesh);
    if (mesh.indices.empty()) return kNoSlot;
    finish_normals(mesh);
    mesh.material = material_slot(primitive.material, where);
    scene_.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene_.meshes.size() - 1);
  }

  // Indices of a triangle list, strip or fan as a triangle list.
  static std::vector<std::uint32_t> triangle_list(const std::vector<std::uint32_t>& indices, int mode,
                                                  const std::string& where) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (indices.size() % 3 != 0) fail("{}: {} indices is not a whole number of triangles", where, indices.size());
      return indices;
    }
    std::vector<std::uint32_t> list;
    for (std::size_t i = 2; i < indices.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN) list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
      else if (i % 2 == 0) list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
      else list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});  // odd strip triangles flip to stay CCW
    }
    return list;
  }

  // Missing normals are computed; given ones are normalized, and unusable ones (zero, NaN) replaced by
  // computed smooth normals.
  void finish_normals(Mesh& mesh) const {
    if (mesh.normals.empty()) {
      if (options_.flat_normals) compute_flat_normals(mesh);
      else compute_smooth_normals(mesh);
      return;
    }
    Mesh computed = mesh;
    bool computed_ready = false;
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
      const float length = glm::length(mesh.normals[v]);
      if (length > 0.0f && std::isfinite(length)) {
        mesh.normals[v] /= length;
        continue;
      }
      if (!computed_ready) {
        compute_smooth_normals(computed);
        computed_ready = true;
      }
      mesh.normals[v] = computed.normals[v];
    }
  }

  std::uint32_t material_slot(int index, const std::string& where) {
    if (index < 0) {
      // glTF's default material: white, fully rough metal. glint gives it no mirror term: a file
      // without materials is plain geometry, not a mirror (docs/scene-format.md).
      if (default_material_ == kNoSlot) {
        Material material = convert_gltf_material(tinygltf::Material(), 0);
        material.name = "default";
        material.reflectivity = 0.0f;
        scene_.materials.push_back(material);
        default_material_ = static_cast<int>(scene_.materials.size() - 1);
      }
      return static_cast<std::uint32_t>(default_material_);
    }
    if (static_cast<std::size_t>(index) >= model_.materials.size())
      fail("{}: material {} does not exist ({} materials)", where, index, model_.materials.size());
    int& slot = material_slots_[static_cast<std::size_t>(index)];
    if (slot == kNoSlot) {
      const tinygltf::Material& source = model_.materials[static_cast<std::size_t>(index)];
      MetallicRoughnessMean texture_mean;
      if (const int texture = source.pbrMetallicRoughness.metallicRoughnessTexture.index; texture >= 0) {
        const std::string texture_where =
            fmt::format("{}: materials[{}].pbrMetallicRoughness.metallicRoughnessTexture", label_, index);
        if (const tinygltf::Image* image = texture_image(texture, texture_where))
          texture_mean = metallic_roughness_mean(convert_gltf_image(*image, texture_where, texture_where));
      }
      Material material = convert_gltf_material(source, index, texture_mean);
      const int texture = source.pbrMetallicRoughness.baseColorTexture.index;
      if (texture >= 0)
        material.diffuse_texture =
            texture_slot(texture, fmt::format("{}: materials[{}].pbrMetallicRoughness.baseColorTexture", label_, index));
      scene_.materials.push_back(material);
      slot = static_cast<int>(scene_.materials.size() - 1);
    }
    return static_cast<std::uint32_t>(slot);
  }

  // The glint texture for a glTF texture (shared per image), or -1 when its image is unavailable.
  int texture_slot(int texture_index, const std::string& where) {
    const int image_index = texture_image_index(texture_index, where);
    if (image_index < 0) return -1;
    std::optional<int>& slot = image_slots_[static_cast<std::size_t>(image_index)];
    if (!slot) {
      slot = -1;
      if (const tinygltf::Image* image = texture_image(texture_index, where)) {
        const std::string image_where = fmt::format("{}: images[{}]", label_, image_index);
        const bool external = !image->uri.empty() && image->uri.rfind("data:", 0) != 0;
        const std::string name = external ? (path_.parent_path() / image->uri).string() : image_where;
        scene_.textures.push_back(convert_gltf_image(*image, name, image_where));
        slot = static_cast<int>(scene_.textures.size() - 1);
      }
    }
    return *slot;
  }

  // The image index of a glTF texture, or -1 when it has none (e.g. only an extension's image,
  // KHR_texture_basisu: not supported). An index out of range is an error.
  int texture_image_index(int texture_index, const std::string& where) const {
    if (static_cast<std::size_t>(texture_index) >= model_.textures.size())
      fail("{}: texture {} does not exist ({} textures)", where, texture_index, model_.textures.size());
    const int image_index = model_.textures[static_cast<std::size_t>(texture_index)].source;
    if (image_index >= 0 && static_cast<std::size_t>(image_index) >= model_.images.size())
      fail("{}: textures[{}]: image {} does not exist ({} images)", label_, texture_index, image_index, model_.images.size());
    return image_index;
  }

  // The decoded image of a glTF texture, or null when it has none or it could not be loaded: like a
  // missing OBJ texture, not fatal; one warning per image (tinygltf has warned when the file was not
  // found), and the material does without it.
  const tinygltf::Image* texture_image(int texture_index, const std::string& where) {
    const int image_index = texture_image_index(texture_index, where);
    if (image_index < 0) return nullptr;
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(image_index)];
    if (!image.image.empty()) return &image;
    if (unloadable_images_warned_.insert(image_index).second) {
      const auto failure = image_failures_.reasons.find(image_index);
      log_warning("{}: images[{}]: image \"{}\" could not be loaded{}; the material does without it", label_,
                  image_index, untrusted_text(image.uri),
                  failure == image_failures_.reasons.end() ? std::string() : ": " + failure->second);
    }
    return nullptr;
  }

  const tinygltf::Model& model_;
  const GltfImageFailures& image_failures_;
  std::filesystem::path path_;
  std::string label_;
  LoadOptions options_;
  Scene scene_;
  std::vector<std::vector<std::optional<int>>> primitive_slots_;
  std::vector<int> material_slots_;
  std::vector<std::optional<int>> image_slots_;
  std::set<int> unloadable_images_warned_;
  int default_material_ = kNoSlot;
  std::optional<GltfCameraNode> first_camera_;
  std::size_t skipped_primitives_ = 0;
  std::size_t degenerate_triangles_ = 0;
};

}  // namespace

Scene load_gltf(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string label = path.string();
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(path, ignored)) fail("{}: no such file", label);

  check_gltf_document(path, label);

  tinygltf::TinyGLTF reader;
  GltfImageFailures image_failures;
  reader.SetImageLoader(&decode_gltf_image, &image_failures);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = is_binary_gltf(path) ? reader.LoadBinaryFromFile(&model, &error, &warning, label)
                                       : reader.LoadASCIIFromFile(&model, &error, &warning, label);
  std::istringstream warnings(warning);
  for (std::string line; std::getline(warnings, line);)
    if (!line.empty()) log_warning("{}: {}", label, untrusted_text(line));  // tinygltf quotes names from the file
  if (!ok) fail("{}: malformed glTF: {}", label, error.empty() ? "unknown error" : untrusted_text(trimmed(error)));
  return GltfSceneBuilder(model, image_failures, path, options).build();
}

}  // namespace glint
