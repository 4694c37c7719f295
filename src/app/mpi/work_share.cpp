#include "app/mpi/work_share.h"

#include "app/mpi/mpi_world.h"
#include "core/error.h"
#include "core/interruption.h"
#include "core/log.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string_view>
#include <thread>

namespace glint::mpi {
namespace {

constexpr int kAskTag = 2401;   // rank -> 0: {"finished": [...], "retire": reason|null, "about": {...}}
constexpr int kGiveTag = 2402;  // 0 -> rank: {"piece": i} or {"stop": true}

// One piece's outcome on the rank that ran it.
struct Outcome {
  std::size_t piece = 0;
  bool ok = false;
  bool retire = false;
  bool interrupted = false;  // stopped by Ctrl-C or SIGTERM: the piece is left for --resume, not failed
  std::string error;
  nlohmann::json result;
};

nlohmann::json to_json(const Outcome& outcome) {
  return {{"piece", outcome.piece}, {"ok", outcome.ok}, {"retire", outcome.retire},
          {"interrupted", outcome.interrupted}, {"error", outcome.error}, {"result", outcome.result}};
}

Outcome outcome_from_json(const nlohmann::json& json) {
  return {json.at("piece").get<std::size_t>(), json.at("ok").get<bool>(), json.at("retire").get<bool>(),
          json.at("interrupted").get<bool>(), json.at("error").get<std::string>(), json.at("result")};
}

// Runs one piece and says how it went; a rank made to fail by the test variable fails here.
Outcome run_piece(std::size_t piece, const std::function<nlohmann::json(std::size_t)>& run,
                  const WorkShareOptions& options, bool& first_piece) {
  Outcome outcome;
  outcome.piece = piece;
  try {
    if (first_piece && rank_made_to_fail() == world().rank)
      throw RankFailure(fmt::format("rank {} made to fail by GLINT_TEST_MPI_FAIL_RANK (a test)", world().rank));
    first_piece = false;
    outcome.result = run(piece);
    outcome.ok = true;
  } catch (const RankFailure& failure) {
    outcome.error = failure.what();
    outcome.retire = true;
  } catch (const Interrupted& interrupted) {  // Ctrl-C or SIGTERM: this rank starts nothing more
    outcome.error = interrupted.what();
    outcome.retire = true;
    outcome.interrupted = true;
  } catch (const Error& error) {
    outcome.error = error.what();
    outcome.retire = options.errors_retire_rank;
  } catch (const std::exception& error) {
    outcome.error = error.what();
    outcome.retire = true;
  }
  first_piece = false;
  return outcome;
}

// Rank 0's book of the job: the scheduler and what came back, shared by its two threads.
struct Book {
  std::mutex mutex;
  std::condition_variable changed;
  PieceScheduler scheduler;
  ShareResult result;

  Book(std::size_t pieces, int ranks, int attempts) : scheduler(pieces, ranks, attempts) {
    result.results.resize(pieces);
    result.ranks.resize(static_cast<std::size_t>(ranks));
    for (int r = 0; r < ranks; ++r) result.ranks[static_cast<std::size_t>(r)].rank = r;
  }

  // Under the lock: what `rank` does next, the scheduler closed first if the time limit passed.
  PieceScheduler::Next next(int rank, const WorkShareOptions& options) {
    if (options.hand_out_until && std::chrono::steady_clock::now() >= *options.hand_out_until) scheduler.close();
    return scheduler.next(rank);
  }

  // Under the lock.
  void record(int rank, const Outcome& outcome) {
    RankReport& report = result.ranks.at(static_cast<std::size_t>(rank));
    if (outcome.ok) {
      scheduler.finished(rank, outcome.piece);
      result.results.at(outcome.piece) = outcome.result;
      ++report.pieces_done;
      return;
    }
    scheduler.failed(rank, outcome.piece, outcome.error, outcome.retire);
    if (outcome.interrupted) {
      report.failure = outcome.error;
      log_info("rank {} ({}) stopped: {}", rank, report.about.value("host", std::string("?")), outcome.error);
    } else if (outcome.retire) {
      report.failure = outcome.error;
      log_warning("rank {} ({}) failed: {}; it takes no more pieces", rank,
                  report.about.value("host", std::string("?")), outcome.error);
    } else {
      log_warning("rank {}: piece {} failed: {}", rank, outcome.piece, outcome.error);
    }
  }
};

// Rank 0's second thread: answers the other ranks until each was told to stop or retired.
void serve_other_ranks(Book& book, const WorkShareOptions& options,
                       const std::function<void(std::size_t)>& on_remote_piece_done) {
  const int size = world().size;
  std::set<int> waiting;  // ranks that asked and got no answer yet
  int active = size - 1;
  auto pause = std::chrono::microseconds(100);
  while (active > 0) {
    bool busy = false;
    if (std::optional<Message> message = try_receive_text(-1, kAskTag)) {
      busy = true;
      const nlohmann::json ask = nlohmann::json::parse(message->text);
      std::vector<std::size_t> done;
      {
        std::lock_guard lock(book.mutex);
        RankReport& report = book.result.ranks.at(static_cast<std::size_t>(message->source));
        if (ask.contains("about")) report.about = ask["about"];
        for (const nlohmann::json& finished : ask.at("finished")) {
          const Outcome outcome = outcome_from_json(finished);
          book.record(message->source, outcome);
          if (outcome.ok) done.push_back(outcome.piece);
        }
        if (ask.at("retire").is_string()) {
          if (!report.failure) {
            report.failure = ask["retire"].get<std::string>();
            book.scheduler.retire(message->source, *report.failure);
          }
          --active;  // a retired rank asks no more
        } else {
          waiting.insert(message->source);
        }
      }
      book.changed.notify_all();
      if (on_remote_piece_done)
        for (const std::size_t piece : done) on_remote_piece_done(piece);
    }
    for (auto it = waiting.begin(); it != waiting.end();) {
      PieceScheduler::Next next;
      {
        std::lock_guard lock(book.mutex);
        next = book.next(*it, options);
      }
      if (next.answer == PieceScheduler::Answer::wait) {
        ++it;
        continue;
      }
      busy = true;
      if (next.answer == PieceScheduler::Answer::run) {
        send_text(*it, kGiveTag, nlohmann::json{{"piece", next.piece}}.dump());
      } else {
        send_text(*it, kGiveTag, nlohmann::json{{"stop", true}}.dump());
        --active;
      }
      it = waiting.erase(it);
    }
    if (busy) {
      pause = std::chrono::microseconds(100);
    } else {
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::microseconds(5000));
    }
  }
}

ShareResult lead(std::size_t pieces, const std::function<nlohmann::json(std::size_t)>& run, const nlohmann::json& about,
                 const WorkShareOptions& options, const std::function<void(std::size_t)>& on_remote_piece_done) {
  Book book(pieces, world().size, options.max_attempts);
  book.result.ranks[0].about = about;
  std::atomic<bool> serving_failed = false;
  std::string serving_error;
  std::thread server([&] {
    try {
      serve_other_ranks(book, options, on_remote_piece_done);
    } catch (const std::exception& error) {
      serving_error = error.what();
      serving_failed = true;
    }
  });
  // Rank 0 works too: its GPU is one of the job's.
  bool first_piece = true;
  while (!serving_failed) {
    PieceScheduler::Next next;
    {
      std::unique_lock lock(book.mutex);
      next = book.next(0, options);
      if (next.answer == PieceScheduler::Answer::wait) {
        book.changed.wait_for(lock, std::chrono::milliseconds(50));
        continue;
      }
    }
    if (next.answer == PieceScheduler::Answer::stop) break;
    const Outcome outcome = run_piece(next.piece, run, options, first_piece);
    std::lock_guard lock(book.mutex);
    book.record(0, outcome);
  }
  server.join();
  if (serving_failed) {
    fmt::print(stderr, "glint: rank 0 lost track of the other ranks: {}\n", serving_error);
    abort_all(1);
  }
  for (std::size_t i = 0; i < pieces; ++i) book.result.pieces.push_back(book.scheduler.piece(i));
  return std::move(book.result);
}

void follow(const std::function<nlohmann::json(std::size_t)>& run, const nlohmann::json& about,
            const WorkShareOptions& options) {
  bool first_piece = true;
  nlohmann::json finished = nlohmann::json::array();
  while (true) {
    send_text(0, kAskTag, nlohmann::json{{"finished", finished}, {"retire", nullptr}, {"about", about}}.dump());
    finished = nlohmann::json::array();
    const nlohmann::json answer = nlohmann::json::parse(receive_text(0, kGiveTag).text);
    if (answer.contains("stop")) return;
    const Outcome outcome = run_piece(answer.at("piece").get<std::size_t>(), run, options, first_piece);
    if (outcome.retire) {
      send_text(0, kAskTag,
                nlohmann::json{{"finished", nlohmann::json::array({to_json(outcome)})}, {"retire", outcome.error},
                               {"about", about}}
                    .dump());
      return;
    }
    finished.push_back(to_json(outcome));
  }
}

}  // namespace

std::size_t ShareResult::failed_pieces() const {
  return static_cast<std::size_t>(std::count_if(pieces.begin(), pieces.end(), [](const PieceScheduler::Piece& p) {
    return p.state == PieceScheduler::State::failed;
  }));
}

std::size_t ShareResult::queued_pieces() const {
  return static_cast<std::size_t>(std::count_if(pieces.begin(), pieces.end(), [](const PieceScheduler::Piece& p) {
    return p.state == PieceScheduler::State::queued;
  }));
}

std::optional<int> rank_made_to_fail() {
  const char* value = std::getenv("GLINT_TEST_MPI_FAIL_RANK");
  if (value == nullptr || *value == '\0') return std::nullopt;
  const std::string_view text(value);
  int rank = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), rank);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return rank;
}

std::optional<ShareResult> share_pieces(std::size_t pieces, const std::function<nlohmann::json(std::size_t)>& run,
                                        const nlohmann::json& about, const WorkShareOptions& options,
                                        const std::function<void(std::size_t)>& on_remote_piece_done) {
  if (!world().lead()) {
    try {
      follow(run, about, options);
    } catch (const std::exception& error) {
      // The protocol itself broke (a message that does not parse): nobody can be sure to finish.
      fmt::print(stderr, "glint: rank {} lost track of rank 0: {}\n", world().rank, error.what());
      abort_all(1);
    }
    return std::nullopt;
  }
  return lead(pieces, run, about, options, on_remote_piece_done);
}

}  // namespace glint::mpi
