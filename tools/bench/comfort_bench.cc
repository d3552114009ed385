// ISO 2631-1 comfort benchmarks. Run with e.g.
//   comfort_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_signals.h"
#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/comfort/weighting_filter.h"

namespace {

using ridefit::bench::sine_on_noise;

// Wk time-domain weighting of 10^6 samples at 1 kHz (1000 s of record), 4 biquads; target
// ≤ 10 ms. Includes the NaN scan and the output allocation, as apply_weighting does.
void BM_WkWeighting_1e6Samples_1kHz(benchmark::State& state) {
  const double fs = 1000.0;
  const std::vector<double> x = sine_on_noise(1000.0, fs);
  for (auto _ : state) {
    auto aw = ridefit::comfort::apply_weighting(ridefit::comfort::Weighting::kWk, x, fs);
    benchmark::DoNotOptimize(aw.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(x.size()));
}
BENCHMARK(BM_WkWeighting_1e6Samples_1kHz)->Unit(benchmark::kMillisecond);

// All metrics (RMS, running RMS τ = 1 s, MTVV, VDV, crest factor) of the same record.
void BM_VibrationMetrics_1e6Samples_1kHz(benchmark::State& state) {
  const double fs = 1000.0;
  const std::vector<double> x = sine_on_noise(1000.0, fs);
  for (auto _ : state) {
    auto m = ridefit::comfort::vibration_metrics(x, fs);
    benchmark::DoNotOptimize(m.mtvv_m_per_s2);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(x.size()));
}
BENCHMARK(BM_VibrationMetrics_1e6Samples_1kHz)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
