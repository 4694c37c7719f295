#pragma once
// `glint info <scene>`: what a scene contains (meshes, counts, deformables, bounds, materials,
// textures, light, paths), as text or JSON.
#include <CLI/CLI.hpp>

#include <string>

namespace glint {

struct InfoOptions {
  std::string scene = "atrium";
  bool json = false;
  bool flat_normals = false;
};

void add_info_command(CLI::App& app, InfoOptions& options);
// --flat-normals (LoadOptions::flat_normals), the same flag for `info` and `render`.
void add_flat_normals_flag(CLI::App& command, bool& flat_normals);
int run_info_command(const InfoOptions& options);

}  // namespace glint
