#pragma once
// The MPI ranks of this glint process, and text messages between them: the thin layer over MPI's C
// interface that the rest of app/mpi/ uses (docs/scale-out.md). mpi_world.cpp holds the MPI calls;
// mpi_world_off.cpp, its twin in a build without MPI (GLINT_MPI=OFF or no MPI found), answers "one
// rank". Nothing else in glint includes <mpi.h>.
//
// MPI starts only when an MPI launcher (mpirun, mpiexec, srun) started this process, which its
// environment says; a plain `glint ...` never calls MPI_Init and behaves as a build without MPI.
#include <optional>
#include <string>

namespace glint::mpi {

// Whether this binary was built with MPI (cmake/GlintMpi.cmake).
bool built_with_mpi();

struct Rank {
  int rank = 0;        // in MPI_COMM_WORLD
  int size = 1;        // ranks in MPI_COMM_WORLD
  int local_rank = 0;  // among the ranks of this host (MPI_Comm_split_type(MPI_COMM_TYPE_SHARED))
  int local_size = 1;
  std::string host;    // MPI_Get_processor_name, else the host name
  bool lead() const { return rank == 0; }
};

// This process's rank. The first call starts MPI (MPI_Init_thread, MPI_THREAD_SERIALIZED: rank 0
// hands out work from a second thread while its main thread renders, never both calling MPI at once)
// when launched by an MPI launcher, and MPI_Finalize runs at exit. A glint::Error when a launcher
// started several tasks that MPI does not see as one world (srun without --mpi=pmix), or when this
// build has no MPI and a launcher started several copies (each would run the whole job).
const Rank& world();

// Text messages between ranks (world().size > 1 only). Receiving polls and sleeps between polls, so
// a rank that waits leaves the CPU to those that work (several ranks may share a host's cores).
struct Message {
  int source = -1;
  std::string text;
};
void send_text(int to, int tag, const std::string& text);
std::optional<Message> try_receive_text(int from, int tag);  // from -1: any rank
Message receive_text(int from, int tag);

// Returns once every rank called it (MPI_Ibarrier, polled as receive_text polls); nothing with one rank.
void barrier();

// Says that this rank's command failed: at exit it ends every rank with MPI_Abort instead of
// finalizing (MPI_Finalize would wait for ranks that wait for it). Nothing without MPI.
void mark_command_failed();

// Ends every rank at once (MPI_Abort): for an error after the ranks started to share work, where
// returning would leave the others waiting for a message that never comes.
[[noreturn]] void abort_all(int exit_code);

}  // namespace glint::mpi
