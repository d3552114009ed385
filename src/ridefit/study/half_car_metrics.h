#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ridefit/simulate/half_car_simulation.h"

namespace ridefit::study {

// The ride figures of a half-car run that seed 001 reports (its Figures 5–17) and a ride
// engineer compares: ISO 2631-1 weighted RMS at the seat and the body segments (Wk) and of the
// body pitch (We), unweighted RMS of those, suspension travel and dynamic tyre force RMS per
// axle (the tyre force over the static wheel load too).
struct HalfCarMetrics {
  double seat_acc_wk_rms_m_per_s2 = 0.0;
  double lower_body_acc_wk_rms_m_per_s2 = 0.0;
  double upper_body_acc_wk_rms_m_per_s2 = 0.0;
  double pitch_acc_we_rms_rad_per_s2 = 0.0;
  double seat_acc_rms_m_per_s2 = 0.0;
  double lower_body_acc_rms_m_per_s2 = 0.0;
  double upper_body_acc_rms_m_per_s2 = 0.0;
  double body_acc_rms_m_per_s2 = 0.0;
  double pitch_acc_rms_rad_per_s2 = 0.0;
  double front_travel_rms_m = 0.0;
  double rear_travel_rms_m = 0.0;
  double front_tyre_force_rms_N = 0.0;
  double rear_tyre_force_rms_N = 0.0;
  double front_dynamic_load_ratio = 0.0;  // tyre force RMS over the static wheel load
  double rear_dynamic_load_ratio = 0.0;

  // (name with unit suffix, value) in the order above: CSV columns and JSON keys.
  std::vector<std::pair<std::string, double>> named() const;
};

// Static wheel loads of the car [N]: body and occupant weight split by the lever rule, plus the
// wheel's own weight.
std::pair<double, double> static_wheel_loads_N(const model::HalfCarParameters<double>& p);

// From a time-domain run; samples before `settle_s` are left out (start-up of the weighting
// filters and of the car). The output rate must be at least what the weightings need (500 Hz
// for Wk; InputError otherwise).
HalfCarMetrics half_car_metrics(const simulate::HalfCarResponse& response,
                                const model::HalfCarParameters<double>& parameters,
                                double settle_s = 0.0);

}  // namespace ridefit::study
