#include "app/mpi/piece_scheduler.h"

#include "core/error.h"

#include <algorithm>

namespace glint::mpi {

PieceScheduler::PieceScheduler(std::size_t pieces, int ranks, int max_attempts)
    : pieces_(pieces), retired_(static_cast<std::size_t>(std::max(ranks, 1))), max_attempts_(std::max(max_attempts, 1)) {}

bool PieceScheduler::can_take(int rank, std::size_t index) const {
  const Piece& piece = pieces_[index];
  if (piece.state != State::queued || retired_[static_cast<std::size_t>(rank)]) return false;
  return std::none_of(piece.attempts.begin(), piece.attempts.end(), [&](const Attempt& a) { return a.rank == rank; });
}

bool PieceScheduler::anyone_can_take(std::size_t index) const {
  for (std::size_t rank = 0; rank < retired_.size(); ++rank)
    if (can_take(static_cast<int>(rank), index)) return true;
  return false;
}

PieceScheduler::Next PieceScheduler::next(int rank) {
  if (closed_) return {Answer::stop, 0};
  for (std::size_t index = 0; index < pieces_.size(); ++index) {
    if (!can_take(rank, index)) continue;
    pieces_[index].state = State::running;
    pieces_[index].attempts.push_back({rank, ""});
    return {Answer::run, index};
  }
  if (retired_.at(static_cast<std::size_t>(rank))) return {Answer::stop, 0};
  // A piece in flight elsewhere may fail and come back to a rank that has not tried it.
  const bool in_flight = std::any_of(pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.state == State::running; });
  return {in_flight ? Answer::wait : Answer::stop, 0};
}

void PieceScheduler::finished(int rank, std::size_t index) {
  Piece& piece = pieces_.at(index);
  if (piece.state != State::running || piece.attempts.empty() || piece.attempts.back().rank != rank)
    fail("MPI: rank {} reported piece {}, which it was not running", rank, index);
  piece.state = State::done;
}

void PieceScheduler::failed(int rank, std::size_t index, const std::string& error, bool retire_rank) {
  Piece& piece = pieces_.at(index);
  if (piece.state != State::running || piece.attempts.empty() || piece.attempts.back().rank != rank)
    fail("MPI: rank {} reported piece {}, which it was not running", rank, index);
  piece.attempts.back().error = error.empty() ? "failed" : error;
  if (retire_rank) retired_.at(static_cast<std::size_t>(rank)) = piece.attempts.back().error;
  piece.state = State::queued;
  if (static_cast<int>(piece.attempts.size()) >= max_attempts_ || !anyone_can_take(index)) piece.state = State::failed;
  fail_orphans();
}

void PieceScheduler::retire(int rank, const std::string& reason) {
  retired_.at(static_cast<std::size_t>(rank)) = reason;
  for (std::size_t index = 0; index < pieces_.size(); ++index) {
    Piece& piece = pieces_[index];
    if (piece.state == State::running && piece.attempts.back().rank == rank) {
      piece.attempts.back().error = reason;
      piece.state = State::queued;
    }
  }
  fail_orphans();
}

void PieceScheduler::fail_orphans() {
  for (std::size_t index = 0; index < pieces_.size(); ++index)
    if (pieces_[index].state == State::queued && !anyone_can_take(index)) {
      pieces_[index].state = State::failed;
      if (pieces_[index].attempts.empty()) pieces_[index].attempts.push_back({-1, "no rank was left to run it"});
    }
}

bool PieceScheduler::all_resolved() const {
  return std::all_of(pieces_.begin(), pieces_.end(),
                     [](const Piece& p) { return p.state == State::done || p.state == State::failed; });
}

}  // namespace glint::mpi
