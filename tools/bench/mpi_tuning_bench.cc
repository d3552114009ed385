// A damper tuning over ranks: the Passat strut with friction, damping and top-mount stiffness
// as the design, three load cases in the time domain (class A road at 50 and 100 km/h, gravel
// at 30 km/h laden), COBYLA from 8 starts, the friction-blind optimum beside it; run by
// `mpirun -np N ridefit optimise STUDY --threads 1` for N = 1 and 2 ranks. Wall time of the
// whole command, launch included (UseManualTime). Target: 2 ranks at least 1.7× faster than 1.
// Skipped in a build without MPI.
//   mpi_tuning_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <fmt/core.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mpi_command.h"

namespace {

const std::filesystem::path& work_dir() {
  static const std::filesystem::path path = [] {
    const std::string root = RIDEFIT_SOURCE_DIR;
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ridefit_mpi_tuning_bench_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string data = root + "/datasets";
    std::ofstream(dir / "study.yaml")
        << "model: " << data << "/vehicles/passat_b8_front.yaml\n"
        << "design:\n"
        << "  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000, scale: log}\n"
        << "  - {parameter: top_mount_stiffness_N_per_m, lower: 150000, upper: 1500000, "
           "scale: log}\n"
        << "load_cases:\n"
        << "  - {name: a50, road: " << data << "/excitations/iso8608_class_a_50kmh.yaml}\n"
        << "  - {name: a100, road: " << data
        << "/excitations/iso8608_class_a_50kmh.yaml, speed_km_per_h: 100}\n"
        << "  - {name: gravel_laden, road: " << data
        << "/excitations/gravel_road_seed001.yaml, speed_km_per_h: 30, "
           "set: {sprung_mass_kg: 445.4}}\n"
        << "objective: {metric: body_acc_wk_rms_m_per_s2}\n"
        << "constraints: [{metric: dynamic_load_ratio, max: 0.2}]\n"
        << "optimiser: {starts: 8, max_evaluations: 60}\n"
        << "evaluation: {method: time, duration_s: 8, settle_s: 1, output_rate_Hz: 500}\n";
    return dir;
  }();
  return path;
}

void BM_MpiTuning8Starts(benchmark::State& state) {
  ridefit::bench::time_ridefit_under_mpirun(
      state, fmt::format("optimise study.yaml --threads 1 -q --force -o r{}.yaml", state.range(0)),
      work_dir().string());
}
BENCHMARK(BM_MpiTuning8Starts)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("ranks")
    ->Unit(benchmark::kSecond)
    ->UseManualTime()
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
