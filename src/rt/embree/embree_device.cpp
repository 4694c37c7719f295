#include "rt/embree/embree_device.h"

#include "core/error.h"

namespace glint::rt {

std::string_view embree_error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN: return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT: return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION: return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY: return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU: return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED: return "RTC_ERROR_CANCELLED";
  }
  return "RTC_ERROR_(unknown code)";
}

EmbreeDevice::EmbreeDevice(const std::string& config) {
  device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  // rtcNewDevice reports its own failure only through the null device's error code.
  if (device_ == nullptr)
    fail("embree: cannot create a device (config \"{}\"): {}", config, embree_error_name(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, &EmbreeDevice::on_error, this);
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeDevice::on_memory, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

void EmbreeDevice::on_error(void* self, RTCError code, const char* message) {
  auto* device = static_cast<EmbreeDevice*>(self);
  std::lock_guard lock(device->error_mutex_);
  // Keep the first message: later ones are usually consequences of it.
  if (device->last_error_.empty()) {
    device->last_error_ += embree_error_name(code);
    if (message != nullptr && *message != '\0') {
      device->last_error_ += ": ";
      device->last_error_ += message;
    }
  }
}

bool EmbreeDevice::on_memory(void* self, ssize_t bytes, bool /*post*/) {
  // bytes > 0 before an allocation, < 0 after a free; returning true lets Embree go ahead.
  static_cast<EmbreeDevice*>(self)->allocated_bytes_.fetch_add(static_cast<int64_t>(bytes), std::memory_order_relaxed);
  return true;
}

void EmbreeDevice::check(std::string_view what) const {
  const RTCError code = rtcGetDeviceError(device_);
  std::string message;
  {
    std::lock_guard lock(error_mutex_);
    message.swap(last_error_);
  }
  if (code == RTC_ERROR_NONE && message.empty()) return;
  if (message.empty()) message = std::string(embree_error_name(code));
  fail("embree: {}: {}", what, message);
}

}  // namespace glint::rt
