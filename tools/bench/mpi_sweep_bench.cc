// 10 000 linear half-car configurations (damping × spring stiffness of both axles, 100 × 100)
// on seed 001's gravel road at 40 km/h, frequency domain, swept by
// `mpirun -np N ridefit sweep STUDY --threads 1` for N = 1 and 2 ranks. Wall time of the whole
// command, launch included, as a user sees it (UseManualTime). Target: 2 ranks at least 1.8×
// faster than 1. Skipped in a build without MPI. For the scaling estimate (README): the
// preparation every rank repeats (BM_PrepareSweep10000: the 10 000 cars made and checked, the
// road spectrum once) and one run alone (BM_OneRun).
//   mpi_sweep_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <fmt/core.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mpi_command.h"
#include "ridefit/study/half_car_sweep.h"

namespace {

const std::filesystem::path& study_file() {
  static const std::filesystem::path path = [] {
    const std::string root = RIDEFIT_SOURCE_DIR;
    const auto file = std::filesystem::temp_directory_path() /
                      ("ridefit_mpi_sweep_bench_" + std::to_string(getpid()) + ".yaml");
    std::ofstream(file) << "model: " << root << "/datasets/vehicles/ajayi_half_car.yaml\n"
                        << "roads:\n  gravel: " << root
                        << "/datasets/excitations/gravel_road_seed001.yaml\n"
                        << "speeds_km_per_h: [40]\n"
                        << "vary:\n  - parameter: [front.damping_Ns_per_m, rear.damping_Ns_per_m]\n"
                        << "    range: {from: 500, to: 4000, count: 100, spacing: linear}\n"
                        << "  - parameter: [front.spring_stiffness_N_per_m, "
                           "rear.spring_stiffness_N_per_m]\n"
                        << "    range: {from: 10000, to: 40000, count: 100, spacing: linear}\n";
    return file;
  }();
  return path;
}

void BM_MpiSweep10000(benchmark::State& state) {
  const auto output = std::filesystem::temp_directory_path() /
                      ("ridefit_mpi_sweep_bench_" + std::to_string(getpid()) + ".csv");
  ridefit::bench::time_ridefit_under_mpirun(
      state, fmt::format("sweep {} --threads 1 -o {}", study_file().string(), output.string()));
  std::filesystem::remove(output);
}
BENCHMARK(BM_MpiSweep10000)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("ranks")
    ->Unit(benchmark::kSecond)
    ->UseManualTime()
    ->Iterations(1);

void BM_PrepareSweep10000(benchmark::State& state) {
  const auto sweep = ridefit::study::load_half_car_sweep(study_file());
  for (auto _ : state) {
    const ridefit::study::PreparedSweep prepared(sweep, 1);
    benchmark::DoNotOptimize(prepared.runs());
  }
}
BENCHMARK(BM_PrepareSweep10000)->Unit(benchmark::kMillisecond);

void BM_OneRun(benchmark::State& state) {
  const auto sweep = ridefit::study::load_half_car_sweep(study_file());
  const ridefit::study::PreparedSweep prepared(sweep, 1);
  std::size_t i = 0;
  for (auto _ : state) {
    auto row = prepared.run(i);
    benchmark::DoNotOptimize(row.metrics.seat_acc_wk_rms_m_per_s2);
    i = (i + 37) % prepared.runs();
  }
}
BENCHMARK(BM_OneRun)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
