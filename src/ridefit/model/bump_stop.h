#pragma once

#include "ridefit/model/scalar_math.h"

namespace ridefit::model {

// A progressive bump stop between body and wheel, in parallel with the coil spring. It acts
// beyond a compression clearance c0 [m] measured from static equilibrium: with the compression
// c = −(zs − zu) [m] (the negative travel) and the force F_bs [N] pushing body and wheel apart,
//
//   F_bs = k_bs · c0 · ((c − c0)/c0)^n   for c > c0,     0 otherwise,
//
// k_bs = bump_stop_stiffness_N_per_m [N/m], c0 = bump_stop_clearance_m (> 0), n =
// bump_stop_exponent (≥ 1, dimensionless, default 2). Written with (c − c0)/c0 dimensionless,
// k_bs keeps the unit N/m for every n: it is the secant stiffness once the stop is compressed
// by c0 beyond first contact (F_bs = k_bs·c0 at c = 2·c0), and n = 1 is a linear stop of rate
// k_bs. F_bs is continuous and monotone in c; for n > 1 also its slope
// n·k_bs·((c − c0)/c0)^(n−1) starts from 0 (C1), so the contact begins softly; n = 1 has a
// slope step at contact (C0).
//
// k_bs = 0 means no bump stop (the keys are absent).
template <typename T>
struct BumpStop {
  T stiffness_N_per_m{0.0};  // k_bs; 0 = no bump stop
  T clearance_m{0.0};        // c0
  T exponent{2.0};           // n

  bool active() const { return stiffness_N_per_m > 0.0; }

  // Compression-positive force [N] at compression c [m] (c = −travel).
  T force_N(const T& compression_m) const {
    if (!active() || !(compression_m > clearance_m)) return T(0.0);
    const T penetration = (compression_m - clearance_m) / clearance_m;  // > 0 here
    return stiffness_N_per_m * clearance_m * signed_power(penetration, exponent);
  }
};

}  // namespace ridefit::model
