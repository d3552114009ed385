// Example: the core library (ridefit::core) on seed 000's Passat B8 front corner.
//
// Reads a quarter-car model file, prints the modes of its two linear limits (damper sliding:
// "slip"; damper locked by friction: "stick"), simulates the nonlinear stick/slip corner over a
// road and prints the ISO 2631-1 Wk-weighted RMS of the body acceleration, the comfort figure
// of a seat rail.
//
//   quarter_car_ride MODEL.yaml EXCITATION.yaml [DURATION_S]
//   e.g., from the repository's root:
//   quarter_car_ride datasets/vehicles/passat_b8_front.yaml
//                    datasets/excitations/iso8608_class_a_50kmh.yaml 10
//
// The same steps on the command line: `ridefit modes MODEL.yaml`, `ridefit simulate MODEL.yaml
// EXCITATION.yaml -o run.csv`, `ridefit analyse run.csv --channel body_acc`. Exit code 1 when a
// result is not finite or outside a broad physical range (the example runs as a test), 2 for
// bad arguments.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/quarter_car_modes.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace {

// Prints what is wrong and returns false when `value` is not finite or outside [lo, hi].
bool in_range(double value, double lo, double hi, const std::string& what) {
  if (std::isfinite(value) && value >= lo && value <= hi) return true;
  fmt::print(stderr, "FAILED: {} = {} is outside [{}, {}]\n", what, value, lo, hi);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    fmt::print(stderr, "usage: {} MODEL.yaml EXCITATION.yaml [DURATION_S]\n", argv[0]);
    return 2;
  }
  using namespace ridefit;
  try {
    bool ok = true;
    // 1. Modes. The file's third argument replaces its damper_state: the stick/slip model is
    //    nonlinear and has no modes, its slip and stick limits are linear and do.
    for (const std::string state : {"slip", "stick"}) {
      io::ModelOverrides topology;
      topology.damper_state = state;
      const io::QuarterCarFile linear = io::load_quarter_car(argv[1], topology);
      const simulate::ModalAnalysis modes = simulate::quarter_car_modes(linear.make_model());
      for (const simulate::OscillatoryMode& mode : modes.oscillatory) {
        fmt::print("{:<5} {:<5} mode {:7.3f} Hz, damping ratio {:.4f}\n", state, mode.dominant_dof,
                   mode.natural_frequency_Hz, mode.damping_ratio);
        ok &= in_range(mode.natural_frequency_Hz, 0.5, 50.0, state + " " + mode.dominant_dof);
      }
      ok &= modes.oscillatory.size() == 2;  // a body mode and a wheel mode
    }

    // 2. Simulation of the model as the file gives it (stick/slip), from static equilibrium at
    //    rest, on ridefit's adaptive ESDIRK integrator at its default tolerance.
    const io::QuarterCarFile corner = io::load_quarter_car(argv[1]);
    const auto road = road::load_excitation(argv[2]);  // any excitation file (type: ...)
    simulate::SimulationOptions options;
    options.output_rate_Hz = 1000.0;  // Wk needs at least 5 × its 100 Hz band limit
    options.duration_s = argc == 4 ? std::stod(argv[3]) : 10.0;
    const simulate::QuarterCarResponse run =
        simulate::simulate(corner.make_model(), *road, options);
    // Share of the samples on the Dahl element's pre-sliding branch (`stuck` is 0 or 1).
    const double stuck = static_cast<double>(std::count(run.stuck.begin(), run.stuck.end(), 1.0)) /
                         static_cast<double>(run.stuck.size());
    fmt::print("simulated {:g} s: {} samples, {} steps ({}), damper stuck {:.1f} % of the time\n",
               run.time_s.back(), run.time_s.size(), run.statistics.steps, run.statistics.method,
               100.0 * stuck);

    // 3. ISO 2631-1: weight the body acceleration with Wk (time domain, from rest), then take
    //    the basic evaluation's RMS a_w and the other clause-6 figures.
    const std::vector<double> weighted = comfort::apply_weighting(
        comfort::Weighting::kWk, run.body_acc_m_per_s2, options.output_rate_Hz);
    const comfort::VibrationMetrics m =
        comfort::vibration_metrics(weighted, options.output_rate_Hz);
    fmt::print("body_acc Wk: a_w {:.4f} m/s^2, MTVV {:.4f} m/s^2, VDV {:.4f} m/s^1.75\n",
               m.weighted_rms_m_per_s2, m.mtvv_m_per_s2, m.vdv_m_per_s1_75);

    // A car's body shakes by some thousandths (a rig's small sweep) to a few m/s^2 (ISO 2631-1
    // Annex C: below 0.315 m/s^2 is "not uncomfortable", above 2 m/s^2 "extremely uncomfortable").
    ok &= in_range(m.weighted_rms_m_per_s2, 0.001, 3.0, "a_w [m/s^2]");
    ok &= in_range(m.vdv_m_per_s1_75, 0.001, 20.0, "VDV [m/s^1.75]");
    ok &= in_range(stuck, 0.0, 1.0, "stuck share");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {  // InputError (bad file), RunError (solver failed)
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
}
