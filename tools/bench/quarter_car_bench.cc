// Stick/slip quarter car (Passat corner, Fc = 60 N) over 60 s of ISO 8608 class A road at
// 50 km/h, output at 1 kHz: ridefit's ESDIRK and CVODE, both at the default rtol (1e-5) and both
// at 1e-6 (rms_diff_pct: body
// acceleration RMS against a CVODE run at rtol 1e-10, made once), and RK4 at the largest of a few
// steps that matches CVODE's body-acceleration RMS within 0.5 % (rms_diff_pct). The road is
// generated once outside the timed loop (tools/bench/road_bench.cc times the generation).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace {

using ridefit::simulate::Method;

const ridefit::model::QuarterCar& passat() {
  static const ridefit::model::QuarterCar car = [] {
    auto file = ridefit::io::load_quarter_car(std::string(RIDEFIT_SOURCE_DIR) +
                                              "/datasets/vehicles/passat_b8_front.yaml");
    file.parameters.coulomb_force_N = 60.0;
    return ridefit::model::QuarterCar(ridefit::model::DamperState::kStickSlip, file.parameters);
  }();
  return car;
}

const ridefit::road::RoadInput& class_a_road() {
  static const ridefit::road::SpatialProfileRoad road = [] {
    ridefit::road::Iso8608RoadParameters parameters;
    parameters.road_class = ridefit::road::Iso8608Class::kA;
    parameters.random.speed_m_per_s = 50.0 / 3.6;
    parameters.random.duration_s = 60.0;
    parameters.random.seed = 1;
    return ridefit::road::make_iso8608_road(parameters);
  }();
  return road;
}

const double kDefaultTolerance = ridefit::simulate::IntegratorOptions{}.relative_tolerance;

ridefit::simulate::SimulationOptions options(Method method, double step_s,
                                             double relative_tolerance = kDefaultTolerance) {
  ridefit::simulate::SimulationOptions o;
  o.output_rate_Hz = 1000.0;
  o.integrator.method = method;
  o.integrator.relative_tolerance = relative_tolerance;
  o.integrator.fixed_step_s = step_s;
  return o;
}

void run(benchmark::State& state, Method method, double step_s,
         double relative_tolerance = kDefaultTolerance) {
  const auto o = options(method, step_s, relative_tolerance);
  static const auto reference = [] {
    auto reference_options = options(Method::kCvodeBdf, 0.0);
    reference_options.integrator.relative_tolerance = 1e-10;
    return ridefit::simulate::simulate(passat(), class_a_road(), reference_options);
  }();
  ridefit::simulate::QuarterCarResponse response;
  for (auto _ : state) {
    response = ridefit::simulate::simulate(passat(), class_a_road(), o);
    benchmark::DoNotOptimize(response.body_acc_m_per_s2.data());
  }
  state.counters["steps"] = static_cast<double>(response.statistics.steps);
  state.counters["rhs_evals"] = static_cast<double>(response.statistics.rhs_evaluations);
  state.counters["jac_evals"] = static_cast<double>(response.statistics.jacobian_evaluations);
  state.counters["error_fails"] = static_cast<double>(response.statistics.error_test_failures);
  state.counters["newton_fails"] =
      static_cast<double>(response.statistics.nonlinear_convergence_failures);
  state.counters["events"] = static_cast<double>(response.statistics.events);
  state.counters["body_rms"] = ridefit::signal::rms(response.body_acc_m_per_s2);
  state.counters["rms_diff_pct"] =
      100.0 * std::abs(ridefit::signal::rms(response.body_acc_m_per_s2) /
                           ridefit::signal::rms(reference.body_acc_m_per_s2) -
                       1.0);
}

void BM_StickSlipClassA60s_Esdirk(benchmark::State& state) { run(state, Method::kEsdirk, 0.0); }
BENCHMARK(BM_StickSlipClassA60s_Esdirk)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StickSlipClassA60s_Cvode(benchmark::State& state) { run(state, Method::kCvodeBdf, 0.0); }
BENCHMARK(BM_StickSlipClassA60s_Cvode)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StickSlipClassA60s_Esdirk_Rtol1e6(benchmark::State& state) {
  run(state, Method::kEsdirk, 0.0, 1e-6);
}
BENCHMARK(BM_StickSlipClassA60s_Esdirk_Rtol1e6)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StickSlipClassA60s_Cvode_Rtol1e6(benchmark::State& state) {
  run(state, Method::kCvodeBdf, 0.0, 1e-6);
}
BENCHMARK(BM_StickSlipClassA60s_Cvode_Rtol1e6)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StickSlipClassA60s_Rk4(benchmark::State& state) {
  run(state, Method::kArkodeRk4, static_cast<double>(state.range(0)) * 1e-6);
}
// Steps in µs: 100 µs is unstable on this road (sliding at wheel-hop speeds makes
// ∂Ḟ/∂F ≈ −σ0·|ż_c|/Fc reach −25 000 1/s), 50 µs is stable.
BENCHMARK(BM_StickSlipClassA60s_Rk4)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
