#pragma once

namespace ridefit::model {

// A linear viscous damper: force = c · deflection rate (positive in extension).
template <typename T>
struct LinearDamper {
  T damping_Ns_per_m;
  T force_N(const T& rate_m_per_s) const { return damping_Ns_per_m * rate_m_per_s; }
};

}  // namespace ridefit::model
