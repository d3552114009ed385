#pragma once

namespace ridefit::model {

// Unilateral tyre contact: the road can push the wheel but never pull it. The total wheel load,
// static + dynamic, cannot go below zero, so with the dynamic tyre force F_dyn [N] (compression
// positive, from the static equilibrium: the Kelvin-Voigt tyre's kt·(h − zu) + ct·(h' − zu'))
// and the static load F_static [N] = (ms + mu)·g,
//
//   F_tyre = max(F_dyn, −F_static).
//
// While the clip acts the wheel flies: the tyre exerts no force (the total load is 0), and
// gravity alone, through the −F_static the equations measure from, pulls the wheel back. The
// force is continuous in the states (a slope step at lift-off, as at any contact); the branch
// follows the value, so Jets take the slope of the branch they are on (zero while airborne).
template <typename T>
T lifted_off_tyre_force_N(const T& dynamic_force_N, const T& static_load_N) {
  return dynamic_force_N < -static_load_N ? T(-static_load_N) : dynamic_force_N;
}

}  // namespace ridefit::model
