// glTF files crafted to crash glint, exhaust its memory or make it load something else than the file
// says: each is refused (or its image skipped) with a message naming the file and the place in it.
#include "core/error.h"
#include "core/log.h"
#include "scene/gltf_loader.h"
#include "scene/crafted_images.h"
#include "scene/gltf_test_builder.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace glint {
namespace {

using nlohmann::json;
using testing::error_of;
using testing::GltfBuilder;
using testing::TempFolder;

void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
}

// One triangle whose POSITION accessor has its "count" replaced.
std::string triangle_with_position_count(std::uint64_t count) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  gltf.json["accessors"][positions]["count"] = count;
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}});
  return gltf.gltf_text();
}

TEST(GltfHostileInput, AccessorCountsThatWrapTheSizeArithmeticAreRefusedBeforeAllocating) {
  TempFolder folder;
  // (2^64 + 2) / 3 elements of 12 bytes wrap the byte count around to a few bytes (a heap overflow
  // write before); 2^62 made std::vector throw "cannot create std::vector larger than max_size()".
  const std::uint64_t wrapping = 6148914691236517206ull;
  for (const std::uint64_t count : {wrapping, std::uint64_t{1} << 62, std::numeric_limits<std::uint64_t>::max()}) {
    SCOPED_TRACE(count);
    const std::string message =
        error_of([&] { load_gltf(folder.write("huge.gltf", triangle_with_position_count(count))); });
    expect_contains(message, {"huge.gltf: meshes[0].primitives[0].attributes.POSITION (accessors[0])",
                              "count " + std::to_string(count), "bufferViews[0] has 36 bytes"});
  }
}

TEST(GltfHostileInput, AccessorWithoutBufferViewHasABoundedCount) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  const int normals = gltf.add_vec3(testing::unit_triangle());
  gltf.json["accessors"][normals].erase("bufferView");  // all zeros: allowed, but not 2^62 of them
  gltf.json["accessors"][normals]["count"] = std::uint64_t{1} << 62;
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}});
  TempFolder folder;
  expect_contains(error_of([&] { load_gltf(folder.write("zeros.gltf", gltf.gltf_text())); }),
                  {"zeros.gltf: meshes[0].primitives[0].attributes.NORMAL (accessors[1])", "without a bufferView",
                   "limit"});
}

TEST(GltfHostileInput, NegativeByteOffsetsAreErrors) {
  TempFolder folder;
  for (const char* array : {"accessors", "bufferViews"}) {
    SCOPED_TRACE(array);
    GltfBuilder gltf;
    gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
    gltf.json[array][0]["byteOffset"] = -12;  // tinygltf read it as 0, silently
    const std::string expected = std::string(array) + "[0].byteOffset: -12 must be a non-negative integer";
    expect_contains(error_of([&] { load_gltf(folder.write("negative.gltf", gltf.gltf_text())); }),
                    {"negative.gltf: " + expected});
    expect_contains(error_of([&] { load_gltf(folder.write("negative.glb", gltf.glb())); }),
                    {"negative.glb: " + expected});
  }
}

TEST(GltfHostileInput, RequiredExtensionsGlintDoesNotImplementAreErrors) {
  GltfBuilder gltf;
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  TempFolder folder;
  gltf.json["extensionsRequired"] = {"KHR_mesh_quantization"};  // only widens accessor types: read anyway
  gltf.json["extensionsUsed"] = {"KHR_mesh_quantization"};
  EXPECT_EQ(load_gltf(folder.write("quantized.gltf", gltf.gltf_text())).triangle_count(), 1u);

  gltf.json["extensionsRequired"] = {"KHR_mesh_quantization", "KHR_draco_mesh_compression"};
  gltf.json["extensionsUsed"] = gltf.json["extensionsRequired"];
  expect_contains(error_of([&] { load_gltf(folder.write("draco.gltf", gltf.gltf_text())); }),
                  {"draco.gltf: extensionsRequired[1]", "\"KHR_draco_mesh_compression\"", "does not implement"});
  expect_contains(error_of([&] { load_gltf(folder.write("draco.glb", gltf.glb())); }),
                  {"draco.glb: extensionsRequired[1]", "KHR_draco_mesh_compression"});
}

// Node 0 holds the mesh; each of `levels` nodes above lists the one below it `copies` times.
GltfBuilder repeated_children(int levels, int copies) {
  GltfBuilder gltf;
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  for (int level = 1; level <= levels; ++level)
    gltf.json["nodes"].push_back({{"children", std::vector<int>(static_cast<std::size_t>(copies), level - 1)}});
  gltf.json["scenes"] = json::array({{{"nodes", {levels}}}});
  gltf.json["scene"] = 0;
  return gltf;
}

TEST(GltfHostileInput, NodeGraphsThatExpandToTooManyInstancesAreRefusedBeforeExpanding) {
  TempFolder folder;
  // A child listed twice is two instances: a small DAG is fine.
  EXPECT_EQ(load_gltf(folder.write("small.gltf", repeated_children(3, 2).gltf_text())).instances.size(), 8u);
  // 41 levels: 2^41 instances from 1.3 KB (it never finished before). 20 levels: 2^20 > 10^6.
  for (const int levels : {41, 20, 64, 200}) {
    SCOPED_TRACE(levels);
    const std::string message =
        error_of([&] { load_gltf(folder.write("bomb.gltf", repeated_children(levels, 2).gltf_text())); });
    expect_contains(message, {"bomb.gltf: ", "more than 1000000 instances"});
  }
  // Paths that end in no mesh make no instance but still take time to walk: 60 levels of 2 over a
  // node without a mesh (and one instance elsewhere) are refused for their 2^61 node visits.
  GltfBuilder empty_paths = repeated_children(60, 2);
  empty_paths.json["nodes"][0].erase("mesh");
  empty_paths.json["nodes"].push_back({{"mesh", 0}});
  empty_paths.json["scenes"][0]["nodes"] = {60, 61};
  expect_contains(error_of([&] { load_gltf(folder.write("paths.gltf", empty_paths.gltf_text())); }),
                  {"paths.gltf: ", "more than 1000000 node visits"});
}

TEST(GltfHostileInput, DeepNodeChainsAndCyclesBelowTheRootDoNotOverflowTheStack) {
  TempFolder folder;
  // A chain of 100,000 nodes: walked recursively, this overflowed the call stack.
  GltfBuilder chain = repeated_children(100'000, 1);
  EXPECT_EQ(load_gltf(folder.write("chain.gltf", chain.gltf_text())).instances.size(), 1u);
  // A cycle that is reachable only through a node listed twice at each level.
  GltfBuilder cycle = repeated_children(30, 2);
  cycle.json["nodes"][0]["children"] = {15};
  expect_contains(error_of([&] { load_gltf(folder.write("cycle.gltf", cycle.gltf_text())); }),
                  {"cycle.gltf: nodes[", "cycle"});
}

TEST(GltfHostileInput, ImagesAboveTheTextureLimitAreSkippedFromTheirHeaderWithAWarning) {
  GltfBuilder gltf;
  const int image = gltf.add_png_image(testing::jpeg_declaring(20000, 20000));  // stores any bytes in the buffer
  gltf.json["images"][image]["mimeType"] = "image/jpeg";
  gltf.json["textures"].push_back({{"source", 0}});
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}, {"material", 0}});
  TempFolder folder;
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("big.glb", gltf.glb()));
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_EQ(scene.materials[0].diffuse_texture, -1);
  EXPECT_EQ(log.count_warnings("big.glb: images[0]"), 1);
  EXPECT_EQ(log.count_warnings("JPEG header declares 20000 x 20000 texels, more than glint's limit"), 1);
}

TEST(GltfHostileInput, AnImageWhoseBufferViewRunsPastItsBufferIsAnError) {
  // tinygltf passed the range to the image decoder unchecked: a heap over-read of up to 4 GB.
  GltfBuilder gltf;
  const int image = gltf.add_png_image(testing::encode_png(1, 1, {255, 0, 0, 255}));
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  const int view = gltf.json["images"][image]["bufferView"];
  gltf.json["bufferViews"][view]["byteLength"] = 1'000'000;
  TempFolder folder;
  for (const char* name : {"over.gltf", "over.glb"}) {
    const std::filesystem::path file =
        std::string(name) == "over.glb" ? folder.write(name, gltf.glb()) : folder.write(name, gltf.gltf_text());
    expect_contains(error_of([&] { load_gltf(file); }),
                    {std::string(name) + ": images[0]: bufferViews[0] (byteOffset 0, byteLength 1000000) runs past "
                                         "the end of buffers[0]"});
  }
}

}  // namespace
}  // namespace glint
