// The bookkeeping of the GPU backends' timed work (cuda/gpu_span_pool.h, cuda/tracer_gpu_times.h)
// with fake spans, so it runs without a GPU: every span is kept until its time is read, however many
// come after (a ring of 64 once lost a frame's update behind the 128 traces of 64 reflection
// samples); reading frees it for reuse; and over many frames of a frame loop's use the pool stays as
// small as the work in flight. The CUDA spans themselves: tests/cuda/cuda_occlusion_test.cpp
// (GpuTimesAreKeptPerTicketUntilRead) and tests/app/render_many_samples_cli_test.cpp, on a GPU.
#include "cuda/gpu_span_pool.h"
#include "cuda/tracer_gpu_times.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace glint::cuda {
namespace {

using testing::error_of;

// A span whose "GPU" finished when `done` is set; recording (record()) is what a CUDA span's event
// records do: it overwrites what a reused span held.
struct FakeSpan {
  double ms = -1.0;
  bool done = false;
  std::optional<double> elapsed_ms(bool wait) const {
    if (!done && !wait) return std::nullopt;
    return ms;  // `wait`: the fake GPU is always finished by then
  }
};

// The time the fake work of `ticket` takes: distinct per ticket, so a read of another span's events shows.
double time_of(std::uint64_t ticket) { return 0.25 + static_cast<double>(ticket); }

template <typename Pool>
std::uint64_t record(Pool& pool, bool done = true) {
  const std::uint64_t ticket = pool.open();
  pool.span(ticket) = FakeSpan{time_of(ticket), done};
  return ticket;
}

TEST(GpuSpanPool, SpansBeyondTheOldRingOfSixtyFourAreReadInOrder) {
  GpuSpanPool<FakeSpan> pool("rt test");
  std::vector<std::uint64_t> tickets;
  for (int i = 0; i < 514; ++i) tickets.push_back(record(pool));
  EXPECT_EQ(pool.held(), 514u);
  for (const std::uint64_t ticket : tickets) EXPECT_EQ(pool.read_ms(ticket, /*wait=*/false), time_of(ticket)) << ticket;
  EXPECT_EQ(pool.held(), 0u);
}

TEST(GpuSpanPool, ReadingFreesTheSpanForTheNextWork) {
  GpuSpanPool<FakeSpan> pool("rt test");
  const std::uint64_t first = record(pool);
  const std::uint64_t second = record(pool);
  EXPECT_EQ(pool.pooled(), 2u);
  EXPECT_EQ(pool.read_ms(first, false), time_of(first));
  EXPECT_FALSE(pool.holds(first));
  EXPECT_TRUE(pool.holds(second));
  EXPECT_NE(error_of([&] { (void)pool.read_ms(first, true); })
                .find("rt test: GPU time of span 0 asked after it was read or let go"),
            std::string::npos);
  const std::uint64_t third = record(pool);  // reuses the first's span: no new one
  EXPECT_EQ(pool.pooled(), 2u);
  EXPECT_EQ(pool.read_ms(third, false), time_of(third));
  EXPECT_EQ(pool.read_ms(second, false), time_of(second));
}

TEST(GpuSpanPool, WorkNotDoneKeepsItsSpanUntilRead) {
  GpuSpanPool<FakeSpan> pool("rt test");
  const std::uint64_t ticket = record(pool, /*done=*/false);
  EXPECT_EQ(pool.read_ms(ticket, /*wait=*/false), std::nullopt);
  EXPECT_TRUE(pool.holds(ticket));
  pool.span(ticket).done = true;
  int looked = 0;
  EXPECT_EQ(pool.read_ms(ticket, false, [&](const FakeSpan& span) { looked += span.done ? 1 : 0; }), time_of(ticket));
  EXPECT_EQ(looked, 1) << "what was kept beside the events is looked at before the span is freed";
  EXPECT_FALSE(pool.holds(ticket));
}

TEST(GpuSpanPool, ReleasedAndUnknownTicketsAreErrors) {
  GpuSpanPool<FakeSpan> pool("GPU deformer");
  const std::uint64_t ticket = record(pool);
  pool.release(ticket);
  EXPECT_EQ(pool.held(), 0u);
  EXPECT_NE(error_of([&] { pool.release(ticket); }).find("after it was read or let go"), std::string::npos);
  EXPECT_NE(error_of([&] { (void)pool.read_ms(7, false); })
                .find("GPU deformer: GPU time of span 7 asked, but 1 spans were started"),
            std::string::npos);
}

// The bug of the 256-sample reference, on the tracer's rules: the update, then hundreds of traces
// (each read as the sample ends, their shadow traces dropped), then the update read frames later.
TEST(TracerGpuTimes, AnUpdateTakenIsReadAfterAFrameOfManySamples) {
  TracerGpuTimes<FakeSpan> times("rt test");
  const std::uint64_t update = record(times);
  times.opened_update(update);
  ASSERT_EQ(times.take_last_update(), update);
  for (int sample = 0; sample < 256; ++sample) {
    const std::uint64_t closest = record(times);
    times.drop(record(times));  // the hits' shadow rays: nobody reads them
    EXPECT_EQ(times.read_ms(closest, /*wait=*/true), time_of(closest));
  }
  EXPECT_EQ(times.read_ms(update, /*wait=*/true), time_of(update));
  EXPECT_EQ(times.last_update_ms(), time_of(update)) << "stats() after the frame loop read it";
  EXPECT_EQ(times.read_ms(update, true), time_of(update)) << "the last update's time is asked again";
  EXPECT_EQ(times.spans().held(), 0u);
}

TEST(TracerGpuTimes, StatsReadTheLastUpdateWithoutTakingItFromItsReader) {
  TracerGpuTimes<FakeSpan> times("rt test");
  const std::uint64_t update = record(times);
  times.opened_update(update);
  ASSERT_EQ(times.take_last_update(), update);
  EXPECT_EQ(times.last_update_ms(), time_of(update));  // stats() first
  const std::uint64_t next = record(times);
  times.opened_update(next);  // the reader has not read `update` yet: kept
  EXPECT_EQ(times.read_ms(update, true), time_of(update));
  EXPECT_EQ(times.last_update_ms(), time_of(next));
  EXPECT_EQ(times.spans().held(), 0u) << "the untaken update was let go once its time was known";
}

TEST(TracerGpuTimes, AnUpdateNobodyTookIsLetGoAtTheNext) {
  TracerGpuTimes<FakeSpan> times("rt test");
  EXPECT_EQ(times.last_update_ms(), 0.0);
  EXPECT_EQ(times.take_last_update(), std::nullopt);
  for (int update = 0; update < 1000; ++update) times.opened_update(record(times));  // glint.Structure.update
  EXPECT_EQ(times.spans().held(), 1u);
  EXPECT_EQ(times.spans().pooled(), 2u);
  EXPECT_EQ(times.last_update_ms(), time_of(999));
  times.forget_update();  // a new build
  EXPECT_EQ(times.last_update_ms(), 0.0);
  EXPECT_EQ(times.spans().held(), 0u);
}

TEST(TracerGpuTimes, DroppingTheLastUpdateKeepsItsTimeForStats) {
  TracerGpuTimes<FakeSpan> times("rt test");
  const std::uint64_t update = record(times);
  times.opened_update(update);
  times.drop(*times.take_last_update());
  EXPECT_EQ(times.last_update_ms(), time_of(update));
  EXPECT_EQ(times.spans().held(), 0u);
}

// A frame loop's use over many frames: three frames in flight, each a structure update whose time
// is read when the frame completes, the reflection trace read then too, shadow and primary-ray traces
// dropped; every eighth frame has 64 reflection samples, each read as it ends. The pool stays the
// size of the work in flight, however many frames run.
TEST(TracerGpuTimes, MemoryStaysBoundedOverManyFramesOfAFrameLoop) {
  TracerGpuTimes<FakeSpan> times("rt test");
  struct InFlight {
    std::uint64_t update, trace;
  };
  std::deque<InFlight> in_flight;
  std::size_t most_pooled_after_warm_up = 0;
  for (int frame = 0; frame < 5000; ++frame) {
    if (in_flight.size() == 3) {
      const InFlight done = in_flight.front();
      in_flight.pop_front();
      EXPECT_EQ(times.read_ms(done.update, false), time_of(done.update));
      EXPECT_EQ(times.read_ms(done.trace, false), time_of(done.trace));
    }
    const std::uint64_t update = record(times);
    times.opened_update(update);
    times.drop(record(times));  // ray-traced shadows (OcclusionBuffers)
    const std::uint64_t trace = record(times);
    times.drop(record(times));  // the reflection hits' shadow rays
    if (frame % 8 == 0)
      for (int sample = 1; sample < 64; ++sample) {
        const std::uint64_t closest = record(times);
        times.drop(record(times));
        EXPECT_EQ(times.read_ms(closest, true), time_of(closest));
      }
    in_flight.push_back({*times.take_last_update(), trace});
    if (frame == 100) most_pooled_after_warm_up = times.spans().pooled();
    if (frame % 1000 == 0) (void)times.last_update_ms();  // stats() now and then
  }
  EXPECT_LE(times.spans().held(), 3u * 2u);  // the frames in flight: an update and a trace each
  EXPECT_EQ(times.spans().pooled(), most_pooled_after_warm_up) << "no growth after the first frames";
  EXPECT_LE(times.spans().pooled(), 16u);
}

}  // namespace
}  // namespace glint::cuda
