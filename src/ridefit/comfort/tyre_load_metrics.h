#pragma once

#include <span>

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/standard_gravity.h"

namespace ridefit::comfort {

// Standard gravity (ISO 80000-3) [m/s²], the model layer's value.
inline constexpr double kStandardGravity_m_per_s2 = model::kStandardGravity_m_per_s2;

// The static tyre load of a quarter car, (m_s + m_u)·g [N]: the tyre carries both masses.
double static_tyre_load_N(const model::QuarterCarParameters<double>& parameters);

// Road holding from a tyre force record.
struct TyreLoadMetrics {
  double static_load_N = 0.0;
  double dynamic_load_rms_N = 0.0;  // RMS of the dynamic load as given (no mean removed)
  // dynamic_load_rms_N / static_load_N: the dimensionless dynamic tyre load (e.g. 0.3 =
  // the wheel load varies by 30 % of the static load, RMS).
  double relative_dynamic_load = 0.0;
  // Share of the samples in [0, 1] in which the total load static + dynamic is ≤ 0: the tyre
  // lifts off. The quarter car's Kelvin-Voigt tyre has no lift-off by default (it pulls the wheel
  // down with negative load), so a share above 0 marks a run outside the model's validity; with
  // the model key tyre_lift_off the force is clipped at −static load and the share counts the
  // samples in flight.
  double lift_off_share = 0.0;
  double min_total_load_N = 0.0;  // smallest static + dynamic load
};

// Metrics of the dynamic tyre load, one sample per time step at a uniform rate.
//
// Sign convention: compression positive, as the quarter car's `tyre_force` channel
// (simulate::QuarterCarResponse::tyre_force_N). The simulator writes the DYNAMIC part only,
// kt·(h − z_u) + ct·(h' − z_u'), measured from static equilibrium; the total wheel load is
// static_load_N + dynamic. A measured total wheel load becomes the dynamic part by
// subtracting its static value first.
//
// Throws InputError for an empty record, a non-finite sample, or a static load that is not
// positive and finite.
TyreLoadMetrics tyre_load_metrics(std::span<const double> dynamic_tyre_force_N,
                                  double static_load_N);

}  // namespace ridefit::comfort
