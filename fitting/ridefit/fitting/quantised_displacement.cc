#include "ridefit/fitting/quantised_displacement.h"

#include "ridefit/signal/zero_phase_low_pass.h"

namespace ridefit::fitting {

void examine_quantised_displacement(HysteresisRecord& record) {
  if (record.displacement_low_pass) return;
  record.displacement_low_pass =
      signal::choose_quantisation_low_pass(record.time_s, record.displacement_m);
}

void smooth_quantised_displacement(HysteresisRecord& record) {
  examine_quantised_displacement(record);
  if (record.displacement_low_passed || !(record.displacement_low_pass->cutoff_Hz > 0.0)) return;
  const double n = static_cast<double>(record.time_s.size() - 1);
  const double rate_Hz = n / (record.time_s.back() - record.time_s.front());
  record.displacement_m = signal::zero_phase_low_pass(record.displacement_m, rate_Hz,
                                                      record.displacement_low_pass->cutoff_Hz);
  record.displacement_low_passed = true;
}

}  // namespace ridefit::fitting
