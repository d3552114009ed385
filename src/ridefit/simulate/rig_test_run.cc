#include "ridefit/simulate/rig_test_run.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::simulate {

RigTestRecord simulate_rig_test(const model::StrutTestParameters<double>& strut,
                                const road::RigTest& test, const road::RigLimits& limits,
                                const StrutTestSolverOptions& solver) {
  const road::RigMotion motion = test.motion(limits);
  RigTestRecord record;
  record.peak_displacement_m = motion.peak_displacement_m();
  record.peak_velocity_m_per_s = motion.peak_velocity_m_per_s();
  record.highest_frequency_Hz = motion.highest_frequency_Hz();
  motion.samples(record.time_s, record.displacement_m, record.velocity_m_per_s);
  StrutTestSolverOptions options = solver;
  std::vector<double> velocity = record.velocity_m_per_s;
  if (test.waveform == road::RigWaveform::kTriangle) {
    // A triangle's velocity jumps at its corners: the samples joined by straight lines are its
    // exact shape wherever a corner falls on a sample, and never overshoot where one does not.
    options.interpolation = RigInterpolation::kLinear;
    velocity.clear();
  }
  const auto force = strut_test_force<double>(record.time_s, record.displacement_m, strut, strut,
                                              options, {}, velocity);
  if (!force) {
    throw InputError(fmt::format(
        "the strut model cannot be solved on this {} test (the solver gave up: more than {:g} "
        "steps per simulated second); check the model's values",
        road::waveform_name(test.waveform), options.max_steps_per_s));
  }
  record.force_N = *force;
  for (std::size_t k = 0; k < record.force_N.size(); ++k) {
    if (std::abs(record.force_N[k]) > record.peak_force_N) {
      record.peak_force_N = std::abs(record.force_N[k]);
      record.peak_time_s = record.time_s[k];
    }
  }
  if (record.peak_force_N > limits.force_N) {
    throw InputError(
        fmt::format("the {} test needs {:.4g} kN (at t = {:.4g} s), beyond the rig's {:.4g} kN "
                    "(rig.force_N); lower its size or speed",
                    road::waveform_name(test.waveform), 1e-3 * record.peak_force_N,
                    record.peak_time_s, 1e-3 * limits.force_N));
  }
  return record;
}

}  // namespace ridefit::simulate
