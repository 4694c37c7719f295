#include "app/mpi/mpi_launch.h"

#include <charconv>
#include <cstdlib>
#include <string_view>

namespace glint::mpi {

std::optional<LaunchedTasks> launched_tasks(const std::function<const char*(const char*)>& getenv) {
  // Open MPI's mpirun; MPICH's hydra and srun --mpi=pmi2; srun itself (any --mpi), for one step.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
    const char* value = getenv(name);
    if (value == nullptr || *value == '\0') continue;
    const std::string_view text(value);
    int count = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (error != std::errc() || end != text.data() + text.size() || count < 1) continue;
    return LaunchedTasks{count, std::string(name) + "=" + std::string(text)};
  }
  // PMIx (srun --mpi=pmix, Open MPI 5's prterun) names the rank only.
  if (const char* rank = getenv("PMIX_RANK"); rank != nullptr && *rank != '\0') return LaunchedTasks{1, "PMIX_RANK"};
  return std::nullopt;
}

std::optional<LaunchedTasks> launched_tasks() {
  return launched_tasks([](const char* name) { return std::getenv(name); });
}

}  // namespace glint::mpi
