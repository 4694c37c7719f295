#pragma once
// RAII owner of an Embree 3 device. Embree reports errors through a callback (and a sticky error
// code), never by return value, so every wrapper call is followed by check(), which turns a pending
// error into a glint::Error carrying Embree's own message. The callback never throws: unwinding
// through Embree's C frames would be undefined behaviour.
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>

namespace glint::rt {

class EmbreeDevice {
public:
  // `config` is Embree's device configuration string (e.g. "verbose=1"); empty for the defaults.
  // Threads: the Debian build of Embree schedules on TBB, so a tbb::global_control limits it too.
  explicit EmbreeDevice(const std::string& config = {});
  ~EmbreeDevice();
  // The device holds a pointer to this object for its callbacks, so it cannot move.
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice handle() const { return device_; }

  // Throws glint::Error "embree: <what>: <Embree's message>" when Embree recorded an error since the
  // last check (rtcGetDeviceError clears it).
  void check(std::string_view what) const;

  // Bytes Embree has allocated and not yet freed on this device (its memory monitor callback): the
  // only way to know how big an Embree BVH is, since Embree does not expose its nodes.
  int64_t allocated_bytes() const { return allocated_bytes_.load(std::memory_order_relaxed); }

private:
  static void on_error(void* self, RTCError code, const char* message);
  static bool on_memory(void* self, ssize_t bytes, bool post);

  RTCDevice device_ = nullptr;
  mutable std::mutex error_mutex_;
  mutable std::string last_error_;
  std::atomic<int64_t> allocated_bytes_{0};
};

// Embree's name of an error code ("RTC_ERROR_INVALID_ARGUMENT", ...).
std::string_view embree_error_name(RTCError code);

}  // namespace glint::rt
