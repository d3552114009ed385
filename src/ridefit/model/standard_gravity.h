#pragma once

namespace ridefit::model {

// Standard gravity (ISO 80000-3) [m/s²]: the static loads of the models (tyre lift-off) and the
// comfort layer's static tyre load use this one value.
inline constexpr double kStandardGravity_m_per_s2 = 9.80665;

}  // namespace ridefit::model
