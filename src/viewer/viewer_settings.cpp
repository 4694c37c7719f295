#include "viewer/viewer_settings.h"

#include "accel/builders/builder.h"
#include "backends/registry.h"
#include "core/error.h"
#include "cuda/device_query.h"
#include "render/raster_settings.h"
#include "render/reflection_mode.h"
#include "render/resolve_settings.h"
#include "render/shadow_method.h"
#include "rt/ray_tracer.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>

namespace glint::viewer {
namespace {

std::vector<std::string> accel_choices() {
  std::vector<std::string> names = accel::kBvhBuilderNames.names();
  for (const backends::Backend& backend : backends::all_backends())
    names.insert(names.end(), backend.structures.begin(), backend.structures.end());
  return names;
}

std::vector<ViewerSetting> make_settings() {
  using O = RenderOptions;
  return {
      {"reflections", &O::reflections, render::kReflectionModeNames.names()},
      {"backend", &O::backend, backends::backend_names()},
      {"accel", &O::accel, accel_choices()},
      {"update", &O::update, rt::kUpdatePolicyNames.names()},
      {"deform", &O::deform, {"on", "off"}},
      {"gbuffer", &O::gbuffer, render::kGBufferMethodNames.names()},
      {"primary", &O::primary, render::kPrimaryVisibilityNames.names()},
      {"shadows", &O::shadows, render::kShadowMethodNames.names()},
      {"shadow-map-size", &O::shadow_map_size, {}, 16, 8192},
      {"shadow-cube-draw", &O::shadow_cube_draw, render::kShadowCubeDrawNames.names()},
      {"ssr-max-steps", &O::ssr_max_steps, {}, 1, 4096},
      // A fraction of the pixel's view depth, (0, 1] (docs/ssr.md); the default 0.01 is 1 %.
      {"ssr-thickness", &O::ssr_thickness, {}, 0.0001, 1.0, "%.4f", "ssr-thickness (x depth)"},
      {"ssr-confidence", &O::ssr_confidence, {}, 0.0, 1.0},
      {"blur-radius", &O::blur_radius, {}, 0, 32},
      {"exposure", &O::exposure, {}, 0.01, 100.0},
      {"tone-map", &O::tone_map, render::kToneMapNames.names()},
  };
}

template <typename Number>
Number parse_number(std::string_view name, std::string_view text, const ViewerSetting& setting) {
  Number value{};
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || stop != text.data() + text.size())
    fail("{}: \"{}\" is not a{} number", name, text, std::is_integral_v<Number> ? "n integer" : "");
  // Compared in the field's own type, so that a float range's ends (0.01) are inside it.
  if (!std::isfinite(static_cast<double>(value)) || value < static_cast<Number>(setting.min) ||
      value > static_cast<Number>(setting.max))
    fail("{}: {} is outside {} to {}", name, text, setting.min, setting.max);
  return value;
}

}  // namespace

const std::vector<ViewerSetting>& viewer_settings() {
  static const std::vector<ViewerSetting> settings = make_settings();
  return settings;
}

const ViewerSetting* find_viewer_setting(std::string_view name) {
  for (const ViewerSetting& setting : viewer_settings())
    if (setting.name == name) return &setting;
  return nullptr;
}

void set_viewer_setting(RenderOptions& options, std::string_view name, std::string_view value) {
  const ViewerSetting* setting = find_viewer_setting(name);
  if (setting == nullptr) {
    std::vector<std::string_view> names;
    for (const ViewerSetting& known : viewer_settings()) names.push_back(known.name);
    fail("unknown setting \"{}\"; settings: {}", name, fmt::join(names, ", "));
  }
  if (const auto* text = std::get_if<std::string RenderOptions::*>(&setting->field)) {
    bool known = false;
    for (const std::string& choice : setting->choices) known = known || choice == value;
    if (!known) fail("{}: \"{}\" is not one of {}", name, value, fmt::join(setting->choices, ", "));
    options.*(*text) = std::string(value);
  } else if (const auto* integer = std::get_if<int RenderOptions::*>(&setting->field)) {
    options.*(*integer) = parse_number<int>(name, value, *setting);
  } else {
    options.*std::get<float RenderOptions::*>(setting->field) = parse_number<float>(name, value, *setting);
  }
}

std::string viewer_setting_text(const RenderOptions& options, const ViewerSetting& setting) {
  return std::visit([&](auto field) { return fmt::format("{}", options.*field); }, setting.field);
}

bool same_viewer_settings(const RenderOptions& a, const RenderOptions& b) {
  if (a.width != b.width || a.height != b.height || a.scene != b.scene || a.flat_normals != b.flat_normals ||
      a.deform_on != b.deform_on)
    return false;
  for (const ViewerSetting& setting : viewer_settings())
    if (!std::visit([&](auto field) { return a.*field == b.*field; }, setting.field)) return false;
  return true;
}

std::vector<std::string> available_backends() {
  std::vector<std::string> backends;
  for (const backends::Backend& backend : backends::all_backends())
    if (backend.built() && (backend.device != backends::Device::cuda || cuda_gpu_present()))
      backends.push_back(backend.name);
  return backends;
}

}  // namespace glint::viewer
