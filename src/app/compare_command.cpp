#include "app/compare_command.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/exr_image.h"
#include "core/image.h"
#include "metrics/error_heatmap.h"
#include "metrics/image_comparison.h"
#include "metrics/linear_metrics.h"
#include "render/tone_map.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <system_error>
#include <filesystem>

namespace glint {
namespace {

namespace fs = std::filesystem;

// read_png accepts every format stb_image knows (JPEG, BMP, ...); compare promises PNGs, so the
// signature is checked first and anything else is named as "not a PNG file".
ImageRgba8 read_png_file(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error)) fail("cannot read PNG '{}': no such file", path.string());
  if (fs::is_directory(path, error)) fail("cannot read PNG '{}': is a directory", path.string());
  std::ifstream file(path, std::ios::binary);
  if (!file) fail("cannot read PNG '{}': {}", path.string(), std::strerror(errno));
  constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::array<char, 8> head{};
  file.read(head.data(), head.size());
  if (file.gcount() != static_cast<std::streamsize>(head.size()) ||
      std::memcmp(head.data(), kSignature.data(), head.size()) != 0)
    fail("cannot read PNG '{}': not a PNG file", path.string());
  return read_png(path);
}

// An input file: PNG (8-bit, as shown) or EXR (linear; `picture` is its tone-mapped 8-bit image).
struct InputImage {
  std::string path;
  ImageRgba8 picture;
  std::optional<ImageRgbaF> linear;  // EXR only
  std::string tone_map;              // EXR only: the tone map that made `picture`
};

bool is_exr_path(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".exr";
}

// EXR by its magic number or its name (so a broken "x.exr" is reported as an EXR), PNG otherwise.
InputImage read_input(const std::string& path, const std::string& tone_map_flag) {
  InputImage input{path, {}, std::nullopt, {}};
  if (!has_exr_signature(path) && !is_exr_path(path)) {
    input.picture = read_png_file(path);
    return input;
  }
  ExrFile file = read_exr(path);
  metrics::require_finite(file.image, path);
  input.tone_map = tone_map_flag;
  if (input.tone_map.empty()) {
    const auto recorded = file.text.find(std::string(render::kExrToneMapAttribute));
    input.tone_map = recorded == file.text.end() ? "aces" : recorded->second;
    if (!render::kToneMapNames.find(input.tone_map))
      fail("cannot read EXR '{}': its {} attribute '{}' is not a tone map (none, reinhard or aces)", path,
           render::kExrToneMapAttribute, input.tone_map);
  }
  input.picture = render::tone_map_to_rgba8(file.image, render::tone_map_from_name(input.tone_map));
  input.linear = std::move(file.image);
  return input;
}

// JSON has no infinity; PSNR of identical images is written as the string "inf".
nlohmann::json json_number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

nlohmann::json comparison_json(const metrics::ImageComparison& c, const std::string& test, const std::string& reference) {
  const auto& b = c.buckets;
  const auto& e = c.error;
  return {
      {"test", test},
      {"reference", reference},
      {"width", c.width},
      {"height", c.height},
      {"color_buckets_percent",
       {{"r", b.channel_percent[0]}, {"g", b.channel_percent[1]}, {"b", b.channel_percent[2]}, {"mean", b.mean_percent}}},
      {"ssim", {{"luma", c.ssim.luma}, {"r", c.ssim.channel[0]}, {"g", c.ssim.channel[1]}, {"b", c.ssim.channel[2]}}},
      {"rmse", {{"r", e.channel_rmse[0]}, {"g", e.channel_rmse[1]}, {"b", e.channel_rmse[2]}, {"overall", e.rmse}}},
      {"psnr_db",
       {{"r", json_number(e.channel_psnr[0])}, {"g", json_number(e.channel_psnr[1])},
        {"b", json_number(e.channel_psnr[2])}, {"overall", json_number(e.psnr)}}},
  };
}

std::string psnr_text(double db) { return std::isinf(db) ? (db > 0 ? std::string("inf") : std::string("-inf")) : fmt::format("{:.2f}", db); }

nlohmann::json linear_json(const metrics::LinearComparison& l) {
  return {
      {"rmse", {{"r", l.channel_rmse[0]}, {"g", l.channel_rmse[1]}, {"b", l.channel_rmse[2]}, {"overall", l.rmse}}},
      {"peak", l.peak},
      {"psnr_db",
       {{"r", json_number(l.channel_psnr[0])}, {"g", json_number(l.channel_psnr[1])},
        {"b", json_number(l.channel_psnr[2])}, {"overall", json_number(l.psnr)}}},
      {"ssim_luminance", l.ssim_luminance},
      {"luminance_peak", l.luminance_peak},
  };
}

void print_linear_table(const metrics::LinearComparison& l) {
  fmt::print("{:<14}{:>10}{:>10}{:>10}{:>10}\n", "linear", "R", "G", "B", "all");
  fmt::print("{:<14}{:>10.5g}{:>10.5g}{:>10.5g}{:>10.5g}\n", "RMSE", l.channel_rmse[0], l.channel_rmse[1],
             l.channel_rmse[2], l.rmse);
  fmt::print("{:<14}{:>10}{:>10}{:>10}{:>10}  (peak {:.5g})\n", "PSNR dB", psnr_text(l.channel_psnr[0]),
             psnr_text(l.channel_psnr[1]), psnr_text(l.channel_psnr[2]), psnr_text(l.psnr), l.peak);
  fmt::print("{:<14}{:>40.5f}  (luminance, L {:.5g})\n", "SSIM", l.ssim_luminance, l.luminance_peak);
}

void print_table(const metrics::ImageComparison& c, const std::string& test, const std::string& reference) {
  const auto& b = c.buckets;
  const auto& e = c.error;
  fmt::print("test       {} ({}x{})\n", test, c.width, c.height);
  fmt::print("reference  {}\n", reference);
  fmt::print("{:<14}{:>10}{:>10}{:>10}{:>10}\n", "", "R", "G", "B", "all");
  fmt::print("{:<14}{:>10.3f}{:>10.3f}{:>10.3f}{:>10.3f}  (mean)\n", "buckets %", b.channel_percent[0],
             b.channel_percent[1], b.channel_percent[2], b.mean_percent);
  fmt::print("{:<14}{:>10.5f}{:>10.5f}{:>10.5f}{:>10.5f}  (luma)\n", "SSIM", c.ssim.channel[0], c.ssim.channel[1],
             c.ssim.channel[2], c.ssim.luma);
  fmt::print("{:<14}{:>10.3f}{:>10.3f}{:>10.3f}{:>10.3f}\n", "RMSE", e.channel_rmse[0], e.channel_rmse[1],
             e.channel_rmse[2], e.rmse);
  fmt::print("{:<14}{:>10}{:>10}{:>10}{:>10}\n", "PSNR dB", psnr_text(e.channel_psnr[0]), psnr_text(e.channel_psnr[1]),
             psnr_text(e.channel_psnr[2]), psnr_text(e.psnr));
}

// --heatmap-scale is a luma difference: finite, > 0 (it divides) and at most 255 (the largest
// difference of 8-bit lumas). Checked at parse time so that 0, nan or inf are a bad flag (exit 2) in
// one line, rather than CLI11's range text with DBL_MAX written out, or a late error (exit 1).
CLI::Validator heatmap_scale_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
            !(value > 0.0 && value <= 255.0))
          return fmt::format("must be a number > 0 and <= 255 (the luma difference shown as white), not '{}'", text);
        return {};
      },
      "SCALE in (0, 255]");
}

}  // namespace

void add_compare_command(CLI::App& app, CompareOptions& options) {
  CLI::App* compare = app.add_subcommand(
      "compare", "Compare two PNG images, or two linear EXR images (in linear space and tone mapped): colour "
                 "buckets (the paper's measure), SSIM, RMSE, PSNR (see docs/metrics.md)");
  compare->add_option("A", options.first, "First image (PNG or EXR)")->required();
  compare->add_option("B", options.second, "Second image (PNG or EXR, as A)")->required();
  compare->add_option("--reference", options.reference, "Which image is the reference (the other is tested against it)")
      ->check(CLI::IsMember({"A", "B"}, CLI::ignore_case))
      ->capture_default_str();
  compare->add_option("--heatmap", options.heatmap, "Write a PNG of the per-pixel luma error (black, red, yellow, white)");
  compare->add_option("--heatmap-scale", options.heatmap_scale, "Luma difference (0..255) shown as white in the heat map")
      ->check(heatmap_scale_check())
      ->capture_default_str();
  compare->add_option("--json", options.json, "Also write the numbers as JSON to this file (PSNR of identical images: \"inf\")");
  compare->add_option("--tone-map", options.tone_map,
                      "EXRs: the tone map of their 8-bit comparison (default: the one each file records, as "
                      "glint render writes it; aces when none)")
      ->check(CLI::IsMember(render::kToneMapNames.names()));
}

int run_compare_command(const CompareOptions& options) {
  // CLI11 normalises "a" to "A"; the lower-case test keeps this right for callers that bypass it.
  const bool a_is_reference = options.reference == "A" || options.reference == "a";
  const std::string& test_path = a_is_reference ? options.second : options.first;
  const std::string& reference_path = a_is_reference ? options.first : options.second;
  const InputImage test_input = read_input(test_path, options.tone_map);
  const InputImage reference_input = read_input(reference_path, options.tone_map);
  if (test_input.linear.has_value() != reference_input.linear.has_value()) {
    const InputImage& exr = test_input.linear ? test_input : reference_input;
    const InputImage& png = test_input.linear ? reference_input : test_input;
    fail("cannot compare '{}' (linear EXR) with '{}' (8-bit PNG): give two EXRs or two PNGs (an EXR's PNG is "
         "written by another glint render run with --format png)",
         exr.path, png.path);
  }
  const ImageRgba8& test = test_input.picture;
  const ImageRgba8& reference = reference_input.picture;
  std::optional<metrics::LinearComparison> linear;
  if (test_input.linear)
    linear = metrics::compare_linear_images(*test_input.linear, *reference_input.linear, test_path, reference_path);

  const metrics::ImageComparison comparison = metrics::compare_images(test, reference, test_path, reference_path);
  if (!options.json.empty()) {
    nlohmann::json numbers = comparison_json(comparison, test_path, reference_path);
    if (linear) {
      numbers["linear"] = linear_json(*linear);
      numbers["tone_map"] = {{"test", test_input.tone_map}, {"reference", reference_input.tone_map}};
    }
    write_file_atomically(options.json, numbers.dump(2) + "\n");
  }
  if (!options.heatmap.empty()) {
    metrics::HeatmapOptions heatmap_options;
    heatmap_options.full_scale = options.heatmap_scale;
    write_png(options.heatmap, metrics::luma_error_heatmap(test, reference, heatmap_options, test_path, reference_path));
  }
  print_table(comparison, test_path, reference_path);
  if (linear) {
    fmt::print("(tone mapped to 8 bits: test {}, reference {})\n", test_input.tone_map, reference_input.tone_map);
    print_linear_table(*linear);
  }
  return 0;
}

}  // namespace glint
