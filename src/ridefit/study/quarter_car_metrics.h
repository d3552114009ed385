#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace ridefit::study {

// The ride figures of a quarter-car run a damper engineer trades against each other: ISO
// 2631-1 Wk-weighted RMS of the body acceleration (the seat-rail comfort value), unweighted
// accelerations, suspension travel (RMS and the largest |travel|, against the rattle space) and
// the dynamic tyre load (RMS, and over the static load (m_s + m_u)·g), and the share of time
// the strut's damper sticks.
struct QuarterCarMetrics {
  double body_acc_wk_rms_m_per_s2 = 0.0;
  double body_acc_rms_m_per_s2 = 0.0;
  double wheel_acc_rms_m_per_s2 = 0.0;
  double travel_rms_m = 0.0;
  double travel_peak_m = 0.0;
  double tyre_force_rms_N = 0.0;
  double dynamic_load_ratio = 0.0;
  double stuck_share = 0.0;

  // (name with unit suffix, value) in the order above: CSV columns and JSON keys.
  std::vector<std::pair<std::string, double>> named() const;
};

// From a time-domain run; samples before `settle_s` are left out (the Wk filter runs over the
// whole record first, so its start-up is left out too). The output rate must be at least what
// Wk needs (InputError otherwise, from the weighting filter).
QuarterCarMetrics quarter_car_metrics(const simulate::QuarterCarResponse& response,
                                      const model::QuarterCarParameters<double>& parameters,
                                      double settle_s = 0.0);

}  // namespace ridefit::study
