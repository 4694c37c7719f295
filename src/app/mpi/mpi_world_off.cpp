// A build without MPI: one rank. Started by an MPI launcher as one of several copies, each copy would
// run the whole job into the same folder, so that is refused with one line.
#include "app/mpi/mpi_world.h"

#include "app/mpi/mpi_launch.h"
#include "core/error.h"

#include <unistd.h>

#include <cstdlib>

namespace glint::mpi {
namespace {

Rank start() {
  if (const std::optional<LaunchedTasks> launched = launched_tasks(); launched && launched->count > 1)
    fail("an MPI launcher started {} copies of glint ({}), but this glint was built without MPI, so each would run the "
         "whole job: rebuild with libopenmpi-dev installed (GLINT_MPI=AUTO or ON; docs/scale-out.md)",
         launched->count, launched->variable);
  Rank rank;
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) == 0) rank.host = name;
  return rank;
}

}  // namespace

bool built_with_mpi() { return false; }

const Rank& world() {
  static const Rank rank = start();
  return rank;
}

void send_text(int to, int /*tag*/, const std::string& /*text*/) { fail("MPI: no rank {} without MPI", to); }
std::optional<Message> try_receive_text(int /*from*/, int /*tag*/) { return std::nullopt; }
Message receive_text(int from, int /*tag*/) { fail("MPI: no rank {} without MPI", from); }
void barrier() {}
void mark_command_failed() {}
void abort_all(int exit_code) { std::_Exit(exit_code); }

}  // namespace glint::mpi
