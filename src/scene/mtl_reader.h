#pragma once
// Reads a Wavefront MTL file's text into glint Materials, rejecting malformed statements with
// "<file.mtl>:<line>: <what is wrong>" (tinyobjloader would silently read "Kd a b c" as black).
//
// The mapping from MTL to glint::Material (everything else in the file is ignored):
//   Kd r g b  -> diffuse              Ks r g b -> specular        Ke r g b -> emissive
//   Ns n      -> specular_exponent    map_Kd   -> diffuse texture (file name, options skipped)
//   Pm, Km, illum 3-7 with Ks -> reflectivity (ReflectionStatements::reflectivity in mtl_reader.cpp,
//                                docs/scene-format.md "OBJ materials": Pm, else Km, else Ks under illum 3-7)
//   Pr r      -> roughness (clamped to 0..1); without Pr, roughness_from_specular_exponent(Ns)
//                (specular_roughness.h); 0 (a mirror) with neither
// A colour with one number is grey (MTL spec: g and b default to r). Statements the renderer has no
// use for (Ka, Tf, Ni, d, Tr, ...) are still checked so that a broken file is caught early.
#include "scene/scene.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct MtlMaterial {
  Material material;               // diffuse_texture stays -1: textures are the loader's business
  std::string diffuse_map;         // map_Kd's file name as written (relative to the MTL's folder), or empty
  std::size_t line = 0;            // line of the `newmtl` statement
  std::size_t diffuse_map_line = 0;
};

// All materials of the file in order. A name defined twice keeps its first definition (as
// tinyobjloader does) with a warning. `file_label` is the name used in messages.
std::vector<MtlMaterial> read_mtl_text(std::string_view text, std::string_view file_label);

// The file name of a texture statement's arguments ("-s 1 1 1 -clamp on tex/a b.png" -> "tex/a b.png"):
// the options of the MTL spec are skipped, the rest of the line is the name (it may contain spaces).
// Empty when there is none.
std::string_view texture_file_name(std::string_view arguments);

}  // namespace glint
