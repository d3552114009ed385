#include "ridefit/comfort/total_vibration_value.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::comfort {

const char* to_string(MeasurementLocation location) {
  switch (location) {
    case MeasurementLocation::kSeatSurface:
      return "seat surface";
    case MeasurementLocation::kSeatBack:
      return "seat back";
    case MeasurementLocation::kFeet:
      return "feet";
  }
  return "?";
}

const char* to_string(Axis axis) {
  switch (axis) {
    case Axis::kX:
      return "x";
    case Axis::kY:
      return "y";
    case Axis::kZ:
      return "z";
    case Axis::kRotationX:
      return "rx";
    case Axis::kRotationY:
      return "ry";
    case Axis::kRotationZ:
      return "rz";
  }
  return "?";
}

AxisFactor comfort_axis_factor(MeasurementLocation location, Axis axis) {
  using enum Axis;
  switch (location) {
    case MeasurementLocation::kSeatSurface:
      switch (axis) {
        case kX:
        case kY:
          return {Weighting::kWd, 1.0};
        case kZ:
          return {Weighting::kWk, 1.0};
        case kRotationX:
          return {Weighting::kWe, 0.63};
        case kRotationY:
          return {Weighting::kWe, 0.40};
        case kRotationZ:
          return {Weighting::kWe, 0.20};
      }
      break;
    case MeasurementLocation::kSeatBack:
      if (axis == kX) return {Weighting::kWc, 0.80};
      if (axis == kY) return {Weighting::kWd, 0.50};
      if (axis == kZ) return {Weighting::kWd, 0.40};
      break;
    case MeasurementLocation::kFeet:
      if (axis == kX || axis == kY) return {Weighting::kWk, 0.25};
      if (axis == kZ) return {Weighting::kWk, 0.40};
      break;
  }
  throw InputError(fmt::format(
      "comfort axis factor: axis {} at the {} has no ISO 2631-1 comfort factor; rotations (rx, "
      "ry, rz) are defined on the seat surface only, the {} takes x, y or z",
      to_string(axis), to_string(location), to_string(location)));
}

double total_vibration_value(std::span<const AxisValue> axes) {
  double sum = 0.0;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const AxisValue& a = axes[i];
    if (!std::isfinite(a.weighted_rms) || a.weighted_rms < 0.0) {
      throw InputError(fmt::format(
          "total vibration value: a_w = {} for {} {} (entry {}) is invalid; it must be a finite "
          "RMS value, at least 0",
          a.weighted_rms, to_string(a.location), to_string(a.axis), i));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (axes[j].location == a.location && axes[j].axis == a.axis) {
        throw InputError(fmt::format(
            "total vibration value: {} {} is given twice (entries {} and {}); give each axis "
            "once",
            to_string(a.location), to_string(a.axis), j, i));
      }
    }
    const double k = comfort_axis_factor(a.location, a.axis).k;
    sum += k * k * a.weighted_rms * a.weighted_rms;
  }
  return std::sqrt(sum);
}

}  // namespace ridefit::comfort
