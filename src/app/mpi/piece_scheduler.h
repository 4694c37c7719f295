#pragma once
// Who runs which piece of a job shared over ranks (docs/scale-out.md), without any MPI: rank 0 keeps
// one PieceScheduler and asks it on behalf of every rank (work_share.h carries the questions).
//
// Pieces are handed out in their order (callers put the longest first), one at a time: a rank that
// finishes asks for the next, so fast ranks take more (dynamic balance). A failed piece goes back to
// the queue for a rank that has not tried it, until it has been tried `max_attempts` times or no
// such rank is left; then it is failed with every attempt's error. A rank that failed as a whole
// (retired: its device is gone, or a test made it fail) gets no more pieces. Once closed (a time
// limit passed) it hands out nothing more: the pieces in flight finish, the queued ones stay queued,
// left for the next run of the same command.
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace glint::mpi {

class PieceScheduler {
public:
  PieceScheduler(std::size_t pieces, int ranks, int max_attempts = 2);

  enum class Answer { run, wait, stop };
  struct Next {
    Answer answer = Answer::stop;
    std::size_t piece = 0;  // with Answer::run
  };
  // What `rank` does next: run a piece (now in flight on it), wait (nothing it can take now, but a
  // piece in flight elsewhere may come back), or stop (nothing left for it).
  Next next(int rank);

  void finished(int rank, std::size_t piece);
  // `retire_rank`: the rank failed as a whole and takes no more pieces.
  void failed(int rank, std::size_t piece, const std::string& error, bool retire_rank);
  void retire(int rank, const std::string& reason);
  // Hands out no more pieces (every rank that asks is told to stop); the queued ones stay queued.
  void close() { closed_ = true; }
  bool closed() const { return closed_; }

  enum class State { queued, running, done, failed };
  struct Attempt {
    int rank = 0;
    std::string error;  // empty for the attempt that finished it
  };
  struct Piece {
    State state = State::queued;
    std::vector<Attempt> attempts;
  };
  const Piece& piece(std::size_t index) const { return pieces_.at(index); }
  std::size_t piece_count() const { return pieces_.size(); }
  // Why the rank retired, or nullopt while it takes pieces.
  const std::optional<std::string>& retired(int rank) const { return retired_.at(static_cast<std::size_t>(rank)); }
  bool all_resolved() const;  // every piece done or failed (none queued or in flight)

private:
  bool can_take(int rank, std::size_t piece) const;
  bool anyone_can_take(std::size_t piece) const;
  // Fails the queued pieces that no rank left can take.
  void fail_orphans();

  std::vector<Piece> pieces_;
  std::vector<std::optional<std::string>> retired_;
  int max_attempts_;
  bool closed_ = false;
};

}  // namespace glint::mpi
