#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ridefit/io/csv_table.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "support/temp_dir.h"

namespace ridefit::testing {

// An MR damper on a press (the UTFSM sine files' setting): Dahl friction and damping affine in
// the coil current, a gas spring and a load-cell offset, a 3e6 N/m mount.
inline model::StrutTestParameters<double> mr_press_truth() {
  model::StrutTestParameters<double> p{};
  p.dahl_sigma0_N_per_m = 2.0e6;
  p.coulomb_force_N = 150.0;
  p.dahl_exponent = 1.0;
  p.top_mount_stiffness_N_per_m = 3.0e6;
  p.damping_Ns_per_m = 1500.0;
  p.force_offset_N = 45.0;
  p.gas_stiffness_N_per_m = 4000.0;
  p.damping_per_command_Ns_per_m = 2500.0;
  p.coulomb_force_per_command_N = 1100.0;
  return p;
}

// A user's start for mr_press_truth()'s levels: each about a third off, no offset.
inline void set_levels_a_third_off(model::StrutTestParameters<double>& p) {
  p.damping_Ns_per_m = 1000.0;
  p.coulomb_force_N = 200.0;
  p.damping_per_command_Ns_per_m = 1700.0;
  p.coulomb_force_per_command_N = 750.0;
  p.force_offset_N = 0.0;
}

// How the file's tests are run and recorded.
struct FiveCurrentTests {
  int tests = 5;            // at 0, 0.25, 0.5, ... A
  double cycles = 4.0;      // sine cycles per test
  double rate_Hz = 1000.0;  // sampling
  double frequency_Hz = 2.0;
  double amplitude_m = 0.008;
};

// A file of tests at stepped currents as a DAQ paused between them writes it: the time runs on,
// the actuator rests at an offset position before and after each test, displacement quantised
// at 3 µm and force at 3 N; a `segment` column numbers the tests. The force is CVODE's at rtol
// 1e-10 on the exact motion (synthetic::reference_rig_record), not the fits' ESDIRK.
inline std::string five_current_file(const TempDir& dir,
                                     const model::StrutTestParameters<double>& truth,
                                     const FiveCurrentTests& run = {},
                                     const std::string& name = "five_currents.csv") {
  const std::string path = (dir.path() / name).string();
  const double rest = -0.0299;
  std::vector<double> time, x, force, current, segment;
  double t0 = 0.0;
  for (int test = 0; test < run.tests; ++test) {
    const double amps = 0.25 * test;
    const double lead = 0.3, motion = run.cycles / run.frequency_Hz;
    // Rest, then a sine from rest (starting at its zero), then rest.
    auto displacement = [&](double t) {
      const double s = t - lead;
      return rest + (s > 0.0 && s < motion
                         ? run.amplitude_m * std::sin(2 * std::numbers::pi * run.frequency_Hz * s)
                         : 0.0);
    };
    const auto samples = static_cast<std::size_t>((2 * lead + motion) * run.rate_Hz);
    const auto grid = synthetic::sample_times(samples, run.rate_Hz);
    const auto r =
        synthetic::reference_rig_record(grid, displacement, truth, [amps](double) { return amps; });
    for (std::size_t k = 0; k < samples; ++k) {
      time.push_back(t0 + grid[k]);
      x.push_back(3e-6 * std::round(r.displacement_m[k] / 3e-6));
      force.push_back(3.0 * std::round(r.force_N[k] / 3.0));
      current.push_back(amps);
      segment.push_back(test + 1);
    }
    t0 += grid.back() + 25.0;  // the pause: the sample clock ran on
  }
  io::CsvTable table(path);
  table.add("time", "s", time);
  table.add("displacement", "m", x);
  table.add("force", "N", force);
  table.add("current", "A", current);
  table.add("segment", "1", segment);
  table.write(path);
  return path;
}

}  // namespace ridefit::testing
