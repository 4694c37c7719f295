// How `mpirun glint bench` cuts the planned cells into pieces (app/mpi/bench_share.h): long
// frame-times cells into near-equal frame ranges, quality cells whole, the longest first.
#include "app/mpi/bench_share.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace glint::mpi {
namespace {

bench::Cell cell(const std::string& id, bench::CellKind kind) {
  bench::Cell c;
  c.id = id;
  c.kind = kind;
  return c;
}

TEST(BenchPieces, SplitsLongFrameTimesCellsIntoNearEqualRanges) {
  const bench::Cell long_cell = cell("fig5-cpu-sah", bench::CellKind::frame_times);
  const bench::Cell short_cell = cell("fig7-cpu-sah-refit", bench::CellKind::frame_times);
  const bench::Cell quality = cell("table1-static", bench::CellKind::quality);
  const bench::Cell skipped = cell("fig8-cpu-sah", bench::CellKind::frame_times);
  const std::vector<int> ten = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, three = {0, 1, 2}, four = {1800, 2100, 2300, 4400};
  const std::vector<BenchCellPlan> plans = {
      {&short_cell, &three, true}, {&long_cell, &ten, true}, {&quality, &four, true}, {&skipped, &ten, false}};
  bench::CellRunSettings settings;
  settings.warmup_frames = 1;
  const std::vector<BenchPiece> pieces = bench_pieces(plans, 4, settings);
  // 10 frames in ranges of at most 4: 3 ranges (3, 3, 4); 3 frames whole; quality whole (12 ticks).
  ASSERT_EQ(pieces.size(), 5u);
  EXPECT_EQ(pieces[0].cell, 2u);  // the quality cell: 3 modes x 4 frames, the longest
  EXPECT_TRUE(pieces[0].whole);
  std::size_t covered = 0;
  for (const BenchPiece& piece : pieces) {
    EXPECT_NE(piece.cell, 3u);  // not to run
    if (piece.cell != 1) continue;
    EXPECT_FALSE(piece.whole);
    EXPECT_GE(piece.count, 3u);
    EXPECT_LE(piece.count, 4u);
    covered += piece.count;
  }
  EXPECT_EQ(covered, 10u);
  for (std::size_t i = 1; i < pieces.size(); ++i) EXPECT_GE(pieces[i - 1].ticks, pieces[i].ticks);
  // Without a piece length nothing is split.
  EXPECT_EQ(bench_pieces(plans, 0, settings).size(), 3u);
}

TEST(BenchPieces, AutomaticRangesAreLongAndOnlyWithSeveralRanks) {
  unsetenv("GLINT_MPI_PIECE_FRAMES");
  EXPECT_EQ(piece_frames_for(147000, 1), 0u);      // one process: never split
  EXPECT_EQ(piece_frames_for(147000, 8), 4594u);   // the paper's 30 cells x 4900 frames: ~4 pieces per rank
  EXPECT_EQ(piece_frames_for(40, 3), 100u);        // never under 100 frames (each range pays a warm-up)
  setenv("GLINT_MPI_PIECE_FRAMES", "2", 1);
  EXPECT_EQ(piece_frames_for(40, 3), 2u);
  setenv("GLINT_MPI_PIECE_FRAMES", "0", 1);
  EXPECT_ANY_THROW(piece_frames_for(40, 3));
  unsetenv("GLINT_MPI_PIECE_FRAMES");
}

TEST(BenchPieces, RangesWriteUnderCellsParts) {
  EXPECT_EQ(part_id(cell("fig5-cpu-sah", bench::CellKind::frame_times), 0, 1225), "parts/fig5-cpu-sah.frames-00000-01225");
}

TEST(BenchPieces, OneProcessRunsHaveNoRanksSection) {
  EXPECT_EQ(distribution_markdown({{"cells", nlohmann::json::array()}}), "");
}

}  // namespace
}  // namespace glint::mpi
