// Who runs which piece of a job shared over MPI ranks (app/mpi/piece_scheduler.h): in order, one at
// a time, a failed piece retried on a rank that has not tried it, a retired rank's piece handed on,
// and nobody left waiting for ever.
#include "app/mpi/piece_scheduler.h"

#include <gtest/gtest.h>

namespace glint::mpi {
namespace {

using Answer = PieceScheduler::Answer;
using State = PieceScheduler::State;

TEST(PieceScheduler, HandsOutPiecesInOrderAsRanksAsk) {
  PieceScheduler scheduler(3, 2);
  EXPECT_EQ(scheduler.next(0).piece, 0u);
  EXPECT_EQ(scheduler.next(1).piece, 1u);
  scheduler.finished(1, 1);
  // The rank that finished first takes the next piece (dynamic balance).
  const PieceScheduler::Next next = scheduler.next(1);
  EXPECT_EQ(next.answer, Answer::run);
  EXPECT_EQ(next.piece, 2u);
  // Nothing queued, but piece 0 and 2 are in flight: rank 1 may yet get one back.
  scheduler.finished(1, 2);
  EXPECT_EQ(scheduler.next(1).answer, Answer::wait);
  scheduler.finished(0, 0);
  EXPECT_EQ(scheduler.next(1).answer, Answer::stop);
  EXPECT_EQ(scheduler.next(0).answer, Answer::stop);
  EXPECT_TRUE(scheduler.all_resolved());
}

TEST(PieceScheduler, RetriesAFailedPieceOnAnotherRank) {
  PieceScheduler scheduler(1, 2);
  ASSERT_EQ(scheduler.next(0).answer, Answer::run);
  EXPECT_EQ(scheduler.next(1).answer, Answer::wait);
  scheduler.failed(0, 0, "backend error", false);
  // Not on the rank that failed it, which is told to stop once nothing is in flight.
  EXPECT_EQ(scheduler.next(0).answer, Answer::stop);
  const PieceScheduler::Next retry = scheduler.next(1);
  ASSERT_EQ(retry.answer, Answer::run);
  scheduler.finished(1, 0);
  EXPECT_EQ(scheduler.piece(0).state, State::done);
  ASSERT_EQ(scheduler.piece(0).attempts.size(), 2u);
  EXPECT_EQ(scheduler.piece(0).attempts[0].error, "backend error");
  EXPECT_EQ(scheduler.piece(0).attempts[1].rank, 1);
  EXPECT_FALSE(scheduler.retired(0).has_value());  // a failed piece does not retire the rank
}

TEST(PieceScheduler, FailsAPieceAfterMaxAttempts) {
  PieceScheduler scheduler(1, 3, 2);
  (void)scheduler.next(0);
  scheduler.failed(0, 0, "first", false);
  (void)scheduler.next(1);
  scheduler.failed(1, 0, "second", false);
  EXPECT_EQ(scheduler.piece(0).state, State::failed);
  EXPECT_EQ(scheduler.next(2).answer, Answer::stop);
  EXPECT_TRUE(scheduler.all_resolved());
}

TEST(PieceScheduler, ARetiredRankGetsNothingAndItsPieceGoesOn) {
  PieceScheduler scheduler(2, 2);
  ASSERT_EQ(scheduler.next(1).piece, 0u);
  scheduler.failed(1, 0, "device lost", true);
  EXPECT_EQ(scheduler.retired(1), std::optional<std::string>("device lost"));
  EXPECT_EQ(scheduler.next(1).answer, Answer::stop);
  EXPECT_EQ(scheduler.next(0).piece, 0u);
  scheduler.finished(0, 0);
  EXPECT_EQ(scheduler.next(0).piece, 1u);
  scheduler.finished(0, 1);
  EXPECT_TRUE(scheduler.all_resolved());
}

TEST(PieceScheduler, PiecesNoRankCanTakeFailInsteadOfWaiting) {
  PieceScheduler scheduler(2, 2);
  (void)scheduler.next(0);
  (void)scheduler.next(1);
  scheduler.retire(1, "gone");
  scheduler.failed(0, 0, "broken", true);
  // Nobody is left: both pieces are failed, with why.
  EXPECT_TRUE(scheduler.all_resolved());
  EXPECT_EQ(scheduler.piece(1).state, State::failed);
  EXPECT_EQ(scheduler.piece(1).attempts.back().error, "gone");
  EXPECT_EQ(scheduler.next(0).answer, Answer::stop);
}

TEST(PieceScheduler, OnceClosedHandsOutNothingAndLeavesTheQueuedPiecesQueued) {
  PieceScheduler scheduler(4, 2);
  ASSERT_EQ(scheduler.next(0).piece, 0u);
  ASSERT_EQ(scheduler.next(1).piece, 1u);
  scheduler.close();  // a time limit passed
  EXPECT_EQ(scheduler.next(0).answer, Answer::stop);
  // The pieces in flight still finish (or fail) as before.
  scheduler.finished(0, 0);
  scheduler.failed(1, 1, "backend error", false);
  EXPECT_EQ(scheduler.next(1).answer, Answer::stop);
  EXPECT_EQ(scheduler.piece(0).state, State::done);
  // Left for the next run: not failed, not run.
  EXPECT_EQ(scheduler.piece(1).state, State::queued);
  EXPECT_EQ(scheduler.piece(2).state, State::queued);
  EXPECT_TRUE(scheduler.piece(2).attempts.empty());
  EXPECT_FALSE(scheduler.all_resolved());
}

TEST(PieceScheduler, RejectsAReportOfAPieceTheRankIsNotRunning) {
  PieceScheduler scheduler(1, 2);
  (void)scheduler.next(0);
  EXPECT_ANY_THROW(scheduler.finished(1, 0));
}

}  // namespace
}  // namespace glint::mpi
