#include "ridefit/study/half_car_metrics.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/errors.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::study {
namespace {

constexpr double kG = 9.80665;

}  // namespace

std::vector<std::pair<std::string, double>> HalfCarMetrics::named() const {
  return {{"seat_acc_wk_rms_m_per_s2", seat_acc_wk_rms_m_per_s2},
          {"lower_body_acc_wk_rms_m_per_s2", lower_body_acc_wk_rms_m_per_s2},
          {"upper_body_acc_wk_rms_m_per_s2", upper_body_acc_wk_rms_m_per_s2},
          {"pitch_acc_we_rms_rad_per_s2", pitch_acc_we_rms_rad_per_s2},
          {"seat_acc_rms_m_per_s2", seat_acc_rms_m_per_s2},
          {"lower_body_acc_rms_m_per_s2", lower_body_acc_rms_m_per_s2},
          {"upper_body_acc_rms_m_per_s2", upper_body_acc_rms_m_per_s2},
          {"body_acc_rms_m_per_s2", body_acc_rms_m_per_s2},
          {"pitch_acc_rms_rad_per_s2", pitch_acc_rms_rad_per_s2},
          {"front_travel_rms_m", front_travel_rms_m},
          {"rear_travel_rms_m", rear_travel_rms_m},
          {"front_tyre_force_rms_N", front_tyre_force_rms_N},
          {"rear_tyre_force_rms_N", rear_tyre_force_rms_N},
          {"front_dynamic_load_ratio", front_dynamic_load_ratio},
          {"rear_dynamic_load_ratio", rear_dynamic_load_ratio}};
}

std::pair<double, double> static_wheel_loads_N(const model::HalfCarParameters<double>& p) {
  const double length = p.wheelbase_m();
  const double occupant = kG * (p.seat.mass_kg + p.lower_body.mass_kg + p.upper_body.mass_kg);
  const double front = kG * p.body_mass_kg * p.rear_axle_distance_m / length +
                       occupant * (p.rear_axle_distance_m + p.seat_distance_m) / length +
                       kG * p.front.unsprung_mass_kg;
  const double rear = kG * p.body_mass_kg * p.front_axle_distance_m / length +
                      occupant * (p.front_axle_distance_m - p.seat_distance_m) / length +
                      kG * p.rear.unsprung_mass_kg;
  return {front, rear};
}

HalfCarMetrics half_car_metrics(const simulate::HalfCarResponse& response,
                                const model::HalfCarParameters<double>& parameters,
                                double settle_s) {
  if (response.time_s.size() < 2) throw InputError("half-car metrics: a run needs 2 samples");
  const double fs = 1.0 / (response.time_s[1] - response.time_s[0]);
  std::size_t first = 0;
  while (first < response.time_s.size() && response.time_s[first] < settle_s) ++first;
  if (response.time_s.size() - first < 2) {
    throw InputError(fmt::format("half-car metrics: nothing left after the first {} s", settle_s));
  }
  auto channel = [&](double model::HalfCarOutputs::*member) {
    std::vector<double> all = response.channel(member);
    return all;
  };
  auto tail = [&](const std::vector<double>& values) {
    return std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(first), values.end());
  };
  // Weight the whole record (the filter starts from rest with the car), then drop the start.
  auto weighted_rms = [&](comfort::Weighting w, double model::HalfCarOutputs::*member) {
    return signal::rms(tail(comfort::apply_weighting(w, channel(member), fs)));
  };
  auto rms = [&](double model::HalfCarOutputs::*member) {
    return signal::rms(tail(channel(member)));
  };
  using O = model::HalfCarOutputs;
  HalfCarMetrics m;
  m.seat_acc_wk_rms_m_per_s2 = weighted_rms(comfort::Weighting::kWk, &O::seat_acc_m_per_s2);
  m.lower_body_acc_wk_rms_m_per_s2 =
      weighted_rms(comfort::Weighting::kWk, &O::lower_body_acc_m_per_s2);
  m.upper_body_acc_wk_rms_m_per_s2 =
      weighted_rms(comfort::Weighting::kWk, &O::upper_body_acc_m_per_s2);
  m.pitch_acc_we_rms_rad_per_s2 = weighted_rms(comfort::Weighting::kWe, &O::pitch_acc_rad_per_s2);
  m.seat_acc_rms_m_per_s2 = rms(&O::seat_acc_m_per_s2);
  m.lower_body_acc_rms_m_per_s2 = rms(&O::lower_body_acc_m_per_s2);
  m.upper_body_acc_rms_m_per_s2 = rms(&O::upper_body_acc_m_per_s2);
  m.body_acc_rms_m_per_s2 = rms(&O::body_acc_m_per_s2);
  m.pitch_acc_rms_rad_per_s2 = rms(&O::pitch_acc_rad_per_s2);
  m.front_travel_rms_m = rms(&O::front_travel_m);
  m.rear_travel_rms_m = rms(&O::rear_travel_m);
  m.front_tyre_force_rms_N = rms(&O::front_tyre_force_N);
  m.rear_tyre_force_rms_N = rms(&O::rear_tyre_force_N);
  const auto [front_load, rear_load] = static_wheel_loads_N(parameters);
  m.front_dynamic_load_ratio = m.front_tyre_force_rms_N / front_load;
  m.rear_dynamic_load_ratio = m.rear_tyre_force_rms_N / rear_load;
  return m;
}

}  // namespace ridefit::study
