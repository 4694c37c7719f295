#include "rt/ray_tracer.h"

#include "core/error.h"

namespace glint::rt {

RayTracer::~RayTracer() = default;
DeviceTracing::~DeviceTracing() = default;
GlTracing::~GlTracing() = default;

HitAndShadowTickets DeviceTracing::trace_closest_and_hit_shadows_device(const accel::Ray*, accel::Hit*,
                                                                        const uint32_t*, uint32_t,
                                                                        const HitShadowRays&) {
  fail("this GPU backend traces the reflection hits' shadow rays only after a GL pass wrote them");
}

}  // namespace glint::rt
