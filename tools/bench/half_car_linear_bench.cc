// The linear half car in the frequency domain: H(f) of all 9 outputs × 4 road inputs at 1000
// frequencies (target ≤ 1 ms), and a full evaluation of the ride figures for one
// configuration on seed 001's gravel road at 40 km/h (state space, eigendecomposition, 1000
// frequencies, weighting, integration) — the unit of work of a linear sweep.
//   half_car_linear_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "ridefit/io/half_car_file.h"
#include "ridefit/road/power_law_road.h"
#include "ridefit/simulate/frequency_response.h"
#include "ridefit/study/half_car_spectral_metrics.h"

namespace {

const ridefit::model::HalfCar& car() {
  static const ridefit::model::HalfCar model =
      ridefit::io::load_half_car(std::string(RIDEFIT_SOURCE_DIR) +
                                 "/datasets/vehicles/ajayi_half_car.yaml")
          .make_model();
  return model;
}

void BM_HalfCarFrequencyResponse1000(benchmark::State& state) {
  const ridefit::simulate::FrequencyResponse response(
      ridefit::simulate::half_car_state_space(car()));
  for (auto _ : state) {
    double sum = 0.0;
    for (int k = 0; k < 1000; ++k) sum += response.at(0.1 + 0.1 * k).norm();
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_HalfCarFrequencyResponse1000)->Unit(benchmark::kMicrosecond);

void BM_HalfCarSpectralMetrics(benchmark::State& state) {
  ridefit::road::PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = ridefit::road::kSeed001GravelHighwayCr_m3;
  p.waviness = ridefit::road::kSeed001Waviness;
  const ridefit::road::RoadSpectrum road{p.spectrum(), p.random.band, 40.0 / 3.6, 60.0};
  for (auto _ : state) {
    auto metrics = ridefit::study::half_car_spectral_metrics(car(), road);
    benchmark::DoNotOptimize(metrics);
  }
}
BENCHMARK(BM_HalfCarSpectralMetrics)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
