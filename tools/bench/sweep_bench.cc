// A sweep of 1000 linear half-car configurations (damping of both axles, 500–4000 Ns/m) on
// seed 001's gravel road at 40 km/h, frequency domain, with 1 and 2 threads (target ≤ 2 s on 2
// cores). Wall time (UseRealTime), so the speed-up shows. The study file is written to /tmp
// once.
//   sweep_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ridefit/study/half_car_sweep.h"

namespace {

const ridefit::study::HalfCarSweep& study() {
  static const ridefit::study::HalfCarSweep sweep = [] {
    const std::string root = RIDEFIT_SOURCE_DIR;
    const auto path = std::filesystem::temp_directory_path() /
                      ("ridefit_sweep_bench_" + std::to_string(getpid()) + ".yaml");
    std::ofstream(path) << "model: " << root << "/datasets/vehicles/ajayi_half_car.yaml\n"
                        << "roads:\n  gravel: " << root
                        << "/datasets/excitations/gravel_road_seed001.yaml\n"
                        << "speeds_km_per_h: [40]\n"
                        << "vary:\n  - parameter: [front.damping_Ns_per_m, rear.damping_Ns_per_m]\n"
                        << "    range: {from: 500, to: 4000, count: 1000, spacing: linear}\n";
    auto loaded = ridefit::study::load_half_car_sweep(path);
    std::filesystem::remove(path);
    return loaded;
  }();
  return sweep;
}

void BM_LinearSweep1000(benchmark::State& state) {
  const auto threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    auto rows = ridefit::study::run_half_car_sweep(study(), threads);
    benchmark::DoNotOptimize(rows.data());
  }
}
BENCHMARK(BM_LinearSweep1000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
