// The MPI calls of glint (built with MPI; mpi_world_off.cpp is the twin without).
#include "app/mpi/mpi_world.h"

#include "app/mpi/mpi_launch.h"
#include "core/error.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <thread>

namespace glint::mpi {
namespace {

std::atomic<bool> g_command_failed = false;

void finalize_at_exit() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  // The error is printed by now (cli.cpp); the other ranks may be waiting for this one.
  if (g_command_failed && world().size > 1) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Finalize();
}

Rank start() {
  Rank rank;
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) == 0) rank.host = name;
  const std::optional<LaunchedTasks> launched = launched_tasks();
  if (!launched) return rank;  // a plain `glint ...`: no MPI at all
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
    fail("MPI: MPI_Init_thread failed ({})", launched->variable);
  std::atexit(finalize_at_exit);
  if (provided < MPI_THREAD_SERIALIZED)
    fail("MPI: the library gives thread level {}, glint needs MPI_THREAD_SERIALIZED ({})", provided,
         MPI_THREAD_SERIALIZED);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &rank.size);
  if (rank.size < launched->count)
    fail("MPI: the launcher started {} tasks ({}) but MPI sees {} rank(s) in its world: each would run the whole "
         "job; with srun pass --mpi=pmix (or pmi2), as docs/scale-out.md shows",
         launched->count, launched->variable, rank.size);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank.rank, MPI_INFO_NULL, &local);
  MPI_Comm_rank(local, &rank.local_rank);
  MPI_Comm_size(local, &rank.local_size);
  MPI_Comm_free(&local);
  int length = 0;
  char processor[MPI_MAX_PROCESSOR_NAME] = {};
  if (MPI_Get_processor_name(processor, &length) == MPI_SUCCESS && length > 0) rank.host.assign(processor, length);
  return rank;
}

}  // namespace

bool built_with_mpi() { return true; }

const Rank& world() {
  static const Rank rank = start();
  return rank;
}

void send_text(int to, int tag, const std::string& text) {
  if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    fail("MPI: a message of {} bytes to rank {} is too long", text.size(), to);
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::optional<Message> try_receive_text(int from, int tag) {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, tag, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  Message message;
  message.source = status.MPI_SOURCE;
  message.text.resize(static_cast<std::size_t>(length));
  MPI_Recv(message.text.data(), length, MPI_CHAR, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return message;
}

Message receive_text(int from, int tag) {
  // MPI_Recv would spin on a core that the ranks still working may need (ranks can share a host).
  auto pause = std::chrono::microseconds(50);
  while (true) {
    if (std::optional<Message> message = try_receive_text(from, tag)) return std::move(*message);
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
}

void barrier() {
  if (world().size <= 1) return;
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  auto pause = std::chrono::microseconds(50);
  while (true) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
}

void mark_command_failed() { g_command_failed = true; }

void abort_all(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::_Exit(exit_code);
}

}  // namespace glint::mpi
