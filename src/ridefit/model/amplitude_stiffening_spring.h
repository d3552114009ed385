#pragma once

#include <cmath>

namespace ridefit::model {

// A spring that is stiffer at small deflection than at large: the damper-path top mount of a
// strut (seed 000, Section 4.2.2: 707 N/mm identified at small amplitude against 488 N/mm at
// large). With deflection δ [m] (extension positive) and force positive in tension [N],
//
//   F(δ) = k_l·δ + (k_s − k_l)·δ0·tanh(δ/δ0)
//
// k_l = large-amplitude stiffness [N/m] (the key top_mount_stiffness_N_per_m), k_s =
// small-amplitude stiffness [N/m] (top_mount_small_amplitude_stiffness_N_per_m, k_s ≥ k_l), δ0 =
// transition deflection [m] (top_mount_transition_deflection_m, > 0). The slope is
// dF/dδ = k_l + (k_s − k_l)/cosh²(δ/δ0): k_s at δ = 0, falling smoothly (C∞) to k_l for
// |δ| ≫ δ0 and never below it, so F is odd, smooth and strictly monotone (the strut's damper
// rate stays explicit and well posed). The extra force saturates at ±(k_s − k_l)·δ0.
//
// δ0 = 0 means no stiffening (the key is absent): F = k_l·δ, bit for bit the linear spring.
template <typename T>
struct AmplitudeStiffeningSpring {
  T stiffness_N_per_m;                       // k_l, large amplitude
  T small_amplitude_stiffness_N_per_m{0.0};  // k_s (only read when δ0 > 0)
  T transition_deflection_m{0.0};            // δ0; 0 = linear

  bool stiffening() const { return transition_deflection_m > 0.0; }

  T force_N(const T& deflection_m) const {
    if (!stiffening()) return stiffness_N_per_m * deflection_m;
    using std::tanh;
    return stiffness_N_per_m * deflection_m +
           (small_amplitude_stiffness_N_per_m - stiffness_N_per_m) * transition_deflection_m *
               tanh(deflection_m / transition_deflection_m);
  }
  // dF/dδ: k_s at δ = 0, towards k_l at large |δ|.
  T stiffness_at_N_per_m(const T& deflection_m) const {
    if (!stiffening()) return stiffness_N_per_m;
    using std::cosh;
    const T c = cosh(deflection_m / transition_deflection_m);
    return stiffness_N_per_m + (small_amplitude_stiffness_N_per_m - stiffness_N_per_m) / (c * c);
  }
  // Linear unless the stiffening is on with k_s ≠ k_l.
  bool linear() const {
    return !stiffening() || small_amplitude_stiffness_N_per_m == stiffness_N_per_m;
  }
};

}  // namespace ridefit::model
