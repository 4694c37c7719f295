#pragma once
// Which CUDA device this process uses. CUDA's current device is per host thread and is 0 unless
// chosen; a process driving one GPU of several (a rank of `mpirun glint ...`, app/mpi/rank_devices.h)
// chooses its own before any other CUDA call, on the thread that does glint's CUDA work (the main
// thread: frame loop, tracers, deformers, interop).
namespace glint::cuda {

// Makes `ordinal` the calling thread's current CUDA device; a glint::Error naming it and the CUDA
// error when that fails. Without CUDA at build time: nothing to choose, does nothing.
void use_device(int ordinal);

// The number of CUDA devices visible to this process (0 without CUDA, a driver or a GPU).
int visible_device_count();

}  // namespace glint::cuda
