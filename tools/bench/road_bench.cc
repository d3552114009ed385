// Road generation and evaluation speed. Run with
//   road_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// and record the medians in README's benchmark table.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "ridefit/road/cleat.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/log_sweep.h"

namespace {

using ridefit::road::Iso8608RoadParameters;

Iso8608RoadParameters class_a_60s_at_50kmh() {
  Iso8608RoadParameters p;
  p.random.speed_m_per_s = 50.0 / 3.6;
  p.random.duration_s = 60.0;
  p.random.seed = 1;
  return p;
}

// Harmonics by inverse FFT, fade-in and the spline's coefficients: 833 m at 0.05 m.
void BM_Iso8608Generation60sAt50kmh(benchmark::State& state) {
  const Iso8608RoadParameters p = class_a_60s_at_50kmh();
  for (auto _ : state) {
    auto road = ridefit::road::make_iso8608_road(p);
    benchmark::DoNotOptimize(road);
  }
}
BENCHMARK(BM_Iso8608Generation60sAt50kmh)->Unit(benchmark::kMillisecond);

// One at() call at a random time, as an integrator's right-hand side makes it.
template <class Road>
void evaluate_at_random_times(benchmark::State& state, const Road& road) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, road.duration_s());
  std::vector<double> times(4096);
  for (double& t : times) t = uniform(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(road.at(times[i++ & 4095]));
  }
}

void BM_Iso8608At(benchmark::State& state) {
  evaluate_at_random_times(state, ridefit::road::make_iso8608_road(class_a_60s_at_50kmh()));
}
BENCHMARK(BM_Iso8608At);

void BM_LogSweepAt(benchmark::State& state) {
  ridefit::road::LogSweepParameters p;
  evaluate_at_random_times(state, ridefit::road::LogSweep(p));
}
BENCHMARK(BM_LogSweepAt);

void BM_CleatAt(benchmark::State& state) {
  evaluate_at_random_times(state, ridefit::road::make_cleat_road({}));
}
BENCHMARK(BM_CleatAt);

}  // namespace

BENCHMARK_MAIN();
