// The 7-DOF half car of seed 001 with seed 000's strut (stick/slip, Fc = 60 N) on the front
// axle, over 60 s of ISO 8608 class A road at 50 km/h, output at 1 kHz, ridefit's ESDIRK (the
// default) and CVODE, both at the default rtol (1e-5) and at 1e-6; and the same car without
// friction (front strut in slip).
// Road generated once, outside the timed loop.
//   half_car_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "ridefit/io/half_car_file.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/simulate/half_car_simulation.h"

namespace {

ridefit::model::HalfCar car(const std::string& damper_state) {
  return ridefit::io::load_half_car(
             std::string(RIDEFIT_SOURCE_DIR) + "/datasets/vehicles/ajayi_half_car.yaml",
             {{"front.suspension", "strut"}, {"front.damper_state", damper_state}})
      .make_model();
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

void run(benchmark::State& state, const std::string& damper_state,
         ridefit::simulate::Method method = ridefit::simulate::Method::kEsdirk,
         double relative_tolerance = ridefit::simulate::IntegratorOptions{}.relative_tolerance) {
  const ridefit::model::HalfCar model = car(damper_state);
  ridefit::simulate::HalfCarSimulationOptions options;
  options.output_rate_Hz = 1000.0;
  options.integrator.method = method;
  options.integrator.relative_tolerance = relative_tolerance;
  ridefit::simulate::HalfCarResponse response;
  for (auto _ : state) {
    response = ridefit::simulate::simulate(model, class_a_road(), options);
    benchmark::DoNotOptimize(response.samples.data());
  }
  state.counters["steps"] = static_cast<double>(response.statistics.steps);
  state.counters["rhs_evals"] = static_cast<double>(response.statistics.rhs_evaluations);
  state.counters["error_fails"] = static_cast<double>(response.statistics.error_test_failures);
  state.counters["newton_fails"] =
      static_cast<double>(response.statistics.nonlinear_convergence_failures);
  state.counters["events"] = static_cast<double>(response.statistics.events);
}

void BM_HalfCarFrontStrutFriction60s(benchmark::State& state) { run(state, "stick_slip"); }
BENCHMARK(BM_HalfCarFrontStrutFriction60s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_HalfCarFrontStrutFriction60s_Cvode(benchmark::State& state) {
  run(state, "stick_slip", ridefit::simulate::Method::kCvodeBdf);
}
BENCHMARK(BM_HalfCarFrontStrutFriction60s_Cvode)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_HalfCarFrontStrutFriction60s_Rtol1e6(benchmark::State& state) {
  run(state, "stick_slip", ridefit::simulate::Method::kEsdirk, 1e-6);
}
BENCHMARK(BM_HalfCarFrontStrutFriction60s_Rtol1e6)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_HalfCarFrontStrutFriction60s_Cvode_Rtol1e6(benchmark::State& state) {
  run(state, "stick_slip", ridefit::simulate::Method::kCvodeBdf, 1e-6);
}
BENCHMARK(BM_HalfCarFrontStrutFriction60s_Cvode_Rtol1e6)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

void BM_HalfCarFrontStrutSlip60s(benchmark::State& state) { run(state, "slip"); }
BENCHMARK(BM_HalfCarFrontStrutSlip60s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
