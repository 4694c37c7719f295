// The GPU each rank of `mpirun glint ...` drives (app/mpi/rank_devices.h) and how glint knows it was
// launched by mpirun or srun (app/mpi/mpi_launch.h).
#include "app/mpi/mpi_launch.h"
#include "app/mpi/mpi_world.h"
#include "app/mpi/rank_devices.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace glint::mpi {
namespace {

EglDeviceDescription nvidia(int index, std::optional<int> cuda) {
  return {index, "EGL_NV_device_cuda EGL_EXT_device_drm", "/dev/dri/card" + std::to_string(index), cuda};
}
EglDeviceDescription software(int index) { return {index, "EGL_MESA_device_software", "", std::nullopt}; }

TEST(RankDevices, EachLocalRankTakesItsOwnGpuAndItsCudaDevice) {
  // EGL lists the GPUs in another order than CUDA: the pairing follows CUDA's.
  const std::vector<EglDeviceDescription> devices = {nvidia(0, 1), nvidia(1, 0), software(2)};
  const RankDevices rank0 = choose_rank_devices(0, devices, 2, std::nullopt);
  const RankDevices rank1 = choose_rank_devices(1, devices, 2, std::nullopt);
  EXPECT_EQ(rank0.egl_device, 1);
  EXPECT_EQ(rank0.cuda_device, 0);
  EXPECT_EQ(rank1.egl_device, 0);
  EXPECT_EQ(rank1.cuda_device, 1);
  // More ranks than GPUs share them round robin.
  EXPECT_EQ(choose_rank_devices(2, devices, 2, std::nullopt).cuda_device, 0);
}

TEST(RankDevices, WithoutAGpuEveryRankTakesTheDefault) {
  const RankDevices chosen = choose_rank_devices(1, {software(0)}, 0, std::nullopt);
  EXPECT_FALSE(chosen.egl_device.has_value());
  EXPECT_FALSE(chosen.cuda_device.has_value());
}

TEST(RankDevices, TheUsersEglDeviceWins) {
  const RankDevices chosen = choose_rank_devices(0, {nvidia(0, 0), nvidia(1, 1)}, 2, 1);
  EXPECT_EQ(chosen.egl_device, 1);
  EXPECT_EQ(chosen.cuda_device, 1);
}

TEST(RankDevices, ACudaDeviceTheProcessCannotSeeIsNotTaken) {
  // CUDA_VISIBLE_DEVICES left one device: EGL's ordinal 1 does not exist for CUDA here.
  const RankDevices chosen = choose_rank_devices(1, {nvidia(0, 0), nvidia(1, 1)}, 1, std::nullopt);
  EXPECT_EQ(chosen.egl_device, 1);
  EXPECT_EQ(chosen.cuda_device, 0);  // the one it sees
}

TEST(MpiLaunch, ReadsTheLaunchersTaskCount) {
  const auto env = [](std::map<std::string, std::string> values) {
    return [values](const char* name) -> const char* {
      const auto found = values.find(name);
      return found == values.end() ? nullptr : found->second.c_str();
    };
  };
  EXPECT_FALSE(launched_tasks(env({})).has_value());
  EXPECT_EQ(launched_tasks(env({{"OMPI_COMM_WORLD_SIZE", "3"}}))->count, 3);
  EXPECT_EQ(launched_tasks(env({{"SLURM_STEP_NUM_TASKS", "8"}}))->variable, "SLURM_STEP_NUM_TASKS=8");
  EXPECT_EQ(launched_tasks(env({{"PMI_SIZE", "x"}, {"PMIX_RANK", "0"}}))->count, 1);
}

TEST(MpiWorld, APlainProcessIsOneRank) {
  // The test binary is not started by mpirun: no MPI_Init, one rank, no devices chosen.
  EXPECT_EQ(world().size, 1);
  EXPECT_TRUE(world().lead());
  EXPECT_TRUE(use_rank_devices().is_null());
}

}  // namespace
}  // namespace glint::mpi
