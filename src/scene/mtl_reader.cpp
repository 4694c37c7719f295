#include "scene/mtl_reader.h"

#include "core/error.h"
#include "core/log.h"
#include "core/untrusted_text.h"
#include "scene/obj_text_parsing.h"
#include "scene/specular_roughness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_set>

namespace glint {
namespace {

using obj_text::parse_float;
using obj_text::take_token;

// Texture options of the MTL spec and how many arguments each takes. -o, -s and -t take 1 to 3
// numbers, so they take as many as follow (up to 3).
struct TextureOption {
  std::string_view name;
  int min_arguments;
  int max_arguments;
};
constexpr std::array<TextureOption, 12> kTextureOptions{{{"-blendu", 1, 1},
                                                         {"-blendv", 1, 1},
                                                         {"-boost", 1, 1},
                                                         {"-mm", 2, 2},
                                                         {"-o", 1, 3},
                                                         {"-s", 1, 3},
                                                         {"-t", 1, 3},
                                                         {"-texres", 1, 1},
                                                         {"-clamp", 1, 1},
                                                         {"-bm", 1, 1},
                                                         {"-imfchan", 1, 1},
                                                         {"-type", 1, 1}}};

bool is_colour_statement(std::string_view keyword) {
  return keyword == "Kd" || keyword == "Ks" || keyword == "Ke" || keyword == "Ka" || keyword == "Tf";
}

bool is_scalar_statement(std::string_view keyword) {
  static const std::unordered_set<std::string_view> scalars{"Ns", "Ni", "d",  "Tr",  "illum", "Pm",    "Pr",  "Km",
                                                            "Ps", "Pc", "Pcr", "aniso", "anisor", "sharpness"};
  return scalars.count(keyword) != 0;
}

// The statements of one material that can make it a mirror, kept until the material is complete
// because they combine (see reflectivity()).
struct ReflectionStatements {
  std::optional<float> metallic;       // Pm
  std::optional<float> mirror;         // Km
  std::optional<vec3> specular;        // Ks
  std::optional<float> illumination;   // illum
  std::optional<float> roughness;      // Pr
  std::optional<float> exponent;       // Ns

  // The roughness of glossy reflections: Pr (clamped to 0..1) when given, else the roughness whose
  // GGX lobe matches the Blinn-Phong exponent Ns (specular_roughness.h), else 0 (a mirror).
  float glossy_roughness() const {
    if (roughness) return std::clamp(*roughness, 0.0f, 1.0f);
    if (exponent) return roughness_from_specular_exponent(*exponent);
    return 0.0f;
  }

  // MTL says "this surface mirrors its surroundings" in several ways; glint has one reflectivity
  // (0..1, the weight of the mirror image). The most explicit statement wins:
  //   Pm m (PBR metallic)                      -> m
  //   Km m (a mirror amount some exporters write; not in the Wavefront spec) -> m
  //   illum 3..7 (the models with ray-traced reflection) -> Ks's largest component, 1 without Ks
  //     (in those models Ks weights the reflected colour)
  //   anything else (illum 0-2, 8-10, or none)  -> 0: Ks is then only the highlight's colour
  // clamped to 0..1.
  float reflectivity() const {
    if (metallic) return std::clamp(*metallic, 0.0f, 1.0f);
    if (mirror) return std::clamp(*mirror, 0.0f, 1.0f);
    const bool ray_traced_reflection = illumination && *illumination >= 3.0f && *illumination <= 7.0f &&
                                       std::floor(*illumination) == *illumination;
    if (!ray_traced_reflection) return 0.0f;
    if (!specular) return 1.0f;
    return std::clamp(std::max({specular->x, specular->y, specular->z}), 0.0f, 1.0f);
  }
};

class MtlTextReader {
public:
  explicit MtlTextReader(std::string_view file_label) : file_(file_label) {}

  void read_line(std::string_view line, std::size_t line_number);
  std::vector<MtlMaterial> finish() {
    for (std::size_t i = 0; i < materials_.size(); ++i) {
      materials_[i].material.reflectivity = reflections_[i].reflectivity();
      materials_[i].material.roughness = reflections_[i].glossy_roughness();
    }
    return std::move(materials_);
  }

private:
  template <typename... Args>
  [[noreturn]] void fail_here(fmt::format_string<Args...> format, Args&&... args) const {
    fail("{}:{}: {}", file_, line_, fmt::format(format, std::forward<Args>(args)...));
  }

  // The material that statements apply to; a statement before any `newmtl` is malformed.
  MtlMaterial& current(std::string_view keyword);
  ReflectionStatements& current_reflection(std::string_view keyword);
  void start_material(std::string_view rest);
  // nullopt for a spectral curve ("Kd spectral file.rfl"), which has no RGB value to use.
  std::optional<vec3> read_colour(std::string_view keyword, std::string_view rest);
  float read_scalar(std::string_view keyword, std::string_view rest);

  std::string_view file_;
  std::size_t line_ = 0;
  std::vector<MtlMaterial> materials_;
  std::vector<ReflectionStatements> reflections_;  // one per material
  std::unordered_set<std::string> names_;
  bool skipping_duplicate_ = false;  // inside a second definition of a name: read, then dropped
  MtlMaterial duplicate_;
  ReflectionStatements duplicate_reflection_;
};

MtlMaterial& MtlTextReader::current(std::string_view keyword) {
  if (skipping_duplicate_) return duplicate_;
  if (materials_.empty()) fail_here("'{}' before any 'newmtl'", keyword);
  return materials_.back();
}

ReflectionStatements& MtlTextReader::current_reflection(std::string_view keyword) {
  (void)current(keyword);  // the same checks
  return skipping_duplicate_ ? duplicate_reflection_ : reflections_.back();
}

void MtlTextReader::start_material(std::string_view rest) {
  // The whole rest of the line: names may hold blanks ("newmtl 01 - Default"), as `usemtl` reads them.
  const std::string_view name = obj_text::trim(rest);
  if (name.empty()) fail_here("'newmtl' needs a material name");
  MtlMaterial material;
  material.material.name = std::string(name);
  material.line = line_;
  skipping_duplicate_ = !names_.emplace(name).second;
  if (skipping_duplicate_) {
    log_warning("{}:{}: material '{}' is defined again; the first definition is used", file_, line_, untrusted_text(name));
    duplicate_ = std::move(material);
    duplicate_reflection_ = {};
    return;
  }
  materials_.push_back(std::move(material));
  reflections_.emplace_back();
}

std::optional<vec3> MtlTextReader::read_colour(std::string_view keyword, std::string_view rest) {
  std::string_view arguments = rest;
  const std::string_view first = take_token(arguments);
  // "Kd xyz x y z" is CIE XYZ; close enough to RGB for a renderer that only reads Kd/Ks/Ke.
  if (first == "spectral") return std::nullopt;
  if (first == "xyz") rest = arguments;
  float values[3] = {0.0f, 0.0f, 0.0f};
  int count = 0;
  for (std::string_view token = take_token(rest); !token.empty(); token = take_token(rest)) {
    const std::optional<float> value = parse_float(token);
    if (!value) fail_here("'{}': '{}' is not a number", keyword, untrusted_text(token));
    if (!std::isfinite(*value)) fail_here("'{}': '{}' is not a finite number", keyword, untrusted_text(token));
    if (count == 3) fail_here("'{}' has more than 3 numbers", keyword);
    values[count++] = *value;
  }
  if (count == 0) fail_here("'{}' needs 3 numbers (r g b)", keyword);
  if (count == 2) fail_here("'{}' has 2 numbers, expected 3 (r g b) or 1 (grey)", keyword);
  return count == 1 ? vec3(values[0]) : vec3(values[0], values[1], values[2]);
}

float MtlTextReader::read_scalar(std::string_view keyword, std::string_view rest) {
  std::string_view token = take_token(rest);
  if (keyword == "d" && token == "-halo") token = take_token(rest);  // "d -halo 0.5"
  if (token.empty()) fail_here("'{}' needs a number", keyword);
  const std::optional<float> value = parse_float(token);
  if (!value) fail_here("'{}': '{}' is not a number", keyword, untrusted_text(token));
  if (!std::isfinite(*value)) fail_here("'{}': '{}' is not a finite number", keyword, untrusted_text(token));
  if (!take_token(rest).empty()) fail_here("'{}' takes one number", keyword);
  return *value;
}

void MtlTextReader::read_line(std::string_view line, std::size_t line_number) {
  line_ = line_number;
  std::string_view rest = line;
  const std::string_view keyword = take_token(rest);
  if (keyword.empty() || keyword.front() == '#') return;
  if (keyword == "newmtl") {
    start_material(rest);
  } else if (is_colour_statement(keyword)) {
    const std::optional<vec3> colour = read_colour(keyword, rest);
    Material& material = current(keyword).material;
    if (!colour) return;  // spectral: the default stays
    if (keyword == "Kd") material.diffuse = *colour;
    if (keyword == "Ks") {
      material.specular = *colour;
      current_reflection(keyword).specular = *colour;
    }
    if (keyword == "Ke") material.emissive = *colour;
  } else if (is_scalar_statement(keyword)) {
    const float value = read_scalar(keyword, rest);
    Material& material = current(keyword).material;
    if (keyword == "Ns") {
      material.specular_exponent = std::max(value, 0.0f);
      current_reflection(keyword).exponent = value;
    }
    if (keyword == "Pm") current_reflection(keyword).metallic = value;
    if (keyword == "Km") current_reflection(keyword).mirror = value;
    if (keyword == "illum") current_reflection(keyword).illumination = value;
    if (keyword == "Pr") current_reflection(keyword).roughness = value;
  } else if (keyword == "map_Kd") {
    const std::string_view name = texture_file_name(rest);
    if (name.empty()) fail_here("'map_Kd' needs a file name");
    MtlMaterial& material = current(keyword);
    material.diffuse_map = std::string(name);
    material.diffuse_map_line = line_;
  }
}

}  // namespace

std::string_view texture_file_name(std::string_view arguments) {
  std::string_view rest = arguments;
  while (true) {
    std::string_view after = rest;
    const std::string_view token = take_token(after);
    const auto option = std::find_if(kTextureOptions.begin(), kTextureOptions.end(),
                                     [&](const TextureOption& candidate) { return candidate.name == token; });
    if (option == kTextureOptions.end()) break;
    // Skip the option's arguments: the required ones, then optional ones while they are numbers.
    for (int i = 0; i < option->max_arguments; ++i) {
      std::string_view next = after;
      const std::string_view argument = take_token(next);
      if (argument.empty() || (i >= option->min_arguments && !parse_float(argument))) break;
      after = next;
    }
    rest = after;
  }
  return obj_text::trim(rest);
}

std::vector<MtlMaterial> read_mtl_text(std::string_view text, std::string_view file_label) {
  MtlTextReader reader(file_label);
  obj_text::LineReader lines(text);
  for (std::string_view line; lines.next(line);) reader.read_line(line, lines.line_number());
  return reader.finish();
}

}  // namespace glint
