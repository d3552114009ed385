#pragma once

namespace ridefit::model {

// Kelvin-Voigt element (spring ∥ damper), the tyre: force = k·δ + c·δ'.
template <typename T>
struct KelvinVoigt {
  T stiffness_N_per_m;
  T damping_Ns_per_m;
  T force_N(const T& deflection_m, const T& rate_m_per_s) const {
    return stiffness_N_per_m * deflection_m + damping_Ns_per_m * rate_m_per_s;
  }
};

}  // namespace ridefit::model
