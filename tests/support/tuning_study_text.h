#pragma once

#include <string>

#include "support/passat.h"

namespace ridefit::testing {

// Seed 001's linear half car (frequency domain, ~1 ms an evaluation): front and rear damping
// for the seat's Wk acceleration on two roads, the front dynamic tyre load limited so that the
// limit is active (unconstrained, the gravel case reaches 0.199 at the optimum). `extra` adds
// study keys (optimiser, evaluation, tradeoff).
inline std::string half_car_study(const std::string& extra, double limit = 0.17) {
  return "model: " + dataset("vehicles/ajayi_half_car.yaml") +
         "\ndesign:\n"
         "  - {parameter: front.damping_Ns_per_m, lower: 300, upper: 5000, scale: log}\n"
         "  - {parameter: rear.damping_Ns_per_m, lower: 300, upper: 5000, scale: log}\n"
         "load_cases:\n"
         "  - {road: " +
         dataset("excitations/smooth_road_seed001.yaml") +
         ", speed_km_per_h: 40}\n"
         "  - {road: " +
         dataset("excitations/gravel_road_seed001.yaml") +
         ", speed_km_per_h: 20}\n"
         "objective: {metric: seat_acc_wk_rms_m_per_s2}\n"
         "constraints:\n"
         "  - {metric: front_dynamic_load_ratio, max: " +
         std::to_string(limit) + "}\n" + extra;
}

}  // namespace ridefit::testing
