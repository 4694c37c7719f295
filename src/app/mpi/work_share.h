#pragma once
// One job's pieces shared over the ranks of an mpirun (docs/scale-out.md): every rank calls
// share_pieces with the same number of pieces (each rank planned the same job from the same flags,
// so a piece is known by its index); rank 0 hands them out (PieceScheduler) from a second thread
// while its main thread runs pieces too, and the other ranks ask it for the next piece each time they
// finish one. Each piece's outcome and its result (JSON: rows, counts) travel with the next question.
//
// A piece that throws glint::Error failed (retried on another rank, see PieceScheduler); with
// `errors_retire_rank`, or when it throws RankFailure or anything else, the rank failed as a whole:
// it is reported, takes no more pieces, and its piece goes to another rank. A test makes rank R fail
// at its first piece with GLINT_TEST_MPI_FAIL_RANK=R.
#include "app/mpi/piece_scheduler.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace glint::mpi {

// Thrown by a piece when the rank as a whole cannot go on (its device failed).
class RankFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct WorkShareOptions {
  bool errors_retire_rank = false;  // render: a failed frame leaves its loop in no state to go on
  int max_attempts = 2;
  // No piece starts after this (bench --time-limit): the pieces in flight finish, the others stay
  // queued in the result, for the next run of the same command.
  std::optional<std::chrono::steady_clock::time_point> hand_out_until;
};

struct RankReport {
  int rank = 0;
  nlohmann::json about;  // what the rank said of itself (host, devices)
  std::size_t pieces_done = 0;
  std::optional<std::string> failure;  // why it retired
};

struct ShareResult {
  std::vector<PieceScheduler::Piece> pieces;  // state and attempts of every piece
  std::vector<nlohmann::json> results;        // per piece, what the run that finished it returned
  std::vector<RankReport> ranks;
  std::size_t failed_pieces() const;
  std::size_t queued_pieces() const;  // left unstarted at the time limit
};

// Runs piece i as run(i) on whichever rank takes it; returns the outcome on rank 0 and nullopt on the
// others (which return once no piece is left for them). `on_remote_piece_done(i)` is called on rank
// 0's second thread when another rank finished piece i (progress).
std::optional<ShareResult> share_pieces(std::size_t pieces, const std::function<nlohmann::json(std::size_t)>& run,
                                        const nlohmann::json& about, const WorkShareOptions& options,
                                        const std::function<void(std::size_t)>& on_remote_piece_done = {});

// The rank GLINT_TEST_MPI_FAIL_RANK names (tests), or nullopt.
std::optional<int> rank_made_to_fail();

}  // namespace glint::mpi
