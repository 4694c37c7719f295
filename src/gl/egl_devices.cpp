#include "gl/egl_devices.h"

#include "core/error.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>

namespace glint {

std::vector<int> egl_device_try_order(const std::vector<EglDeviceDescription>& devices) {
  std::vector<int> order;
  for (const auto& device : devices)
    if (device.is_nvidia()) order.push_back(device.index);
  for (const auto& device : devices)
    if (!device.is_nvidia()) order.push_back(device.index);
  return order;
}

std::string describe_egl_devices(const std::vector<EglDeviceDescription>& devices) {
  if (devices.empty()) return "no EGL devices";
  std::vector<std::string> parts;
  for (const auto& device : devices) {
    std::string part = fmt::format("device {}: {}", device.index,
                                   device.extensions.empty() ? "(no device extensions)" : device.extensions);
    if (!device.drm_node.empty()) part += fmt::format(" ({})", device.drm_node);
    parts.push_back(std::move(part));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

int parse_egl_device_override(std::string_view text, const std::vector<EglDeviceDescription>& devices) {
  int index = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  const bool is_number = error == std::errc() && end == text.data() + text.size();
  if (!is_number || index < 0 || index >= static_cast<int>(devices.size()))
    fail("GLINT_EGL_DEVICE={}: not an EGL device index; there {} {} EGL device{} ({})", text,
         devices.size() == 1 ? "is" : "are", devices.size(), devices.size() == 1 ? "" : "s",
         describe_egl_devices(devices));
  return index;
}

std::optional<std::string> egl_device_override_from_env() {
  const char* value = std::getenv("GLINT_EGL_DEVICE");
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::string(value);
}

}  // namespace glint
