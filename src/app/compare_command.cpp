#include "app/compare_command.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image.h"
#include "metrics/error_heatmap.h"
#include "metrics/image_comparison.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
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

std::string psnr_text(double db) { return std::isinf(db) ? std::string("inf") : fmt::format("{:.2f}", db); }

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
      "compare", "Compare two PNG images: colour buckets (the paper's measure), SSIM, RMSE, PSNR (see docs/metrics.md)");
  compare->add_option("A", options.first, "First PNG image")->required();
  compare->add_option("B", options.second, "Second PNG image")->required();
  compare->add_option("--reference", options.reference, "Which image is the reference (the other is tested against it)")
      ->check(CLI::IsMember({"A", "B"}, CLI::ignore_case))
      ->capture_default_str();
  compare->add_option("--heatmap", options.heatmap, "Write a PNG of the per-pixel luma error (black, red, yellow, white)");
  compare->add_option("--heatmap-scale", options.heatmap_scale, "Luma difference (0..255) shown as white in the heat map")
      ->check(heatmap_scale_check())
      ->capture_default_str();
  compare->add_option("--json", options.json, "Also write the numbers as JSON to this file (PSNR of identical images: \"inf\")");
}

int run_compare_command(const CompareOptions& options) {
  // CLI11 normalises "a" to "A"; the lower-case test keeps this right for callers that bypass it.
  const bool a_is_reference = options.reference == "A" || options.reference == "a";
  const std::string& test_path = a_is_reference ? options.second : options.first;
  const std::string& reference_path = a_is_reference ? options.first : options.second;
  const ImageRgba8 test = read_png_file(test_path);
  const ImageRgba8 reference = read_png_file(reference_path);

  const metrics::ImageComparison comparison = metrics::compare_images(test, reference, test_path, reference_path);
  if (!options.json.empty())
    write_file_atomically(options.json, comparison_json(comparison, test_path, reference_path).dump(2) + "\n");
  if (!options.heatmap.empty()) {
    metrics::HeatmapOptions heatmap_options;
    heatmap_options.full_scale = options.heatmap_scale;
    write_png(options.heatmap, metrics::luma_error_heatmap(test, reference, heatmap_options, test_path, reference_path));
  }
  print_table(comparison, test_path, reference_path);
  return 0;
}

}  // namespace glint
