#pragma once
// The fuzz targets' entry functions, one definition each, shared by the libFuzzer programs
// (fuzz/libfuzzer_main.cpp, preset `fuzz`) and the corpus replay test (tests/fuzz/).
//
// Each writes its input to files in a scratch folder of this process and runs glint's real loader on
// them, as a user's file would be read. A glint::Error is a correct answer to a bad input and is
// thrown on to the caller; anything else (another exception, a broken invariant of the result, a
// sanitizer report, a crash) is a bug. docs/reliability.md ("Fuzzing") says how to run them.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace glint::fuzz {

using FuzzInput = std::span<const std::uint8_t>;
using FuzzEntry = void (*)(FuzzInput input);

// The OBJ+MTL input is the OBJ text, this line, then the MTL text (no line: OBJ only). The OBJ is
// written as f.obj and the MTL as f.mtl beside it, so `mtllib f.mtl` finds it.
inline constexpr std::string_view kObjMtlSeparator = "\n=mtl=\n";

void load_obj_and_mtl(FuzzInput input);
// A .gltf or .glb (the loader tells them apart by the magic bytes), written as f.gltf.
void load_gltf_file(FuzzInput input);
// A *.scene.json written as f.scene.json; its assets folder is the scratch folder, which holds a
// small m.obj (with m.mtl) and m.gltf for the scene to place.
void load_scene_json_file(FuzzInput input);
// Any image file through the texture loader (stb_image: PNG, JPEG, ...): a decoded texture must be
// width x height RGBA8, an unreadable one the checker placeholder.
void decode_texture_file(FuzzInput input);

struct FuzzTarget {
  std::string_view name;  // the folder name under fuzz/corpus/, fuzz/regressions/ and fuzz/dict/
  FuzzEntry entry;
};

// obj_mtl, gltf, scene_json, texture.
std::span<const FuzzTarget> fuzz_targets();
// The target of that name, or nullptr.
const FuzzTarget* find_fuzz_target(std::string_view name);

// This process's scratch folder (/dev/shm/glint-fuzz-<pid>, or under the system temp folder when
// /dev/shm is missing), created on first use and removed at exit.
const std::filesystem::path& scratch_folder();

}  // namespace glint::fuzz
