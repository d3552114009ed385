// Signal-processing benchmarks. Run with e.g.
//   signal_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_signals.h"
#include "ridefit/signal/band_power.h"
#include "ridefit/signal/spectrum_peak.h"
#include "ridefit/signal/welch_psd.h"

namespace {

using ridefit::bench::sine_on_noise;

// 60 s at 1 kHz, 10 s segments, 50 % overlap: 11 segments of 10 000 samples.
void BM_WelchPsd_60s_1kHz_10sSegments(benchmark::State& state) {
  const double fs = 1000.0;
  const std::vector<double> x = sine_on_noise(60.0, fs);
  const ridefit::signal::WelchOptions options{.segment_length_s = 10.0, .overlap_fraction = 0.5};
  for (auto _ : state) {
    auto psd = ridefit::signal::welch_psd(x, fs, options);
    benchmark::DoNotOptimize(psd.psd.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(x.size()));
}
BENCHMARK(BM_WelchPsd_60s_1kHz_10sSegments)->Unit(benchmark::kMillisecond);

// 10^6 samples (1000 s at 1 kHz), 4096-sample segments, 50 % overlap: 487 segments.
void BM_WelchPsd_1e6Samples_4096Segments(benchmark::State& state) {
  const double fs = 1000.0;
  const std::vector<double> x = sine_on_noise(1000.0, fs);
  const ridefit::signal::WelchOptions options{.segment_length_samples = 4096,
                                              .overlap_fraction = 0.5};
  for (auto _ : state) {
    auto psd = ridefit::signal::welch_psd(x, fs, options);
    benchmark::DoNotOptimize(psd.psd.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(x.size()));
}
BENCHMARK(BM_WelchPsd_1e6Samples_4096Segments)->Unit(benchmark::kMillisecond);

// Peak search plus band power on the resulting 5001-bin spectrum.
void BM_PeakAndBandPower_5001Bins(benchmark::State& state) {
  const double fs = 1000.0;
  const auto psd =
      ridefit::signal::welch_psd(sine_on_noise(60.0, fs), fs, {.segment_length_s = 10.0});
  for (auto _ : state) {
    const auto peak = ridefit::signal::find_peak(psd, 0.5, 20.0);
    const double power = ridefit::signal::band_power(psd, 0.5, 80.0);
    benchmark::DoNotOptimize(peak.frequency_Hz);
    benchmark::DoNotOptimize(power);
  }
}
BENCHMARK(BM_PeakAndBandPower_5001Bins)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
