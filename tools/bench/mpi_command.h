#pragma once

// What the MPI benchmarks share: `mpirun -np N ridefit ARGUMENTS` timed as a user sees it,
// launch included (UseManualTime), N = state.range(0); skipped in a build without MPI. One
// machine, so Open MPI's point-to-point layer is named (pml ob1, over shared memory): that is
// what it ends up choosing here anyway, after a 0.25 s probe for UCX network hardware in every
// rank's MPI_Init, which the README advises users on one machine to skip the same way.

#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <chrono>
#include <cstdlib>
#include <string>

namespace ridefit::bench {

inline void time_ridefit_under_mpirun(benchmark::State& state, const std::string& arguments,
                                      const std::string& working_dir = ".") {
  const std::string mpiexec = RIDEFIT_MPIEXEC;
  if (mpiexec.empty()) {
    state.SkipWithError("ridefit was built without MPI");
    return;
  }
  const std::string command = fmt::format(
      "cd {} && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
      "OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_pml=ob1 {} -np {} {} {} >/dev/null 2>&1",
      working_dir, mpiexec, state.range(0), RIDEFIT_CLI, arguments);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (std::system(command.c_str()) != 0) {
      state.SkipWithError(("failed: " + command).c_str());
      break;
    }
    state.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

}  // namespace ridefit::bench
