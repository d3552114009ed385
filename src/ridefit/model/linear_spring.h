#pragma once

namespace ridefit::model {

// A linear spring: force = k · deflection (positive in extension).
template <typename T>
struct LinearSpring {
  T stiffness_N_per_m;
  T force_N(const T& deflection_m) const { return stiffness_N_per_m * deflection_m; }
};

// Springs in series share one force; their compliances add.
template <typename T>
T series_stiffness(const T& k1, const T& k2) {
  return k1 * k2 / (k1 + k2);
}

// Springs in parallel share one deflection; their stiffnesses add.
template <typename T>
T parallel_stiffness(const T& k1, const T& k2) {
  return k1 + k2;
}

}  // namespace ridefit::model
