#pragma once

#include <span>

#include "ridefit/comfort/frequency_weighting.h"

namespace ridefit::comfort {

// Where on a seated person the acceleration is measured.
enum class MeasurementLocation { kSeatSurface, kSeatBack, kFeet };

// Translational axes x (fore-aft), y (lateral), z (vertical); rotations about them
// (roll r_x, pitch r_y, yaw r_z), ISO 2631-1 Figure 1 basicentric axes.
enum class Axis { kX, kY, kZ, kRotationX, kRotationY, kRotationZ };

// The weighting and multiplying factor k for comfort of a seated person, ISO 2631-1:1997
// clause 8.2 (8.2.2 lists the factors, 8.2.3 combines the axes):
//   seat surface  x: Wd, 1.0    y: Wd, 1.0    z: Wk, 1.0
//                 r_x: We, 0.63 (m/s² per rad/s²)   r_y: We, 0.40   r_z: We, 0.20
//   seat back     x: Wc, 0.80   y: Wd, 0.50   z: Wd, 0.40
//   feet          x: Wk, 0.25   y: Wk, 0.25   z: Wk, 0.40
// Rotations are defined only on the seat surface; asking for one elsewhere is an InputError.
struct AxisFactor {
  Weighting weighting;
  double k;
};
AxisFactor comfort_axis_factor(MeasurementLocation location, Axis axis);

// One measured axis: its weighted RMS a_w (m/s², rad/s² for rotations), already weighted with
// comfort_axis_factor(location, axis).weighting.
struct AxisValue {
  MeasurementLocation location;
  Axis axis;
  double weighted_rms;
};

// Vibration total value, ISO 2631-1 eq. (9): a_v = √(Σ k_i²·a_wi²) over the given axes, with
// k_i from comfort_axis_factor. Throws InputError for a negative or non-finite a_w, a rotation
// off the seat surface, or the same (location, axis) given twice (it would count twice).
double total_vibration_value(std::span<const AxisValue> axes);

const char* to_string(MeasurementLocation location);
const char* to_string(Axis axis);

}  // namespace ridefit::comfort
