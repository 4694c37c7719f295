#include "core/progress_bar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace glint {
namespace {

using namespace std::chrono_literals;

// A clock that moves only when the test says so.
class FakeClock {
public:
  std::chrono::steady_clock::time_point now() const { return *now_; }
  void advance(std::chrono::duration<double> step) {
    *now_ += std::chrono::duration_cast<std::chrono::steady_clock::duration>(step);
  }
  ProgressClock function() const {
    return [now = now_] { return *now; };
  }

private:
  std::shared_ptr<std::chrono::steady_clock::time_point> now_ =
      std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::time_point{} + 1000s);
};

ProgressOutput fake_output(ProgressStyle style, std::ostream& stream, const FakeClock& clock) {
  ProgressOutput output;
  output.style = style;
  output.stream = &stream;
  output.clock = clock.function();
  return output;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

TEST(ProgressBar, FormatsDurations) {
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(7.4), "0:07");
  EXPECT_EQ(format_duration(7.6), "0:08");
  EXPECT_EQ(format_duration(754.0), "12:34");
  EXPECT_EQ(format_duration(3723.0), "1:02:03");
  EXPECT_EQ(format_duration(-5.0), "0:00");
}

TEST(ProgressBar, RateAndEtaComeFromTheMeanRate) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("render", 100, fake_output(ProgressStyle::plain, out, clock));
  clock.advance(10s);
  bar.tick(25);
  const ProgressSnapshot s = bar.snapshot();
  EXPECT_EQ(s.done, 25u);
  EXPECT_EQ(s.total, 100u);
  EXPECT_DOUBLE_EQ(s.elapsed_seconds, 10.0);
  ASSERT_TRUE(s.items_per_second.has_value());
  EXPECT_DOUBLE_EQ(*s.items_per_second, 2.5);
  ASSERT_TRUE(s.eta_seconds.has_value());
  EXPECT_DOUBLE_EQ(*s.eta_seconds, 30.0);  // 75 items left at 2.5 items/s
  // The line printed at the 10 s mark says the same.
  EXPECT_EQ(out.str(), "render: 25/100 (25%), 2.50 items/s, ETA 0:30, elapsed 0:10\n");
}

TEST(ProgressBar, RateAndEtaAreUnknownBeforeAnythingIsDone) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("bench", 10, fake_output(ProgressStyle::plain, out, clock));
  clock.advance(3s);
  const ProgressSnapshot s = bar.snapshot();
  EXPECT_FALSE(s.items_per_second.has_value());
  EXPECT_FALSE(s.eta_seconds.has_value());
  bar.tick(0);  // no progress yet, but a plain line is not due anyway
  EXPECT_EQ(out.str(), "");
}

TEST(ProgressBar, PlainPrintsOnlyAtTheInterval) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("render", 1000, fake_output(ProgressStyle::plain, out, clock));
  EXPECT_EQ(out.str(), "");  // nothing at creation in plain mode
  // One item every 0.5 s for 35 s: lines are due at 10, 20 and 30 s.
  for (int i = 0; i < 70; ++i) {
    clock.advance(500ms);
    bar.tick();
  }
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 3u) << out.str();
  EXPECT_EQ(lines[0], "render: 20/1000 (2%), 2.00 items/s, ETA 8:10, elapsed 0:10");
  EXPECT_EQ(lines[1], "render: 40/1000 (4%), 2.00 items/s, ETA 8:00, elapsed 0:20");
  EXPECT_EQ(lines[2], "render: 60/1000 (6%), 2.00 items/s, ETA 7:50, elapsed 0:30");
  EXPECT_EQ(count_of(out.str(), "\r"), 0u);
}

TEST(ProgressBar, PlainIntervalIsConfigurable) {
  FakeClock clock;
  std::ostringstream out;
  ProgressOutput output = fake_output(ProgressStyle::plain, out, clock);
  output.plain_interval = 2s;
  ProgressBar bar("x", 10, output);
  clock.advance(1999ms);
  bar.tick();
  EXPECT_EQ(out.str(), "");
  clock.advance(1ms);
  bar.tick();
  EXPECT_EQ(lines_of(out.str()).size(), 1u);
}

TEST(ProgressBar, FinishPrintsOnceWithTotalsAndMeanRate) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("render", 8, fake_output(ProgressStyle::plain, out, clock));
  for (int i = 0; i < 8; ++i) {
    clock.advance(500ms);
    bar.tick();
  }
  bar.finish();
  bar.finish();
  bar.tick();
  EXPECT_EQ(out.str(), "render: 8/8 done in 0:04, 2.00 items/s mean\n");
}

TEST(ProgressBar, TerminalRedrawsOneLineAtMostTenTimesASecond) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("render", 200, fake_output(ProgressStyle::terminal, out, clock));
  // Drawn at once, before the first item.
  EXPECT_EQ(out.str(), "\rrender [........................] 0/200 (0%), -- items/s, ETA --, elapsed 0:00");
  // 200 items, 10 ms apart: 2 s of work allow about 20 redraws, not 200.
  for (int i = 0; i < 200; ++i) {
    clock.advance(10ms);
    bar.tick();
  }
  const std::size_t redraws = count_of(out.str(), "\r") - 1;
  EXPECT_GE(redraws, 19u);
  EXPECT_LE(redraws, 21u);
  EXPECT_EQ(count_of(out.str(), "\n"), 0u);  // one line, redrawn in place
  bar.finish();
  const std::string text = out.str();
  EXPECT_EQ(count_of(text, "\n"), 1u);
  const std::string last = text.substr(text.rfind('\r'));
  EXPECT_EQ(last.rfind("\rrender: 200/200 done in 0:02, 100 items/s mean", 0), 0u) << last;
}

TEST(ProgressBar, TerminalLineShowsTheBarAndBlanksLeftoversOfALongerLine) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("r", 4, fake_output(ProgressStyle::terminal, out, clock));
  clock.advance(1s);
  bar.tick(2);
  std::string text = out.str();
  const std::string drawn = text.substr(text.rfind('\r') + 1);
  EXPECT_EQ(drawn, "r [############............] 2/4 (50%), 2.00 items/s, ETA 0:01, elapsed 0:01");
  clock.advance(1s);
  bar.tick(2);
  bar.finish();
  text = out.str();
  // The final line is shorter than the bar line under it, so spaces cover the rest of that line.
  const std::string final_line = "r: 4/4 done in 0:02, 2.00 items/s mean";
  const std::string bar_line = "r [########################] 4/4 (100%), 2.00 items/s, ETA 0:00, elapsed 0:02";
  ASSERT_LT(final_line.size(), bar_line.size());
  EXPECT_EQ(text.substr(text.size() - (2 * bar_line.size() + 3)),
            "\r" + bar_line + "\r" + final_line + std::string(bar_line.size() - final_line.size(), ' ') + "\n")
      << text;
}

TEST(ProgressBar, FinishInTerminalModeEndsTheLine) {
  FakeClock clock;
  std::ostringstream out;
  {
    ProgressBar bar("render", 3, fake_output(ProgressStyle::terminal, out, clock));
    clock.advance(3s);
    bar.tick(3);
    bar.finish();
  }
  const std::string text = out.str();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(count_of(text, "\n"), 1u);  // the destructor adds nothing after finish
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_EQ(last.rfind("render: 3/3 done in 0:03, 1.00 items/s mean", 0), 0u) << last;
}

TEST(ProgressBar, UnfinishedTerminalBarEndsItsLineWhenDestroyed) {
  FakeClock clock;
  std::ostringstream out;
  {
    ProgressBar bar("render", 3, fake_output(ProgressStyle::terminal, out, clock));
    clock.advance(1s);
    bar.tick();
  }
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_EQ(count_of(out.str(), "\n"), 1u);
}

TEST(ProgressBar, TotalZeroDoesNotDivideByZero) {
  FakeClock clock;
  std::ostringstream out;
  ProgressOutput output = fake_output(ProgressStyle::terminal, out, clock);
  ProgressBar bar("empty", 0, output);
  EXPECT_NE(out.str().find("[########################] 0/0 (100%), -- items/s, ETA 0:00"), std::string::npos)
      << out.str();
  bar.finish();  // no time elapsed and nothing done: the rate is unknown, not NaN or inf
  EXPECT_NE(out.str().find("empty: 0/0 done in 0:00, -- items/s mean"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("nan"), std::string::npos);
  EXPECT_EQ(out.str().find("inf"), std::string::npos);
}

TEST(ProgressBar, MoreItemsThanTheTotalClampTheBar) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("over", 2, fake_output(ProgressStyle::plain, out, clock));
  clock.advance(10s);
  bar.tick(5);
  EXPECT_EQ(out.str(), "over: 5/2 (100%), 0.500 items/s, ETA 0:00, elapsed 0:10\n");
}

TEST(ProgressBar, TicksFromManyThreadsAreAllCounted) {
  FakeClock clock;
  std::ostringstream out;
  ProgressBar bar("threads", 4000, fake_output(ProgressStyle::plain, out, clock));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&bar] {
      for (int i = 0; i < 1000; ++i) bar.tick();
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(bar.snapshot().done, 4000u);
}

}  // namespace
}  // namespace glint
