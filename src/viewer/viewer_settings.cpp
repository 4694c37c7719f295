#include "viewer/viewer_settings.h"

#include "accel/builder.h"
#include "core/error.h"
#include "cuda/device_query.h"
#include "rt/gas_build_preference.h"
#include "rt/ray_tracer.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>

namespace glint::viewer {
namespace {

std::vector<std::string> accel_choices() {
  std::vector<std::string> names;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) names.emplace_back(accel::builder_name(builder));
  for (const rt::OptixBuildPreference preference : rt::kAllOptixBuildPreferences)
    names.emplace_back(rt::optix_accel_name(preference));
  return names;
}

std::vector<ViewerSetting> make_settings() {
  using O = RenderOptions;
  return {
      {"reflections", &O::reflections, {"off", "ssr", "hybrid", "rt"}},
      {"backend", &O::backend, {"cpu", "embree", "gl", "cuda", "optix"}},
      {"accel", &O::accel, accel_choices()},
      {"update", &O::update, {"rebuild", "refit", "auto"}},
      {"deform", &O::deform, {"on", "off"}},
      {"gbuffer", &O::gbuffer, {"raster", "visibility"}},
      {"primary", &O::primary, {"raster", "rt", "compute"}},
      {"shadows", &O::shadows, {"cube", "rt", "hybrid"}},
      {"shadow-map-size", &O::shadow_map_size, {}, 16, 8192},
      {"shadow-cube-draw", &O::shadow_cube_draw, {"per-face", "layered"}},
      {"ssr-max-steps", &O::ssr_max_steps, {}, 1, 4096},
      {"ssr-thickness", &O::ssr_thickness, {}, 0.001, 100.0},
      {"ssr-confidence", &O::ssr_confidence, {}, 0.0, 1.0},
      {"blur-radius", &O::blur_radius, {}, 0, 32},
      {"exposure", &O::exposure, {}, 0.01, 100.0},
      {"tone-map", &O::tone_map, {"aces", "reinhard", "none"}},
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
  std::vector<std::string> backends{"cpu", "embree", "gl"};
  for (const char* gpu_backend : {"cuda", "optix"}) {
    try {
      rt::check_backend_built(gpu_backend);
    } catch (const Error&) {
      continue;
    }
    if (cuda_gpu_present()) backends.emplace_back(gpu_backend);
  }
  return backends;
}

}  // namespace glint::viewer
