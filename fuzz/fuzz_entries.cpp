#include "fuzz_entries.h"

#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "scene/scene_json_loader.h"
#include "scene/texture_io.h"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

namespace glint::fuzz {
namespace {

// Failing to write a scratch file is a broken harness, not an answer of the loader: it must not look
// like a glint::Error.
void write_file(const std::filesystem::path& path, std::string_view bytes) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file || std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
    throw std::runtime_error("fuzz harness: cannot write " + path.string());
}

std::string_view as_text(FuzzInput input) {
  return {reinterpret_cast<const char*>(input.data()), input.size()};
}

void remove_scratch_folder() {
  std::error_code ignored;
  std::filesystem::remove_all(scratch_folder(), ignored);
}

// The mesh files a fuzzed scene file can place: a one-triangle OBJ with a material library and a
// one-triangle glTF whose buffer (3 float positions, 3 unsigned short indices) is embedded.
constexpr std::string_view kSceneObj = "mtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr std::string_view kSceneMtl = "newmtl red\nKd 0.8 0.1 0.1\n";
constexpr std::string_view kSceneGltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}]})";

void write_scene_meshes_once() {
  static const bool written = [] {
    write_file(scratch_folder() / "m.obj", kSceneObj);
    write_file(scratch_folder() / "m.mtl", kSceneMtl);
    write_file(scratch_folder() / "m.gltf", kSceneGltf);
    return true;
  }();
  (void)written;
}

constexpr std::array kTargets{
    FuzzTarget{"obj_mtl", &load_obj_and_mtl},
    FuzzTarget{"gltf", &load_gltf_file},
    FuzzTarget{"scene_json", &load_scene_json_file},
    FuzzTarget{"texture", &decode_texture_file},
};

}  // namespace

const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    std::error_code error;
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base = std::filesystem::is_directory(shm, error) ? shm : std::filesystem::temp_directory_path();
    std::filesystem::path path = base / ("glint-fuzz-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path, error);  // left by an earlier process of the same id that crashed
    std::filesystem::create_directories(path);
    return path;
  }();
  static const bool cleanup_registered = std::atexit(remove_scratch_folder) == 0;
  (void)cleanup_registered;
  return folder;
}

void load_obj_and_mtl(FuzzInput input) {
  const std::string_view text = as_text(input);
  const std::size_t split = text.find(kObjMtlSeparator);
  const std::filesystem::path obj = scratch_folder() / "f.obj";
  const std::filesystem::path mtl = scratch_folder() / "f.mtl";
  write_file(obj, text.substr(0, split));
  if (split == std::string_view::npos) {
    std::error_code ignored;
    std::filesystem::remove(mtl, ignored);  // an `mtllib f.mtl` then names a missing file
  } else {
    write_file(mtl, text.substr(split + kObjMtlSeparator.size()));
  }
  load_obj(obj);
}

void load_gltf_file(FuzzInput input) {
  const std::filesystem::path path = scratch_folder() / "f.gltf";
  write_file(path, as_text(input));
  load_gltf(path);
}

void load_scene_json_file(FuzzInput input) {
  write_scene_meshes_once();
  const std::filesystem::path path = scratch_folder() / "f.scene.json";
  write_file(path, as_text(input));
  LoadOptions options;
  options.assets_dir = scratch_folder();  // never the shared assets: a fuzzed scene places only m.*
  load_scene_json(path, options);
}

void decode_texture_file(FuzzInput input) {
  const std::filesystem::path path = scratch_folder() / "t.img";
  write_file(path, as_text(input));
  const Texture texture = load_texture_or_placeholder(path, "fuzz");
  const auto texels = static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height);
  if (texture.width <= 0 || texture.height <= 0 || texture.rgba.size() != texels * 4)
    throw std::logic_error("decoded texture is " + std::to_string(texture.width) + " x " +
                           std::to_string(texture.height) + " with " + std::to_string(texture.rgba.size()) + " bytes");
}

std::span<const FuzzTarget> fuzz_targets() { return kTargets; }

const FuzzTarget* find_fuzz_target(std::string_view name) {
  for (const FuzzTarget& target : kTargets)
    if (target.name == name) return &target;
  return nullptr;
}

}  // namespace glint::fuzz
