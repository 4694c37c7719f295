#pragma once
// What the environment says about an MPI launcher: mpirun/mpiexec (Open MPI, MPICH's hydra) and
// Slurm's srun export the number of tasks they started to every task. Read without MPI, so that a
// build without MPI can refuse to run as one of several copies.
#include <functional>
#include <optional>
#include <string>

namespace glint::mpi {

// The number of tasks the launcher started, with the variable that said so
// ("OMPI_COMM_WORLD_SIZE=2"), or nullopt when no launcher started this process. `getenv` is
// injectable for tests.
struct LaunchedTasks {
  int count = 1;
  std::string variable;
};
std::optional<LaunchedTasks> launched_tasks(const std::function<const char*(const char*)>& getenv);
std::optional<LaunchedTasks> launched_tasks();

}  // namespace glint::mpi
