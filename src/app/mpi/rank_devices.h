#pragma once
// Which GPU a rank of `mpirun glint ...` drives: the one of its node-local rank (the ranks of one host
// numbered 0, 1, ...; MPI_Comm_split_type), as an EGL device for OpenGL and the matching CUDA device
// for the cuda backend, GPU deformers and interop (docs/scale-out.md). NVIDIA's EGL devices say which
// CUDA device they are (EGL_CUDA_DEVICE_NV), which pairs the two. More local ranks than GPUs share
// them round robin; without an NVIDIA device (llvmpipe) every rank takes the default.
#include "gl/egl_devices.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace glint::mpi {

struct RankDevices {
  std::optional<int> egl_device;   // EGL device index to use; nullopt: glint's usual choice
  std::optional<int> cuda_device;  // CUDA ordinal to make current; nullopt: leave CUDA's default (0)
  std::string note;                // how they were chosen, for the log and the run's record
};

// The choice for `local_rank` among `devices`, with `cuda_count` CUDA devices visible; `egl_override`
// is GLINT_EGL_DEVICE when the user set it (it wins: the rank keeps it and takes its CUDA device).
RankDevices choose_rank_devices(int local_rank, const std::vector<EglDeviceDescription>& devices, int cuda_count,
                                const std::optional<int>& egl_override);

// A command's stay on its rank (render and bench make one first thing): it chooses the rank's devices
// (use_rank_devices) and, when the command leaves by an exception, marks it failed so that the exit
// ends every rank (mpi_world.h) instead of leaving the others waiting for this one. Once the shared
// work is over on every rank (`shared_work_over`: rank 0 after share_pieces returned), nobody waits
// for this rank any more: an exception then (a time limit, an interruption, an unwritable report)
// leaves by the usual MPI_Finalize with the command's own exit code.
class RankSession {
public:
  RankSession();
  ~RankSession();
  RankSession(const RankSession&) = delete;
  RankSession& operator=(const RankSession&) = delete;
  const nlohmann::json& about() const { return about_; }  // use_rank_devices()'s answer
  void shared_work_over() { shared_work_over_ = true; }

private:
  nlohmann::json about_;
  int exceptions_ = 0;
  bool shared_work_over_ = false;
};

// On a rank of a run with several ranks: chooses this rank's devices, exports GLINT_EGL_DEVICE for
// the contexts it makes and makes the CUDA device current on this thread, before any other GL or
// CUDA call of the command. Returns what the rank says of itself (rank, host, devices) for the
// record. A run with one rank is left exactly as it is (nothing is chosen); returns null then.
nlohmann::json use_rank_devices();

}  // namespace glint::mpi
