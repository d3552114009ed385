// Hysteresis fits on synthetic rig tests of seed 000's Passat strut (σ0 5e6 N/m, Fc 60 N, d 1,
// top mount 488 N/mm, c 887 Ns/m): 3 free parameters (σ0, Fc, d) on 10 quasi-static cycles
// (3 mm at 1 mm/s, 200 Hz; target ≤ 0.3 s) and 5 free parameters on a 60 s dynamic history at
// 1 kHz (three sines; target ≤ 1 s). Data generated once outside the timed loop (by the same
// ESDIRK strut solver: a timing, not an accuracy test; tests/fitting/strut_fit_recovery_test.cc
// fits CVODE-made records); each fit starts from the same perturbed values.
//   hysteresis_fit_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <functional>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/synthetic/multisine.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "ridefit/synthetic/triangle_history.h"

namespace {

using ridefit::fitting::HysteresisRecord;

ridefit::model::StrutTestParameters<double> truth() {
  return ridefit::model::dahl_strut_on_rig(5e6, 60.0, 1.0, 488000.0, 887.0);
}

HysteresisRecord record(bool dynamic) {
  HysteresisRecord r;
  const auto p = truth();
  const std::function<double(double)> x =
      dynamic ? std::function<double(double)>(ridefit::synthetic::lab_three_sines())
              : ridefit::synthetic::TriangleHistory(0.003, 0.001);
  r.time_s = dynamic ? ridefit::synthetic::sample_times(60001, 1000.0)
                     : ridefit::synthetic::sample_times(10 * 12 * 200 + 1, 200.0);
  for (double t : r.time_s) r.displacement_m.push_back(x(t));
  // The triangle is straight between samples: linear interpolation, as the fit uses below.
  ridefit::simulate::StrutTestSolverOptions solver;
  if (!dynamic) solver.interpolation = ridefit::simulate::RigInterpolation::kLinear;
  r.force_N =
      *ridefit::simulate::strut_test_force<double>(r.time_s, r.displacement_m, p, p, solver);
  return r;
}

void BM_HysteresisFit3ParametersQuasiStatic(benchmark::State& state) {
  const auto data = record(false);
  auto start = truth();
  start.dahl_sigma0_N_per_m = 2e6;
  start.coulomb_force_N = 40.0;
  start.dahl_exponent = 1.5;
  ridefit::fitting::HysteresisFitOptions options;
  options.free = {"dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent"};
  options.solver.interpolation = ridefit::simulate::RigInterpolation::kLinear;
  for (auto _ : state) {
    auto fit = ridefit::fitting::fit_hysteresis({data}, start, options);
    benchmark::DoNotOptimize(fit.final_cost);
    state.counters["iterations"] = fit.iterations;
  }
}
BENCHMARK(BM_HysteresisFit3ParametersQuasiStatic)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HysteresisFit5ParametersDynamic60s(benchmark::State& state) {
  const auto data = record(true);
  auto start = truth();
  start.dahl_sigma0_N_per_m = 3e6;
  start.coulomb_force_N = 45.0;
  start.dahl_exponent = 1.3;
  start.top_mount_stiffness_N_per_m = 350000.0;
  start.damping_Ns_per_m = 1200.0;
  ridefit::fitting::HysteresisFitOptions options;
  options.free = {"dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent",
                  "top_mount_stiffness_N_per_m", "damping_Ns_per_m"};
  for (auto _ : state) {
    auto fit = ridefit::fitting::fit_hysteresis({data}, start, options);
    benchmark::DoNotOptimize(fit.final_cost);
    state.counters["iterations"] = fit.iterations;
  }
}
BENCHMARK(BM_HysteresisFit5ParametersDynamic60s)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
